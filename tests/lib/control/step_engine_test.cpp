// The whole per-tick data path on random input step streams with compensation active:
// output = input + correction exactly, no step lost or invented, no drive timing violated,
// output within two ticks of the input.
//
// The path is ControlTick (input counters to targets) and the step/dir output stage StepOutput
// (targets to pulse plans). Input lines are simulated edge by edge through StepDecoder (the
// hardware counter model, tests/reference); outputs go through MockStepIo into DriveModel
// checkers. VOLCOMP_LONG_TESTS (cmake option) or
// the environment variable VOLCOMP_ENGINE_STEPS raises the step count (10^8 for the long run).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "test_tables.hpp"
#include "volcomp/control/control_tick.hpp"
#include "volcomp/hal/mock/mock_step_io.hpp"
#include "volcomp/output/step_output.hpp"
#include "volcomp/reference/step_decoder.hpp"

namespace volcomp {
namespace {

uint64_t StepsPerFormat() {
  if (const char* env = std::getenv("VOLCOMP_ENGINE_STEPS")) return std::strtoull(env, nullptr, 10);
#ifdef VOLCOMP_LONG_TESTS
  return 100000000;
#else
  return 1000000;
#endif
}

// A grid with strong gradients so corrections keep changing as the axes move: up to +-40 steps
// over a 4x4x4 lattice spanning +-50000 steps.
testing::GridCase SteepGrid(std::mt19937_64& rng) {
  testing::GridCase g;
  g.type = table::ElementType::kInt16;
  g.frac_bits = 8;
  for (auto& d : g.dim) d = {4, -50000, 33334};
  std::uniform_int_distribution<int> v(-40 * 256, 40 * 256);
  for (size_t i = 0; i < g.count(); ++i) {
    g.i16.push_back(static_cast<int16_t>(v(rng)));
    g.steps.push_back(g.i16.back() / 256.0);
  }
  return g;
}

// `c` compensates with `table` from now on, the machine at position 0 on every axis.
void CompensateFromZero(Compensator& c, const PreparedTable& table) {
  const int32_t at_zero[3] = {0, 0, 0};
  c.SetTable(table, at_zero);
  c.SetEnabled(true);
}

struct EngineRun {
  uint64_t input_steps = 0;
  uint64_t output_steps = 0;
  uint64_t violations = 0;
  uint32_t max_backlog = 0;
  int64_t max_abs_correction = 0;
  uint64_t ticks = 0;
};

EngineRun RunEngine(PulseFormat in_format,
                    PulseFormat out_format,
                    uint8_t counter_bits,
                    uint64_t steps_wanted,
                    uint64_t seed) {
  std::mt19937_64 rng(seed);
  BoardConfig cfg = DefaultBoardConfig();
  for (int a = 0; a < 3; ++a) {
    AxisConfig& ax = cfg.axis[a];
    ax.input_format = in_format;
    ax.output_format = out_format;
    ax.input_counter_bits = counter_bits;
    ax.max_input_rate_hz = 1000000;
    ax.max_correction_steps = 1000;
    ax.max_correction_rate_steps_s = 20000;
    ax.max_correction_accel_steps_s2 = 4000000;
    ax.drive = {200, 200, 300, 300, 2000000};  // width, space, setup, hold (ns), max rate
  }
  ControlTick engine;
  EXPECT_TRUE(engine.Configure(cfg).ok());
  StepOutput output;
  EXPECT_TRUE(output.Configure(cfg).ok());
  const uint32_t zero_counters[3] = {0, 0, 0};
  engine.LatchCounters(zero_counters);
  const testing::GridCase grid = SteepGrid(rng);
  const testing::AlignedBytes img = testing::WriteGridImage(grid);
  const auto view = table::ParseImage(img.data(), img.size());
  PreparedTable table;
  EXPECT_TRUE(table.Prepare(*view, cfg).ok());
  CompensateFromZero(engine.compensator(), table);
  for (uint8_t a = 0; a < 3; ++a) engine.Reference(a);

  hal::mock::MockStepIo io(cfg, nullptr);
  StepDecoder dec[3] = {StepDecoder(in_format), StepDecoder(in_format), StepDecoder(in_format)};
  bool line_a[3] = {}, line_b[3] = {};
  int8_t quad_phase[3] = {};
  for (int a = 0; a < 3; ++a) {
    line_b[a] = in_format == PulseFormat::kStepDir;
    dec[a].Reset(line_a[a], line_b[a]);
  }
  const uint64_t tick_ns = 1000000000ull / cfg.tick_hz;
  EngineRun run;
  int64_t input_pos[3] = {};
  int dir[3] = {1, 1, 1};
  uint32_t rate[3] = {};
  // Emits one input step on axis a through its line levels.
  auto step = [&](int a, int d) {
    switch (in_format) {
      case PulseFormat::kStepDir:
        if (line_b[a] != (d > 0)) {
          line_b[a] = d > 0;
          dec[a].Sample(line_a[a], line_b[a]);
        }
        dec[a].Sample(true, line_b[a]);
        dec[a].Sample(false, line_b[a]);
        break;
      case PulseFormat::kCwCcw:
        dec[a].Sample(d > 0, d < 0);
        dec[a].Sample(false, false);
        break;
      case PulseFormat::kQuadrature: {
        static const bool kA[4] = {false, true, true, false}, kB[4] = {false, false, true, true};
        quad_phase[a] = static_cast<int8_t>((quad_phase[a] + (d > 0 ? 1 : 3)) & 3);
        dec[a].Sample(kA[quad_phase[a]], kB[quad_phase[a]]);
        break;
      }
    }
    input_pos[a] += d;
    ++run.input_steps;
  };

  uint64_t t = 0;
  // One tick of the data path at time t: counters in, pulses planned and applied.
  const auto tick = [&] {
    io.set_tick_start_ns(t);
    uint32_t counters[3];
    io.ReadCounters(counters);
    PulsePlan plans[3];
    engine.Run(counters);
    output.Plan(engine.targets(), plans);
    io.Apply(plans);
  };
  while (run.input_steps < steps_wanted) {
    for (int a = 0; a < 3; ++a) {
      // Random walk of the step rate: 0..20 steps per 20 us tick (up to 1 MHz), with reversals,
      // kept inside the grid +-60000 (partly outside it, where the boundary values hold).
      if (rng() % 64 == 0) rate[a] = static_cast<uint32_t>(rng() % 21);
      if (rng() % 256 == 0 || (input_pos[a] > 60000 && dir[a] > 0) ||
          (input_pos[a] < -60000 && dir[a] < 0)) {
        dir[a] = -dir[a];
      }
      for (uint32_t s = 0; s < rate[a]; ++s) step(a, dir[a]);
      io.set_counter(static_cast<uint8_t>(a), static_cast<uint32_t>(dec[a].count()));
    }
    tick();
    for (uint8_t a = 0; a < 3; ++a) {
      // Exactness every tick: planned output = input + correction - backlog.
      EXPECT_EQ(output.position(a) + output.backlog(a, engine.target(a)),
                static_cast<int32_t>(input_pos[a]) + engine.correction_steps(a));
      run.max_abs_correction =
          std::max<int64_t>(run.max_abs_correction, std::abs(engine.correction_steps(a)));
    }
    t += tick_ns;
  }
  // Let the correction settle with the inputs standing still, then compare.
  for (int i = 0; i < 20000; ++i) {
    tick();
    t += tick_ns;
  }
  for (uint8_t a = 0; a < 3; ++a) {
    const auto& drive = io.drive(a);
    EXPECT_EQ(drive.position(), input_pos[a] + engine.correction_steps(a)) << "axis " << int(a);
    EXPECT_EQ(output.backlog(a, engine.target(a)), 0);
    EXPECT_EQ(dec[a].errors(), 0u);
    for (const auto& v : drive.violation_log()) ADD_FAILURE() << "axis " << int(a) << ": " << v;
    run.violations += drive.violations();
    run.output_steps += drive.steps();
    run.max_backlog = std::max(run.max_backlog, output.max_backlog(a));
  }
  run.ticks = engine.ticks();
  // Latency: a step read at a tick start is emitted within that tick unless the backlog exceeds
  // one tick's capacity, so the backlog never reaching it means <= 2 ticks edge to output.
  EXPECT_LT(run.max_backlog, output.generator(0).max_pulses_per_tick());
  return run;
}

const char* Name(PulseFormat f) {
  return f == PulseFormat::kStepDir ? "step/dir"
                                    : (f == PulseFormat::kCwCcw ? "cw/ccw" : "quadrature");
}

class StepEngine : public ::testing::TestWithParam<PulseFormat> {};

TEST_P(StepEngine, OutputEqualsInputPlusCorrectionWithoutTimingViolations) {
  const PulseFormat f = GetParam();
  const EngineRun r = RunEngine(f, f, 32, StepsPerFormat(), 100 + static_cast<int>(f));
  EXPECT_GE(r.input_steps, StepsPerFormat());
  EXPECT_EQ(r.violations, 0u);
  EXPECT_GT(r.max_abs_correction, 5);  // the compensation really was active
  std::printf(
      "[ metric ] %s: %llu input steps, %llu output steps, %llu ticks, max backlog %u, "
      "max |correction| %lld steps, %llu violations\n",
      Name(f), static_cast<unsigned long long>(r.input_steps),
      static_cast<unsigned long long>(r.output_steps), static_cast<unsigned long long>(r.ticks),
      r.max_backlog, static_cast<long long>(r.max_abs_correction),
      static_cast<unsigned long long>(r.violations));
}

INSTANTIATE_TEST_SUITE_P(Formats,
                         StepEngine,
                         ::testing::Values(PulseFormat::kStepDir,
                                           PulseFormat::kCwCcw,
                                           PulseFormat::kQuadrature));

TEST(StepEngineReference, SeveralAxesAtOnceEqualOneAxisAtATime) {
  std::mt19937_64 rng(11);
  BoardConfig cfg = DefaultBoardConfig();
  for (int a = 0; a < 3; ++a) cfg.axis[a].home_position_steps = 1000 * (a + 1);
  const testing::GridCase grid = SteepGrid(rng);
  const testing::AlignedBytes img = testing::WriteGridImage(grid);
  const auto view = table::ParseImage(img.data(), img.size());
  ControlTick one, all;
  PreparedTable table;
  ASSERT_TRUE(table.Prepare(*view, cfg).ok());
  for (ControlTick* e : {&one, &all}) {
    ASSERT_TRUE(e->Configure(cfg).ok());
    CompensateFromZero(e->compensator(), table);
  }
  uint32_t counters[3] = {0, 0, 0};
  for (int t = 0; t < 300; ++t) {
    for (int a = 0; a < 3; ++a) counters[a] += static_cast<uint32_t>(a + 1) * 7u;
    if (t == 20) {  // axes 0 and 2 (and a bit of an axis the board does not have)
      one.Reference(0);
      one.Reference(2);
      all.ReferenceAxes(0x85u);
    }
    if (t == 40) {
      one.Reference(1);
      all.ReferenceAxes(0x2u);
    }
    one.Run(counters);
    all.Run(counters);
    for (uint8_t a = 0; a < 3; ++a) {
      ASSERT_EQ(one.referenced(a), all.referenced(a)) << t;
      ASSERT_EQ(one.machine_position(a), all.machine_position(a)) << t;
      ASSERT_EQ(one.target(a), all.target(a)) << t;
      ASSERT_EQ(one.compensator().target_q8(a), all.compensator().target_q8(a)) << t;
    }
  }
  EXPECT_TRUE(all.compensator().engaged());
}

// The two rates (control_tick.hpp): at 50 kHz the compensator runs every third tick
// (CompensationDivider), and every tick's target is its commanded position plus the correction
// the runs before it published. The oracle is a Compensator of its own stepped on the commanded
// positions at those ticks.
TEST(StepEngineTwoRates, TheCompensatorRunsEveryDividerTicksAndTheStepPathAppliesItsLastOutput) {
  std::mt19937_64 rng(5);
  const BoardConfig cfg = DefaultBoardConfig();
  ASSERT_EQ(cfg.tick_hz, 50000u);
  ASSERT_EQ(CompensationDivider(cfg.tick_hz), 3u);
  for (uint32_t tick_hz = kMinTickHz; tick_hz <= kMaxTickHz; ++tick_hz) {
    const uint32_t d = CompensationDivider(tick_hz);  // the smallest divider to <= 20 kHz
    ASSERT_LE(tick_hz, d * kMaxCompensationHz) << tick_hz;
    ASSERT_TRUE(d == 1 || tick_hz > (d - 1) * kMaxCompensationHz) << tick_hz;
  }
  const testing::GridCase grid = SteepGrid(rng);
  const testing::AlignedBytes img = testing::WriteGridImage(grid);
  const auto view = table::ParseImage(img.data(), img.size());
  PreparedTable table;
  ASSERT_TRUE(table.Prepare(*view, cfg).ok());
  ControlTick engine;
  Compensator oracle;
  ASSERT_TRUE(engine.Configure(cfg).ok());
  ASSERT_TRUE(oracle.Configure(cfg).ok());
  EXPECT_EQ(engine.compensation_divider(), 3u);
  CompensateFromZero(engine.compensator(), table);
  engine.ReferenceAxes(0x7u);  // home 0: machine = commanded
  CompensateFromZero(oracle, table);
  oracle.SetReferenced(true);
  uint32_t counters[3] = {0, 0, 0};
  int32_t published[3] = {0, 0, 0};
  int32_t commanded[3] = {0, 0, 0};
  uint32_t runs = 0;
  std::uniform_int_distribution<int> step(-20, 20);
  for (uint32_t t = 0; t < 30000; ++t) {
    for (int a = 0; a < 3; ++a) {
      const int d = step(rng) + (t / 3000 % 2 == 0 ? 12 : -12);
      counters[a] += static_cast<uint32_t>(d);
      commanded[a] += d;
    }
    const bool due = engine.RunSteps(counters);
    ASSERT_EQ(due, t % 3 == 0) << t;
    for (uint8_t a = 0; a < 3; ++a) {
      ASSERT_EQ(engine.commanded(a), commanded[a]) << t;
      ASSERT_EQ(engine.correction_steps(a), published[a]) << t;
      ASSERT_EQ(engine.target(a), commanded[a] + published[a]) << t;
    }
    if (!due) continue;
    engine.Compensate();
    oracle.Run(commanded, published);
    ++runs;
    for (uint8_t a = 0; a < 3; ++a) {
      ASSERT_EQ(engine.published_correction_steps(a), published[a]) << t;
    }
  }
  EXPECT_EQ(runs, 10000u);
  EXPECT_TRUE(engine.compensator().engaged());
  int32_t largest = 0;
  for (int32_t c : published) largest = std::max(largest, std::abs(c));
  EXPECT_GT(largest, 0);  // the table is in the targets
}

// The board's tick activates a table and references in the same tick with one rebase
// (Compensator::BindTable, ControlTick::MarkReferenced, RebaseCompensator): the same state, tick
// by tick afterwards, as UseTable() and ReferenceAxes() with a rebase each. The new table has a
// wrapping (rotary) AXIS1D table on Z, so the wrap trackers must be set from the referenced
// positions.
TEST(StepEngineReference, TableSwitchAndReferencingShareOneRebase) {
  std::mt19937_64 rng(23);
  BoardConfig cfg = DefaultBoardConfig();
  for (int a = 0; a < 3; ++a) cfg.axis[a].home_position_steps = 123457 * (a + 1);
  const testing::GridCase grid = SteepGrid(rng);
  std::vector<int16_t> wrap_values;
  for (int i = 0; i < 5; ++i) {
    wrap_values.push_back(static_cast<int16_t>(static_cast<int32_t>(rng() % 1601) - 800));
  }
  wrap_values.back() = wrap_values.front();  // continuous across the seam
  table::Axis1dSpec rotary;
  rotary.axis = 2;
  rotary.frac_bits = 4;
  rotary.dim = table::Dimension{5, 100, 1000};
  rotary.period_steps = 4000;
  rotary.forward = {table::ElementType::kInt16, wrap_values.data(), nullptr, nullptr};
  const testing::AlignedBytes first_img = testing::WriteGridImage(grid);
  const testing::AlignedBytes second_img = testing::WriteGridImage(grid, 9, &rotary, 1);
  const auto first_view = table::ParseImage(first_img.data(), first_img.size());
  const auto second_view = table::ParseImage(second_img.data(), second_img.size());
  ASSERT_TRUE(first_view.ok() && second_view.ok());
  PreparedTable first, second;
  ASSERT_TRUE(first.Prepare(*first_view, cfg).ok());
  ASSERT_TRUE(second.Prepare(*second_view, cfg).ok());
  ControlTick two, one;
  for (ControlTick* e : {&two, &one}) {
    ASSERT_TRUE(e->Configure(cfg).ok());
    CompensateFromZero(e->compensator(), first);
  }
  uint32_t counters[3] = {0, 0, 0};
  for (int t = 0; t < 400; ++t) {
    counters[0] += 5u;
    counters[1] -= 3u;
    counters[2] += t < 200 ? 0u - 11u : 13u;  // Z backward across several periods, then forward
    if (t == 30) {
      int32_t machine[3];
      for (uint8_t a = 0; a < 3; ++a) machine[a] = two.machine_position(a);
      two.compensator().UseTable(&second, machine);
      two.ReferenceAxes(0x7u);
      one.compensator().BindTable(&second);
      ASSERT_TRUE(one.MarkReferenced(0x7u));
      one.RebaseCompensator();
    }
    two.Run(counters);
    one.Run(counters);
    for (uint8_t a = 0; a < 3; ++a) {
      ASSERT_EQ(two.machine_position(a), one.machine_position(a)) << t;
      ASSERT_EQ(two.compensator().reverse(a), one.compensator().reverse(a)) << t;
      ASSERT_EQ(two.compensator().target_q8(a), one.compensator().target_q8(a)) << t;
      ASSERT_EQ(two.target(a), one.target(a)) << t;
    }
  }
  EXPECT_TRUE(one.compensator().engaged());
  EXPECT_NE(one.compensator().target_q8(2), 0);
}

TEST(StepEngineMixed, SixteenBitCountersAndFormatConversion) {
  // Quadrature in, step/dir out, 16-bit hardware counters that wrap many times.
  const EngineRun r = RunEngine(PulseFormat::kQuadrature, PulseFormat::kStepDir, 16, 300000, 7);
  EXPECT_EQ(r.violations, 0u);
  EXPECT_GE(r.input_steps, 300000u);
}

}  // namespace
}  // namespace volcomp
