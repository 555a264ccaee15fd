// The lib/ tests on the Cortex-M4F (QEMU mps2-an386): a small freestanding runner. Each test
// prints [ RUN ] / [ OK ] / [ FAILED ] over semihosting; the exit code is the number of failures.
// The command line (QEMU -append, set by ctest) selects one test by name; empty runs all.
//   golden_<section>   the Cortex-M4F results equal the host's checked-in golden vectors
//                      (interpolation, AXIS1D, CRC-32, image validation, limiter, step generator,
//                      control tick): bit-identical fixed point (and float32) on host and target
//   hot_path_reference GridLookup::Lookup() equals the reference template on the target
//   crc32_check_value  "123456789" -> 0xCBF43926
//   limiter_limits     the correction limiter never exceeds its velocity/acceleration limits
//   step_timing        pulse plans respect the minimum period and fit the tick
#include <cstdint>

#include "cases.hpp"
#include "golden_stream.hpp"
#include "semihost.hpp"
#include "volcomp/base/crc32.hpp"
#include "volcomp/limiter/correction_limiter.hpp"
#include "volcomp/output/step_generator.hpp"

namespace volcomp::target {
namespace {

using semihost::Write;

int g_failures_in_test = 0;

void Fail(const char* what, int64_t got, int64_t want) {
  ++g_failures_in_test;
  Write("    FAIL: ");
  Write(what);
  Write(" got ");
  semihost::WriteInt(got);
  Write(" want ");
  semihost::WriteInt(want);
  Write("\n");
}

#define CHECK_EQ(got, want)                                                        \
  do {                                                                             \
    const int64_t g_ = static_cast<int64_t>(got), w_ = static_cast<int64_t>(want); \
    if (g_ != w_) Fail(#got " == " #want, g_, w_);                                 \
  } while (0)
#define CHECK(cond)                 \
  do {                              \
    if (!(cond)) Fail(#cond, 0, 1); \
  } while (0)

void GoldenSectionTest(GoldenSection s) {
  CompareSink sink;
  uint32_t mismatches = 0;
  ComputeGolden(s, sink, &mismatches);
  CHECK_EQ(mismatches, 0);
  CHECK_EQ(sink.computed(), sink.expected());
  if (sink.first_diff() != ~0u) {
    Write("    first difference at word ");
    semihost::WriteUint(sink.first_diff());
    Write(": target ");
    semihost::WriteHex(sink.got());
    Write(", host ");
    semihost::WriteHex(sink.want());
    Write("\n");
    ++g_failures_in_test;
  }
}

void Crc32CheckValue() {
  const char s[] = "123456789";
  CHECK_EQ(ComputeCrc32(reinterpret_cast<const uint8_t*>(s), 9), 0xCBF43926u);
  Crc32 inc;
  inc.Update(reinterpret_cast<const uint8_t*>(s), 4);
  inc.Update(reinterpret_cast<const uint8_t*>(s) + 4, 5);
  CHECK_EQ(inc.value(), 0xCBF43926u);
}

void LimiterLimits() {
  const Result<LimiterParams> p = CorrectionLimiter::MakeParams(50000, 20000, 2000000);
  CHECK(p.ok());
  if (!p.ok()) return;
  CorrectionLimiter lim(*p);
  const int64_t a = p->accel_q32, vmax = int64_t{p->max_k} * p->accel_q32;
  int64_t prev = 0, prev_v = 0;
  const int64_t targets[] = {int64_t{500} << 32, -(int64_t{321} << 32), 0};
  for (int64_t t : targets) {
    for (int i = 0; i < 6000; ++i) {  // 821 steps at 0.4 steps/tick need about 2100 ticks
      const int64_t pos = lim.Step(t);
      const int64_t v = pos - prev;
      if (v > vmax || v < -vmax) Fail("|velocity| <= limit", v, vmax);
      if (pos != t && (v - prev_v > a || prev_v - v > a)) Fail("|accel| <= limit", v - prev_v, a);
      prev = pos;
      prev_v = v;
    }
    CHECK_EQ(prev, t);  // reached, no overshoot left
  }
}

void StepTiming() {
  const BoardConfig cfg = TickBoardConfig();
  StepGenerator gen;
  CHECK(gen.Configure(cfg.axis[0], cfg.tick_hz, cfg.pulse_clock_hz).ok());
  int32_t target = 0;
  for (uint32_t i = 0; i < kTickPatternLength; ++i) {
    target = static_cast<int32_t>(static_cast<uint32_t>(target) + TickCounterDelta(i, 0));
    const PulsePlan p = gen.Plan(target);
    if (p.count > 0) {
      CHECK(p.period >= gen.min_period());
      CHECK(p.first_rise + (p.count - 1) * p.period < gen.tick_length());
    }
  }
}

void HotPathReference() {
  CompareSink sink;
  uint32_t mismatches = 0;
  ComputeGolden(GoldenSection::kGridLookup, sink, &mismatches);
  CHECK_EQ(mismatches, 0);
}

struct Test {
  const char* name;
  void (*run)();
};

template <GoldenSection S>
void Golden() {
  GoldenSectionTest(S);
}

constexpr Test kTests[] = {
    {"golden_grid_lookup", Golden<GoldenSection::kGridLookup>},
    {"golden_axis_lookup", Golden<GoldenSection::kAxisLookup>},
    {"golden_crc32", Golden<GoldenSection::kCrc>},
    {"golden_image_validation", Golden<GoldenSection::kImageErrors>},
    {"golden_limiter", Golden<GoldenSection::kLimiter>},
    {"golden_step_generator", Golden<GoldenSection::kStepGenerator>},
    {"golden_control_tick", Golden<GoldenSection::kControlTick>},
    {"hot_path_reference", HotPathReference},
    {"crc32_check_value", Crc32CheckValue},
    {"limiter_limits", LimiterLimits},
    {"step_timing", StepTiming},
};

bool Equal(const char* a, const char* b) {
  while (*a != '\0' && *a == *b) ++a, ++b;
  return *a == *b;
}

}  // namespace
}  // namespace volcomp::target

int main() {
  using namespace volcomp::target;
  const char* filter = volcomp::semihost::CommandLine();
  int passed = 0, failed = 0;
  for (const Test& t : kTests) {
    if (filter[0] != '\0' && !Equal(filter, t.name)) continue;
    Write("[ RUN      ] ");
    Write(t.name);
    Write("\n");
    g_failures_in_test = 0;
    t.run();
    Write(g_failures_in_test == 0 ? "[       OK ] " : "[  FAILED  ] ");
    Write(t.name);
    Write("\n");
    (g_failures_in_test == 0 ? passed : failed) += 1;
  }
  if (passed + failed == 0) {
    Write("no test named '");
    Write(filter);
    Write("'\n");
    return 2;
  }
  volcomp::semihost::WriteInt(passed);
  Write(" passed, ");
  volcomp::semihost::WriteInt(failed);
  Write(" failed\n");
  return failed;
}
