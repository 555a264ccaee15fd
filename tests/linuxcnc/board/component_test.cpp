// The LinuxCNC components' logic without LinuxCNC: the board's sampled input counter counts a
// stepgen-like waveform exactly, its output waveform sampled at the base period loses no pulse and
// keeps the drive's direction rules (checked by a drive counter written here), the step I/O and
// the thread's tick timer refuse what the pins and the thread cannot do, the firmware on pins
// passes the input through and then adds the table's correction (checked against the independent
// double trilinear reference) from the position its home edge assigns. (The native component's
// tests are in ../native/.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <vector>

#include "board/board_glue.hpp"
#include "board/hal_step_io.hpp"
#include "board/thread_board_config.hpp"
#include "board/thread_tick_timer.hpp"
#include "test_tables.hpp"
#include "volcomp/firmware/board_app.hpp"
#include "volcomp/firmware/step_dir_io.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"
#include "volcomp/output/step_generator.hpp"

namespace volcomp::linuxcnc {
namespace {

// A step/dir drive sampling its inputs once per base period: counts a rising STEP edge up while
// DIR is low, down while high; flags a DIR change while STEP is high or in the sample of a rise.
struct SampledDrive {
  int64_t count = 0;
  bool step = false, dir = false;
  int violations = 0;
  void Sample(bool s, bool d) {
    if (d != dir && (step || s)) ++violations;
    if (s && !step) count += d ? -1 : 1;
    step = s;
    dir = d;
  }
};

// A stepgen (step_type 0) with every time one base period: per period at most one line changes;
// a step is DIR (if it changes) in one period, STEP high in the next, STEP low in the one after.
// DIR high = negative (LinuxCNC's convention, the component's invert_dir=1).
// One step takes at least three periods (16.7 kHz at 20 us), below the board's input limit.
struct StepgenLines {
  bool step = false, dir = false;
  int32_t position = 0;  // steps emitted, signed
  int64_t steps = 0;     // steps emitted, both directions
  int phase = 0;         // 0 idle, 1 DIR set, 2 STEP high, 3 STEP low
  void Period(int32_t target) {
    if (phase == 2) {  // end of the pulse
      step = false;
      phase = 3;
      return;
    }
    if (phase == 3) {  // the third period of the step
      phase = 0;
      return;
    }
    if (target == position) return;
    const bool negative = target < position;
    if (phase == 0 && dir != negative) {
      dir = negative;
      phase = 1;
      return;
    }
    step = true;
    position += negative ? -1 : 1;
    ++steps;
    phase = 2;
  }
};

constexpr uint32_t kPeriodNs = 20000;
constexpr uint32_t kTickHz = 1000000000u / (kPeriodsPerTick * kPeriodNs);

BoardConfig OneAxisConfig() {
  BoardConfig c = ThreadBoardConfig(ThreadBoardParams(), kPeriodNs);
  c.axis_count = 1;
  return c;
}

TEST(LinuxcncBoardIo, CountsTheSampledInputExactly) {
  for (const bool invert : {true, false}) {
    BoardConfig c = OneAxisConfig();
    c.axis[0].invert_input_dir = invert;
    HalStepIo io(kPeriodNs, true);
    ASSERT_TRUE(io.Configure(c).ok());
    StepgenLines in;
    std::mt19937_64 rng(3);
    std::uniform_int_distribution<int32_t> jump(-40, 40);
    int32_t target = 0;
    for (int period = 0; period < 200000; ++period) {
      if (period % 300 == 0) target += jump(rng);
      in.Period(target);
      // The board's convention: DIR high = positive unless inverted; the test's lines put DIR
      // high for negative moves, so the non-inverted counter counts the other way.
      const bool step[HalStepIo::kAxes] = {in.step, false, false};
      const bool dir[HalStepIo::kAxes] = {in.dir, false, false};
      io.SampleInputs(step, dir);
    }
    uint32_t count[HalStepIo::kAxes];
    io.ReadCounters(count);
    EXPECT_EQ(static_cast<int32_t>(count[0]), invert ? in.position : -in.position) << invert;
    EXPECT_GT(in.steps, 10000);
    EXPECT_EQ(io.decode_errors(), 0u);
  }
}

TEST(LinuxcncBoardIo, ReportsADirectionChangeInTheSampleOfAStep) {
  HalStepIo io(kPeriodNs, true);
  ASSERT_TRUE(io.Configure(OneAxisConfig()).ok());
  const bool lo[3] = {false, false, false};
  const bool step_up[3] = {true, false, false}, dir_up[3] = {true, false, false};
  io.SampleInputs(lo, lo);
  io.SampleInputs(step_up, lo);  // DIR low and stable: +1 (inverted input), no violation
  io.SampleInputs(lo, lo);
  io.SampleInputs(step_up, dir_up);  // -1, but DIR changed in the sample of the rise
  uint32_t count[3];
  io.ReadCounters(count);
  EXPECT_EQ(static_cast<int32_t>(count[0]), 1 - 1);
  EXPECT_EQ(io.decode_errors(), 1u);
}

TEST(LinuxcncBoardIo, RefusesWhatSampledPinsCannotDo) {
  HalStepIo io(kPeriodNs, true);
  EXPECT_TRUE(io.Configure(ThreadBoardConfig(ThreadBoardParams(), kPeriodNs)).ok());
  BoardConfig c = OneAxisConfig();
  c.axis[0].input_format = PulseFormat::kQuadrature;
  EXPECT_EQ(io.Configure(c).error(), Error::kConfigInvalid);
  c = OneAxisConfig();
  c.axis[0].output_format = PulseFormat::kCwCcw;
  EXPECT_EQ(io.Configure(c).error(), Error::kConfigInvalid);
  c = OneAxisConfig();
  c.axis[0].drive.pulse_width_ns = kPeriodNs - 1;  // could fall between two samples
  EXPECT_EQ(io.Configure(c).error(), Error::kConfigInvalid);
  c = OneAxisConfig();
  c.axis[0].drive.dir_setup_ns = kPeriodNs / 2;
  EXPECT_EQ(io.Configure(c).error(), Error::kConfigInvalid);
  c = OneAxisConfig();
  c.pulse_clock_hz = 170000000u;
  EXPECT_EQ(io.Configure(c).error(), Error::kConfigInvalid);
  c = ThreadBoardConfig(ThreadBoardParams(), kPeriodNs);
  c.axis_count = 4;
  c.axis[3] = c.axis[0];
  c.axis[3].name = 'A';
  EXPECT_EQ(io.Configure(c).error(), Error::kConfigInvalid);
  c = OneAxisConfig();
  c.tick_hz = 1000;  // 1 ms ticks: 25 pulses per tick, more edges than the queue holds
  EXPECT_EQ(io.Configure(c).error(), Error::kConfigInvalid);
}

TEST(LinuxcncBoardTimer, RunsOnlyTheThreadsTickRate) {
  ThreadTickTimer t(kPeriodNs, kPeriodsPerTick);
  EXPECT_EQ(t.thread_rate_hz(), 25000u);
  EXPECT_EQ(t.Start().error(), Error::kNotReady);
  EXPECT_EQ(t.SetRate(50000).error(), Error::kConfigInvalid);
  EXPECT_EQ(t.SetRate(24999).error(), Error::kConfigInvalid);
  EXPECT_EQ(t.rate_hz(), 0u);
  ASSERT_TRUE(t.SetRate(25000).ok());
  ASSERT_TRUE(t.Start().ok());
  EXPECT_TRUE(t.running());
  EXPECT_EQ(t.SetRate(25000).error(), Error::kBusy);
  t.Stop();
  EXPECT_FALSE(t.running());
  // 30 us periods: 16666.67 Hz ticks, no whole rate: every rate is refused.
  ThreadTickTimer odd(30000, kPeriodsPerTick);
  EXPECT_EQ(odd.thread_rate_hz(), 0u);
  EXPECT_EQ(odd.SetRate(16666).error(), Error::kConfigInvalid);
  EXPECT_EQ(odd.SetRate(16667).error(), Error::kConfigInvalid);
}

// The firmware refuses, visibly, a tick rate the thread does not run (the step I/O accepts it:
// 80 us ticks of four periods).
TEST(LinuxcncBoardTimer, FirmwareRefusesAnotherTickRate) {
  hal::mock::MockClock clock;
  hal::mock::MockSlowIo lines(&clock, nullptr);
  hal::mock::MockFlash flash(1u << 16, 4096, 8, &clock, nullptr);
  HalStepIo io(kPeriodNs, true);
  firmware::StepDirIo<HalStepIo> tick_io(&io);
  ThreadTickTimer timer(kPeriodNs, kPeriodsPerTick);
  using App = firmware::BoardApp<firmware::StepDirIo<HalStepIo>>;
  App::Devices d;
  d.tick_io = &tick_io;
  d.io = &lines;
  d.table_flash = &flash;
  d.tick_timer = &timer;
  App app(d);
  BoardConfig c = ThreadBoardConfig(ThreadBoardParams(), kPeriodNs);
  c.tick_hz = 12500;
  for (uint8_t a = 0; a < c.axis_count; ++a) {
    c.axis[a].drive.max_rate_hz = c.tick_hz;
    c.axis[a].max_input_rate_hz = c.tick_hz - c.axis[a].max_correction_rate_steps_s;
  }
  EXPECT_EQ(app.Start(c).error(), Error::kConfigInvalid);
  EXPECT_EQ(app.config_refused_by(), canopen::ConfigPart::kTickTimer);
  EXPECT_FALSE(app.started());
  EXPECT_FALSE(timer.running());
  EXPECT_TRUE(lines.output(hal::OutputLine::kFault));
  EXPECT_FALSE(lines.output(hal::OutputLine::kReady));
}

TEST(LinuxcncBoardIo, SampledOutputLosesNoPulse) {
  AxisConfig axis = OneAxisConfig().axis[0];
  StepGenerator gen;
  ASSERT_TRUE(gen.Configure(axis, kTickHz, 1000000000u).ok());
  HalStepIo io(kPeriodNs, true);
  ASSERT_TRUE(io.Configure(OneAxisConfig()).ok());
  SampledDrive drive;
  drive.dir = false;
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> move(-1, 1);
  int32_t target = 0;
  int64_t now = 0;
  for (int tick = 0; tick < 200000; ++tick) {
    // A random walk with runs, reversals and pauses; at most one step per tick (the tick rate is
    // the drive's maximum rate), often less.
    if (tick % 7 != 0) target += move(rng);
    PulsePlan plans[HalStepIo::kAxes];
    io.BeginTick(now);
    plans[0] = gen.Plan(target);
    io.Apply(plans);
    for (int p = 0; p < 2; ++p, now += kPeriodNs) {
      bool step[HalStepIo::kAxes], dir[HalStepIo::kAxes];
      io.Render(now, step, dir);
      drive.Sample(step[0], dir[0]);
    }
  }
  for (int tick = 0; tick < 1000; ++tick, now += 2 * kPeriodNs) {  // drain the backlog
    PulsePlan plans[HalStepIo::kAxes];
    io.BeginTick(now);
    plans[0] = gen.Plan(target);
    io.Apply(plans);
    bool step[HalStepIo::kAxes], dir[HalStepIo::kAxes];
    io.Render(now, step, dir);
    drive.Sample(step[0], dir[0]);
    io.Render(now + kPeriodNs, step, dir);
    drive.Sample(step[0], dir[0]);
  }
  EXPECT_EQ(gen.position(), target);
  EXPECT_EQ(drive.count, target);
  EXPECT_EQ(drive.violations, 0);
  EXPECT_EQ(io.queue_overflows(), 0u);
  EXPECT_GT(io.rendered_pulses(0), 10000);
}

// 1 um per step.
testing::GridCase Grid(uint64_t seed, double amplitude_steps) {
  std::mt19937_64 rng(seed);
  testing::GridCase g =
      testing::RandomGrid(rng, table::ElementType::kInt16, 5, 1000, amplitude_steps);
  for (auto& d : g.dim) d.origin_steps = 0;
  return g;
}

// The firmware on pins, as the component runs it: stepgen-like input lines, one tick every two
// base periods, the main loop every 50, the output sampled by drive counters. Unreferenced it
// passes the input through; the home edge (joint.N.homed) arrives where the input count is not 0
// (LinuxCNC homed to switches away from the power-on position) and makes that point the
// configured home position (home_steps); referenced and enabled, at every rest point the drives
// stand at the input plus the whole-step correction, which is the table's value (the double
// trilinear reference) at the machine position = input - input at home + home position, rounded
// to a step. (BoardGlue is process-wide: the only test that starts it.)
TEST(LinuxcncBoard, FirmwareOnPinsPassesThroughThenCompensates) {
  testing::GridCase g = Grid(21, 30.0);
  for (auto& d : g.dim) d.spacing_steps = 500;
  static const testing::AlignedBytes image = testing::WriteGridImage(g);  // outlives the board
  ASSERT_GT(image.size(), 0u);
  const int32_t home_counts[3] = {1234, -567, 890};  // input counts where the joints home
  ThreadBoardParams params;
  const int32_t home_steps[3] = {700, 300, 0};
  for (int a = 0; a < 3; ++a) params.home_position_steps[a] = home_steps[a];
  BoardGlue board;
  ASSERT_TRUE(board.Start(ThreadBoardConfig(params, kPeriodNs), kPeriodNs, true).ok());
  ASSERT_TRUE(board.ticking());
  ASSERT_TRUE(board.ActivateImage(image.data(), static_cast<uint32_t>(image.size())).ok());
  StepgenLines in[3];
  SampledDrive drive[3];
  int32_t target[3] = {};
  BoardLines lines;
  lines.enable = true;
  uint64_t period = 0;
  int64_t now = 0;
  auto run = [&](int periods) {
    for (int i = 0; i < periods; ++i, ++period, now += kPeriodNs) {
      bool step[3], dir[3];
      for (int a = 0; a < 3; ++a) {
        in[a].Period(target[a]);
        step[a] = in[a].step;
        dir[a] = in[a].dir;
      }
      HalStepIo& io = board.io();
      io.SampleInputs(step, dir);
      if (period % kPeriodsPerTick == 0 && board.ticking()) {
        io.BeginTick(now);
        board.Tick();
      }
      if (period % 50 == 0) board.Poll(lines);
      io.Render(now, step, dir);
      for (int a = 0; a < 3; ++a) drive[a].Sample(step[a], dir[a]);
    }
  };
  // Moves to random points of the grid and rests (long enough for every step and the correction
  // to settle: 4 cells x 500 steps at 16.7 kHz, then 0.1 s).
  std::mt19937_64 rng(8);
  int32_t machine[3] = {};  // the target in machine coordinates (after referencing)
  auto move_and_rest = [&]() {
    for (int a = 0; a < 3; ++a) {
      const int32_t span = static_cast<int32_t>((g.dim[a].nodes - 1) * g.dim[a].spacing_steps);
      machine[a] = std::uniform_int_distribution<int32_t>(0, span)(rng);
      target[a] = machine[a] + home_counts[a] - home_steps[a];
    }
    run(6 * 2000 + 5000);
    for (int a = 0; a < 3; ++a) ASSERT_EQ(in[a].position, target[a]) << a;
  };
  for (int i = 0; i < 4; ++i) {
    move_and_rest();
    BoardState st;
    board.ReadState(&st);
    EXPECT_FALSE(st.compensating);
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(st.correction[a], 0) << a;
      EXPECT_EQ(drive[a].count, in[a].position) << a;  // pass-through
    }
  }
  for (int a = 0; a < 3; ++a) target[a] = home_counts[a];
  run(20000);
  for (int a = 0; a < 3; ++a) lines.home[a] = true;  // rising edges: referenced here
  run(2000);
  int max_correction = 0;
  for (int i = 0; i < 8; ++i) {
    move_and_rest();
    BoardState st;
    board.ReadState(&st);
    EXPECT_TRUE(st.referenced);
    EXPECT_TRUE(st.compensating);
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(drive[a].count, int64_t{in[a].position} + st.correction[a]) << a;
      EXPECT_EQ(st.output[a], in[a].position + st.correction[a]) << a;
      EXPECT_EQ(st.backlog[a], 0) << a;
      EXPECT_NEAR(st.correction[a], testing::ExactTrilinear(g, machine, a), 0.5 + 1.0 / 256) << a;
      max_correction = std::max(max_correction, std::abs(st.correction[a]));
    }
    EXPECT_EQ(st.overruns, 0u);
  }
  EXPECT_GT(max_correction, 5);  // the table did move the drives
  for (int a = 0; a < 3; ++a) EXPECT_EQ(drive[a].violations, 0) << a;
  EXPECT_EQ(board.io().queue_overflows(), 0u);
  EXPECT_EQ(board.io().decode_errors(), 0u);
}

}  // namespace
}  // namespace volcomp::linuxcnc
