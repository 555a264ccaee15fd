// Cycle-budget bench image (QEMU mps2-an386): calls the hot paths with adversarial inputs while
// QEMU records the executed instructions of the hot range; toolchain/cyclemodel/cm4cost.py prices
// them. Protocol: before each scenario the image prints
//   SCENARIO <name> <function symbol prefix>
// and calls volcomp_bench_mark(); the model attributes every top-level call of <function symbol>
// after that mark to the scenario. Results are also checked for sanity (exit code != 0 on error).
#include <cstdint>

#include "cases.hpp"
#include "hand_lookup.hpp"
#include "semihost.hpp"
#include "volcomp/control_tick.hpp"
#include "volcomp/grid_lookup.hpp"
#include "volcomp/step_output.hpp"
#include "volcomp/table_image.hpp"

extern "C" __attribute__((noinline, section(".text.volcomp_bench_mark"))) void
volcomp_bench_mark() {
  __asm volatile("" ::: "memory");
}

// The tick's data path of a step/dir board as BoardApp::Tick() runs it between reading the
// counters and StepIo::Apply(): ControlTick::Run() (counters to targets), then the step output
// stage's planning (targets to pulse plans). One call per tick: the control_tick_3axes row.
// (No sibling call: the cycle model prices the two calls as calls.)
extern "C" __attribute__((noinline,
                          optimize("no-optimize-sibling-calls"),
                          section(".text.volcomp_bench_tick"))) void
volcomp_bench_tick(volcomp::ControlTick* engine,
                   volcomp::StepOutput* output,
                   const uint32_t* counters,
                   volcomp::PulsePlan* plans) {
  engine->Run(counters);
  output->Plan(engine->targets(), plans);
}

namespace volcomp::target {
namespace {

alignas(8) uint8_t g_image[kMaxCaseImage];
volatile int32_t g_sink;

void Scenario(const char* name, const char* symbol) {
  semihost::Write("SCENARIO ");
  semihost::Write(name);
  semihost::Write(" ");
  semihost::Write(symbol);
  semihost::Write("\n");
  volcomp_bench_mark();
}

// The whole lookup of each element type (GridLookup::Lookup dispatches to these: the three parts
// the tick spreads over ticks, run back to back).
template <class Loader>
const char* KernelSymbol();
template <>
const char* KernelSymbol<LoadInt16>() {
  return "_ZNK7volcomp10GridLookup8LookupAsINS_11grid_kernel5Int16E";
}
template <>
const char* KernelSymbol<LoadInt32>() {
  return "_ZNK7volcomp10GridLookup8LookupAsINS_11grid_kernel5Int32E";
}
template <>
const char* KernelSymbol<LoadFloat32>() {
  return "_ZNK7volcomp10GridLookup8LookupAsINS_11grid_kernel7Float32E";
}

template <class Loader>
__attribute__((noinline)) void RunLookup(const GridLookup& lookup,
                                         const int32_t* pos,
                                         int32_t* out) {
  lookup.Lookup(pos, out);
  int32_t ref[3];
  lookup.Interpolate<Loader>(pos, ref);
  if (ref[0] != out[0] || ref[1] != out[1] || ref[2] != out[2]) {
    semihost::Write("bench: hot path differs from the reference\n");
    semihost::Exit(3);
  }
}

// The three parts of the lookup the control tick spreads over ticks (GridLookup::Begin,
// AccumulateZ0, FinishZ1), on every grid case: one scenario per part.
__attribute__((noinline)) void RunParts(const GridLookup& lookup, const int32_t* pos, int part) {
  static GridLookup::Partial s;
  int32_t out[3];
  if (part == 0) lookup.Begin(pos, &s);
  if (part == 1) lookup.AccumulateZ0(&s);
  if (part == 2) {
    lookup.FinishZ1(s, out);
    g_sink = out[0] + out[1] + out[2];
  }
}

int BenchParts(int part, const char* name, const char* symbol) {
  Scenario(name, symbol);
  for (const GridCaseSpec& c : kGridCases) {
    const uint32_t size = BuildGridImage(c, g_image, sizeof g_image);
    const Result<table::TableView> view = table::ParseImage(g_image, size);
    GridLookup lookup;
    if (size == 0 || !view.ok() || !lookup.Init(view->grid).ok()) return 1;
    Rng rng(c.seed);
    uint32_t n[3];
    for (int d = 0; d < 3; ++d) n[d] = CoordinateCount(c.dim[d]);
    for (uint32_t i = 0; i < n[0] + n[1] + n[2]; ++i) {
      int32_t pos[3];
      for (int d = 0; d < 3; ++d) pos[d] = Coordinate(c.dim[d], (i * (d + 1) + d) % n[d], rng);
      for (int p = 0; p <= part; ++p) RunParts(lookup, pos, p);
    }
  }
  return 0;
}

// The timed positions of a grid case: each dimension walks its adversarial coordinates; the others
// cycle through theirs offset, so every coordinate of every dimension appears with varied
// partners. `visit(pos)` returns false to stop (a failed check).
template <class Visit>
bool ForEachTimedPosition(const GridCaseSpec& c, Visit&& visit) {
  Rng rng(c.seed);
  uint32_t n[3];
  for (int d = 0; d < 3; ++d) n[d] = CoordinateCount(c.dim[d]);
  const uint32_t total = n[0] > n[1] ? (n[0] > n[2] ? n[0] : n[2]) : (n[1] > n[2] ? n[1] : n[2]);
  for (uint32_t i = 0; i < 2 * total; ++i) {
    int32_t pos[3];
    for (int d = 0; d < 3; ++d) pos[d] = Coordinate(c.dim[d], (i * (d + 1) + d) % n[d], rng);
    if (!visit(pos)) return false;
  }
  return true;
}

template <class Loader>
int BenchGrid(const GridCaseSpec& c, const char* name) {
  const uint32_t size = BuildGridImage(c, g_image, sizeof g_image);
  const Result<table::TableView> view = table::ParseImage(g_image, size);
  if (size == 0 || !view.ok()) {
    semihost::Write("bench: grid case image invalid\n");
    return 1;
  }
  GridLookup lookup;
  if (!lookup.Init(view->grid).ok()) return 1;
  Scenario(name, KernelSymbol<Loader>());
  ForEachTimedPosition(c, [&](const int32_t* pos) {
    int32_t out[3];
    RunLookup<Loader>(lookup, pos, out);
    g_sink = out[0] + out[1] + out[2];
    return true;
  });
  return 0;
}

// A hand-scheduled kernel (hand_lookup.hpp) on the positions BenchGrid times, each result checked
// against the GridLookup kernel of the same element type.
using HandKernel = void (*)(const HandLookupConstants*, const int32_t*, int32_t*);
int BenchHandLookup(const GridCaseSpec& c, const char* name, const char* symbol, HandKernel hand) {
  const uint32_t size = BuildGridImage(c, g_image, sizeof g_image);
  const Result<table::TableView> view = table::ParseImage(g_image, size);
  GridLookup lookup;
  HandLookupConstants k;
  if (size == 0 || !view.ok() || !lookup.Init(view->grid).ok() ||
      !PrepareHandLookup(view->grid, &k)) {
    semihost::Write("bench: hand lookup case invalid\n");
    return 1;
  }
  Scenario(name, symbol);
  const bool same = ForEachTimedPosition(c, [&](const int32_t* pos) {
    int32_t out[3], ref[3];
    hand(&k, pos, out);
    lookup.Lookup(pos, ref);
    return ref[0] == out[0] && ref[1] == out[1] && ref[2] == out[2];
  });
  if (!same) {
    semihost::Write("bench: hand-scheduled lookup differs from GridLookup::Lookup\n");
    return 1;
  }
  return 0;
}

int BenchTick() {
  static ControlTick engine;
  static StepOutput output;
  static PreparedTable table;
  if (!StartTickEngine(g_image, sizeof g_image, engine, output, table)) {
    semihost::Write("bench: tick image or engine setup invalid\n");
    return 1;
  }
  uint32_t counters[3] = {0, 0, 0};
  PulsePlan plans[3];
  // The tick's data path (ControlTick::Run and the step output stage), then the same pattern
  // again with its parts as their own rows (each call of the part inside the tick is one sample).
  const char* const kRuns[][2] = {
      {"control_tick_3axes", "volcomp_bench_tick"},
      {"tick_part_refresh", "_ZN7volcomp11Compensator14RefreshTargets"},
      {"tick_part_limiter", "_ZN7volcomp17CorrectionLimiter4Step"},
      {"tick_part_step_generator", "_ZN7volcomp13StepGenerator8PlanTick"},
  };
  for (const auto& run : kRuns) {
    Scenario(run[0], run[1]);
    for (uint32_t i = 0; i < kTickPatternLength; ++i) {
      for (uint32_t a = 0; a < 3; ++a) counters[a] += TickCounterDelta(i, a);
      volcomp_bench_tick(&engine, &output, counters, plans);
    }
  }
  if (!engine.compensator().engaged()) {
    semihost::Write("bench: compensation not engaged\n");
    return 1;
  }
  g_sink = static_cast<int32_t>(plans[0].count + plans[1].count + plans[2].count);
  return 0;
}

}  // namespace
}  // namespace volcomp::target

int main() {
  using namespace volcomp::target;
  using namespace volcomp;
  int rc = 0;
  rc |= BenchGrid<LoadInt16>(kGridCases[0], "lookup_int16_a");
  rc |= BenchGrid<LoadInt16>(kGridCases[1], "lookup_int16_b");
  rc |= BenchHandLookup(kGridCases[0], "hand_lookup_int16_a", "volcomp_hand_lookup_int16",
                        volcomp_hand_lookup_int16);
  rc |= BenchHandLookup(kGridCases[1], "hand_lookup_int16_b", "volcomp_hand_lookup_int16",
                        volcomp_hand_lookup_int16);
  rc |= BenchGrid<LoadInt32>(kGridCases[2], "lookup_int32_a");
  rc |= BenchGrid<LoadInt32>(kGridCases[3], "lookup_int32_b");
  rc |= BenchGrid<LoadFloat32>(kGridCases[4], "lookup_float32_a");
  rc |= BenchGrid<LoadFloat32>(kGridCases[5], "lookup_float32_b");
  rc |= BenchHandLookup(kGridCases[4], "hand_lookup_float32_a", "volcomp_hand_lookup_float32",
                        volcomp_hand_lookup_float32);
  rc |= BenchHandLookup(kGridCases[5], "hand_lookup_float32_b", "volcomp_hand_lookup_float32",
                        volcomp_hand_lookup_float32);
  rc |= BenchParts(0, "lookup_part_begin", "_ZNK7volcomp10GridLookup5Begin");
  rc |= BenchParts(1, "lookup_part_z0", "_ZNK7volcomp10GridLookup12AccumulateZ0");
  rc |= BenchParts(2, "lookup_part_z1", "_ZNK7volcomp10GridLookup8FinishZ1");
  rc |= BenchTick();
  volcomp::semihost::Write(rc == 0 ? "bench: done\n" : "bench: FAILED\n");
  return rc;
}
