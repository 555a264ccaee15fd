// Cycle-budget bench image (QEMU mps2-an386): calls the hot paths with adversarial inputs while
// QEMU records the executed instructions of the hot range; toolchain/cyclemodel/cm4cost.py prices
// them. Protocol: before each scenario the image prints
//   SCENARIO <name> <function symbol prefix>
// and calls volcomp_bench_mark(); the model attributes every top-level call of <function symbol>
// after that mark to the scenario. Results are also checked for sanity (exit code != 0 on error).
#include <cstdint>

#include "bench_support.hpp"
#include "cases.hpp"
#include "semihost.hpp"
#include "volcomp/control/control_tick.hpp"
#include "volcomp/firmware/board_app.hpp"
#include "volcomp/firmware/step_dir_io.hpp"
#include "volcomp/firmware/stm32g4/tick_isr.hpp"
#include "volcomp/hal/stm32g4/drivers.hpp"
#include "volcomp/hal/stm32g4/registers.hpp"
#include "volcomp/lookup/grid_lookup.hpp"
#include "volcomp/output/step_output.hpp"
#include "volcomp/table/table_image.hpp"

// The tick's step path of a step/dir board as BoardApp::StepTick() runs it between reading the
// counters and StepIo::Apply(): ControlTick::RunSteps() (counters to targets), then the step
// output stage's planning (targets to pulse plans). One call per tick: the control_tick_3axes
// row. Returns true when a compensation run is due. (No sibling call: the cycle model prices the
// two calls as calls.)
extern "C" __attribute__((noinline,
                          optimize("no-optimize-sibling-calls"),
                          section(".text.volcomp_bench_tick"))) bool
volcomp_bench_tick(volcomp::ControlTick* engine,
                   volcomp::StepOutput* output,
                   const uint32_t* counters,
                   volcomp::PulsePlan* plans) {
  const bool due = engine->RunSteps(counters);
  output->Plan(engine->targets(), plans);
  return due;
}

// One compensation run (ControlTick::Compensate(): sensing, the refresh slice, the limiters): the
// compensation_3axes row.
extern "C" __attribute__((noinline, section(".text.volcomp_bench_compensate"))) void
volcomp_bench_compensate(volcomp::ControlTick* engine) {
  engine->Compensate();
}

// ---- The whole tick interrupt of the step/dir STM32G474 image ---------------------------------
// The image's BoardApp<StepDirIo<stm32g4::StepIo>> and ISR body (RunTickIsr: timer acknowledge,
// BoardApp::Tick with the counter read, ControlTick::Run, the step output stage and
// StepIo::Apply), on the same drivers built with their registers in RAM
// (VOLCOMP_STM32G4_REGISTER_WINDOW): the tick_isr_3axes row. The bench moves the input counters
// in the RAM copies of TIM2/TIM5/TIM3 CNT between ticks.
namespace volcomp::target {
namespace {

using IsrIo = BenchIo;
using IsrApp = BenchApp;
stm32g4::StepIo g_isr_step_io;
IsrIo g_isr_io(&g_isr_step_io);
BenchLines g_isr_lines;
BenchFlash g_isr_flash;
IsrApp g_isr_app({&g_isr_io, &g_isr_lines, &g_isr_flash, nullptr, nullptr, nullptr, nullptr});

}  // namespace
}  // namespace volcomp::target

extern "C" __attribute__((noinline, section(".text.volcomp_bench_isr"))) void volcomp_bench_isr() {
  volcomp::firmware::stm32g4::RunTickIsr(volcomp::target::g_isr_app);
}
extern "C" __attribute__((noinline, section(".text.volcomp_bench_compensation_isr"))) void
volcomp_bench_compensation_isr() {
  volcomp::firmware::stm32g4::RunCompensationIsr(volcomp::target::g_isr_app);
}

namespace volcomp::target {
namespace {

alignas(8) uint8_t g_image[kMaxCaseImage];
volatile int32_t g_sink;

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
  // The tick's step path (ControlTick::RunSteps and the step output stage) and the compensation
  // runs when due, the same pattern once per row: the step path, the compensation run, and the
  // compensation's one remaining call, the target refresh (each call one sample; the limiter and
  // the step generator are inlined into the walks over the axes).
  const char* const kRuns[][2] = {
      {"control_tick_3axes", "volcomp_bench_tick"},
      {"compensation_3axes", "volcomp_bench_compensate"},
      {"tick_part_refresh", "_ZN7volcomp11Compensator14RefreshTargets"},
  };
  uint32_t runs = 0;
  for (const auto& run : kRuns) {
    Scenario(run[0], run[1]);
    for (uint32_t i = 0; i < kTickPatternLength; ++i) {
      for (uint32_t a = 0; a < 3; ++a) counters[a] += TickCounterDelta(i, a);
      if (volcomp_bench_tick(&engine, &output, counters, plans)) {
        volcomp_bench_compensate(&engine);
        ++runs;
      }
    }
  }
  if (runs * engine.compensation_divider() != 3 * kTickPatternLength) {
    semihost::Write("bench: compensation runs not every compensation_divider() ticks\n");
    return 1;
  }
  if (!engine.compensator().engaged()) {
    semihost::Write("bench: compensation not engaged\n");
    return 1;
  }
  g_sink = static_cast<int32_t>(plans[0].count + plans[1].count + plans[2].count);
  return 0;
}

// The tick interrupt with the board stepping: every axis at its configured maximum input rate
// (BoardConfig max_input_rate_hz per tick), forward, backward and reversing every tick in turn,
// with a table (grid + AXIS1D, int16) engaged on all three axes.
int BenchTickIsr() {
  alignas(8) static uint8_t image[kMaxCaseImage];
  BoardConfig cfg = TickBoardConfig();
  for (uint8_t a = 0; a < stm32g4::kStepAxes; ++a) {
    cfg.axis[a].input_counter_bits = stm32g4::kInputCounterBits[a];
  }
  firmware::AppOptions options;
  options.use_enable_input = false;
  const uint32_t size = BuildTickImage(image, sizeof image);
  if (!g_isr_app.Start(cfg, options).ok() || !g_isr_app.ActivateImage(image, size).ok()) {
    semihost::Write("bench: tick ISR board setup failed\n");
    return 1;
  }
  g_isr_lines.homed = true;
  g_isr_app.Poll();  // the home edges: referenced at the next tick
  // The board's two interrupts as the NVIC would run them: the tick, then (when it pended it) the
  // compensation run before anything of lower priority. QEMU's mps2-an386 NVIC has no IRQ 55, so
  // the bench follows the tick's own word (StepTick()'s due flag, as RunTickIsr() acts on it).
  const uint32_t divider = g_isr_app.control_tick().compensation_divider();
  const auto tick = [&] {
    volcomp_bench_isr();
    if ((g_isr_app.control_tick().ticks() - 1u) % divider == 0) volcomp_bench_compensation_isr();
  };
  for (int i = 0; i < 24; ++i) tick();
  if (!g_isr_app.control_tick().compensator().engaged()) {
    semihost::Write("bench: tick ISR board not compensating\n");
    return 1;
  }
  constexpr uintptr_t kCounter[3] = {stm32g4::kTim2Base, stm32g4::kTim5Base, stm32g4::kTim3Base};
  const char* const kRuns[][2] = {
      {"tick_isr_3axes", "volcomp_bench_isr"},
      {"compensation_isr_3axes", "volcomp_bench_compensation_isr"},
  };
  for (const auto& run : kRuns) {
    Scenario(run[0], run[1]);
    for (uint32_t i = 0; i < kTickPatternLength; ++i) {
      for (uint32_t a = 0; a < 3; ++a) {
        const uint32_t rate = cfg.axis[a].max_input_rate_hz / cfg.tick_hz;
        const uint32_t phase = (i / 40 + a) % 3;
        const bool back = phase == 1 || (phase == 2 && (i & 1) != 0);
        volatile uint32_t& cnt = stm32g4::Reg(kCounter[a], stm32g4::tim::kCnt);
        const uint32_t mask = cfg.axis[a].input_counter_bits == 32 ? 0xFFFFFFFFu : 0xFFFFu;
        cnt = (cnt + (back ? 0u - rate : rate)) & mask;
      }
      tick();
    }
  }
  const StepOutput& out = g_isr_app.tick_io().output();
  if (out.position(0) == 0 && out.position(1) == 0 && out.position(2) == 0) {
    semihost::Write("bench: tick ISR planned no pulses\n");
    return 1;
  }
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
  rc |= BenchGrid<LoadInt32>(kGridCases[2], "lookup_int32_a");
  rc |= BenchGrid<LoadInt32>(kGridCases[3], "lookup_int32_b");
  rc |= BenchGrid<LoadFloat32>(kGridCases[4], "lookup_float32_a");
  rc |= BenchGrid<LoadFloat32>(kGridCases[5], "lookup_float32_b");
  rc |= BenchParts(0, "lookup_part_begin", "_ZNK7volcomp10GridLookup5Begin");
  rc |= BenchParts(1, "lookup_part_z0", "_ZNK7volcomp10GridLookup12AccumulateZ0");
  rc |= BenchParts(2, "lookup_part_z1", "_ZNK7volcomp10GridLookup8FinishZ1");
  rc |= BenchTick();
  rc |= BenchTickIsr();
  volcomp::semihost::Write(rc == 0 ? "bench: done\n" : "bench: FAILED\n");
  return rc;
}
