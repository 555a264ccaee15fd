// Compensator behaviour: pass-through until referenced, ramps, clamp, table changes, directions.
#include "volcomp/control/compensator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "test_tables.hpp"

namespace volcomp {
namespace {

constexpr double kQ8 = 256.0;
// The fixture's rate limit (1000 steps/s) per Run(): the compensator runs every
// CompensationDivider(tick_hz) ticks of the default tick.
constexpr uint32_t kTickHz = DefaultBoardConfig().tick_hz;
constexpr double kStepsPerRun = 1000.0 * CompensationDivider(kTickHz) / kTickHz;

// A uniform grid correction (every node the same vector) plus an optional X AXIS1D table.
struct TableFixture {
  std::vector<int32_t> values;
  std::vector<int32_t> x_fwd, x_rev;
  testing::AlignedBytes img;
  table::TableView view;

  TableFixture(double cx,
               double cy,
               double cz,
               bool x_table = false,
               const thermal::ThermalModel* thermal = nullptr) {
    values.assign(2 * 2 * 2 * 3, 0);
    for (size_t i = 0; i < values.size(); i += 3) {
      values[i] = static_cast<int32_t>(cx * kQ8);
      values[i + 1] = static_cast<int32_t>(cy * kQ8);
      values[i + 2] = static_cast<int32_t>(cz * kQ8);
    }
    table::GridSpec g;
    g.frac_bits = 8;
    for (auto& d : g.dim) d = {2, -100000, 200000};
    g.values.type = table::ElementType::kInt32;
    g.values.i32 = values.data();
    table::ImageSpec s = testing::XyzImageSpec(g, 42);
    if (x_table) {
      x_fwd = {0, 0};
      x_rev = {static_cast<int32_t>(3 * kQ8), static_cast<int32_t>(3 * kQ8)};  // +3 steps reversing
      table::Axis1dSpec& a = s.axis1d[0];
      a.axis = 0;
      a.frac_bits = 8;
      a.dim = {2, -100000, 200000};
      a.forward.type = a.reverse.type = table::ElementType::kInt32;
      a.forward.i32 = x_fwd.data();
      a.has_reverse = true;
      a.reverse.i32 = x_rev.data();
      s.axis1d_count = 1;
    }
    s.thermal = thermal;
    img = testing::WriteImageBytes(s);
    EXPECT_NE(img.size(), 0u);
    view = *table::ParseImage(img.data(), img.size());
  }
};

class CompensatorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    config_ = DefaultBoardConfig();
    for (int a = 0; a < 3; ++a) {
      config_.axis[a].max_correction_steps = 100;
      config_.axis[a].max_correction_rate_steps_s = 1000;
      config_.axis[a].max_correction_accel_steps_s2 = 100000;
    }
    ASSERT_TRUE(comp_.Configure(config_).ok());
  }
  // Runs with the axes at `pos_`; returns the last correction of axis 0.
  int32_t RunN(int n) {
    for (int i = 0; i < n; ++i) {
      comp_.Run(pos_, corr_);
      for (int a = 0; a < 3; ++a) {
        const double applied = comp_.applied_q8(a) / kQ8;
        max_rate_ = std::max(max_rate_, std::fabs(applied - last_[a]));
        last_[a] = applied;
      }
    }
    return corr_[0];
  }
  PreparedTable Prepare(const TableFixture& f) {
    PreparedTable t;
    EXPECT_TRUE(t.Prepare(f.view, config_).ok());
    return t;
  }

  BoardConfig config_;
  Compensator comp_;
  int32_t pos_[3] = {0, 0, 0};
  int32_t corr_[3] = {};
  double last_[3] = {};
  double max_rate_ = 0;  // steps per Run() (one compensation run)
};

TEST_F(CompensatorTest, APreparedTableLeavesTheThermalModelToItsOwner) {
  // The THERMAL section is applied by the owner's main loop (PublishThermal()): the prepared
  // table of an image with a model is the table of the same image without one.
  thermal::ThermalModel m;
  m.axis_count = 3;
  m.channel_mask = 1;
  m.axis[2].offset_um_per_K[0] = 1.0f;
  const TableFixture with_model(1, 2, 3, false, &m);
  ASSERT_NE(with_model.view.thermal, nullptr);
  const TableFixture plain(1, 2, 3);
  PreparedTable t;
  ASSERT_TRUE(t.Prepare(with_model.view, config_).ok());
  const PreparedTable p = Prepare(plain);
  const int32_t pos[3] = {1000, -2000, 3000};
  const bool reverse[3] = {};
  int32_t a[3], b[3];
  t.TargetsQ8(pos, pos, reverse, 3, a);
  p.TargetsQ8(pos, pos, reverse, 3, b);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(a[i], b[i]) << i;
  EXPECT_EQ(b[0], 1 * 256);  // the fixture's constant corrections, 1, 2, 3 steps
  EXPECT_EQ(b[2], 3 * 256);
}

TEST_F(CompensatorTest, PassThroughUntilReferenced) {
  TableFixture f(10, -20, 30);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetEnabled(true);
  RunN(20000);
  EXPECT_EQ(corr_[0], 0);
  EXPECT_EQ(corr_[1], 0);
  EXPECT_TRUE(comp_.passthrough());
  EXPECT_FALSE(comp_.engaged());
  comp_.SetReferenced(true);
  EXPECT_TRUE(comp_.engaged());
  RunN(20000);
  EXPECT_EQ(corr_[0], 10);
  EXPECT_EQ(corr_[1], -20);
  EXPECT_EQ(corr_[2], 30);
  EXPECT_FALSE(comp_.passthrough());
}

TEST_F(CompensatorTest, EnableRampsInAndDisableRampsOutWithinLimits) {
  TableFixture f(50, 0, 0);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  std::vector<int32_t> ramp;
  for (int i = 0; i < 10000; ++i) {
    comp_.Run(pos_, corr_);
    ramp.push_back(comp_.applied_q8(0));
  }
  EXPECT_EQ(ramp.back(), 50 * 256);
  // Monotonic ramp, each step within the rate limit (1000 steps/s at the compensation rate, one
  // Run() every CompensationDivider(50 kHz) ticks: 0.02 step per control tick).
  for (size_t i = 1; i < ramp.size(); ++i) {
    ASSERT_GE(ramp[i], ramp[i - 1]);
    ASSERT_LE(ramp[i] - ramp[i - 1], kStepsPerRun * 256 + 1);
  }
  const auto runs_to_full = std::find(ramp.begin(), ramp.end(), 50 * 256) - ramp.begin();
  // 50 steps at the rate limit, plus 10 ms of acceleration and braking (1000 steps/s at 100000
  // steps/s^2): a limiter converted for one tick per run instead would take 3 times as long.
  EXPECT_GT(runs_to_full, 50 / kStepsPerRun);
  EXPECT_LT(runs_to_full, (50 / kStepsPerRun) * 1.3);
  last_[0] = comp_.applied_q8(0) / kQ8;
  comp_.SetEnabled(false);
  RunN(10000);
  EXPECT_TRUE(comp_.passthrough());
  EXPECT_EQ(corr_[0], 0);
  EXPECT_LE(max_rate_, kStepsPerRun + 1.0 / 256);
}

TEST_F(CompensatorTest, FaultRampsOut) {
  TableFixture f(0, 40, 0);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  RunN(10000);
  EXPECT_EQ(corr_[1], 40);
  comp_.SetFault(true);
  comp_.Run(pos_, corr_);
  EXPECT_GE(corr_[1], 39);  // no jump
  RunN(10000);
  EXPECT_EQ(corr_[1], 0);
  EXPECT_TRUE(comp_.passthrough());
}

TEST_F(CompensatorTest, ClampHoldsTheConfiguredMaximum) {
  TableFixture f(5000, -5000, 99.5);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  RunN(30000);
  EXPECT_EQ(corr_[0], 100);
  EXPECT_EQ(corr_[1], -100);
  EXPECT_EQ(corr_[2], 100);  // 99.5 rounds half up
  EXPECT_EQ(comp_.target_q8(0), 100 * 256);
}

// The thermal term (thermal_term.hpp) at the commanded position, added to the table's target
// before the clamp; the expected values are worked here in double from the terms' definition.
TEST_F(CompensatorTest, TheThermalTermIsAddedToTheTargetBeforeTheClamp) {
  TableFixture f(10, -20, 30);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  thermal::ThermalTermSteps terms[2];
  terms[0].offset_q8 = 5 * 256;  // +5 steps at p0
  terms[0].slope_q32 = 1288490;  // 0.0003 steps per step
  terms[0].p0_steps = 10000;
  terms[1].offset_q8 = -640;       // -2.5 steps, no slope
  comp_.PublishThermal(terms, 2);  // axis 2: none
  // From the published terms (not read back from the compensator).
  auto thermal_steps = [&](int a, double pos) {
    return terms[a].offset_q8 / kQ8 + terms[a].slope_q32 / 4294967296.0 * (pos - terms[a].p0_steps);
  };
  for (const int32_t x : {20000, 0, -70000}) {
    pos_[0] = x;
    RunN(20000);
    const double want0 = 10 + thermal_steps(0, x);
    EXPECT_NEAR(comp_.target_q8(0) / kQ8, want0, 1 / kQ8) << "X at " << x;
    EXPECT_EQ(corr_[0], static_cast<int32_t>(std::floor(want0 + 0.5))) << "X at " << x;
  }
  EXPECT_EQ(comp_.target_q8(1), -20 * 256 - 640);
  EXPECT_EQ(corr_[1], -22);  // -22.5 rounds half up
  EXPECT_EQ(corr_[2], 30);
  EXPECT_EQ(comp_.clamped_refreshes(0), 0u);

  // A term that takes the sum past the board's maximum is clamped, and counted.
  terms[0].offset_q8 = 95 * 256;
  comp_.PublishThermal(terms, 1);  // axis 1's term drops out
  pos_[0] = 10000;                 // at p0: 10 + 95 steps
  RunN(20000);
  EXPECT_EQ(comp_.target_q8(0), 100 * 256);
  EXPECT_EQ(corr_[0], 100);
  EXPECT_GT(comp_.clamped_refreshes(0), 0u);
  EXPECT_EQ(corr_[1], -20);

  // Disengaged: the thermal term goes with the table's (it is read in the table's coordinates).
  comp_.SetEnabled(false);
  RunN(30000);
  EXPECT_EQ(corr_[0], 0);
  EXPECT_TRUE(comp_.passthrough());

  // Reset() drops the published terms.
  ASSERT_TRUE(comp_.Configure(config_).ok());
  EXPECT_EQ(comp_.thermal_term(0).offset_q8, 0);
  EXPECT_EQ(comp_.thermal_term(0).slope_q32, 0);
}

TEST_F(CompensatorTest, TableChangeIsSpreadWithinLimits) {
  TableFixture a(-30, 0, 0), b(30, 0, 0);
  comp_.SetTable(Prepare(a), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  RunN(10000);
  ASSERT_EQ(corr_[0], -30);
  max_rate_ = 0;
  comp_.SetTable(Prepare(b), pos_);
  EXPECT_EQ(comp_.table_id(), 42u);
  RunN(10000);
  EXPECT_EQ(corr_[0], 30);
  EXPECT_LE(max_rate_, kStepsPerRun + 1.0 / 256);  // applied_q8() truncates to 1/256 step
}

// The AXIS1D direction turns when the drive has gone back by more than the axis's direction
// hysteresis (default 1 step: the one-step dither of the output at rest never turns it).
TEST_F(CompensatorTest, ReverseDirectionSelectsTheReverseTable) {
  TableFixture f(0, 0, 0, /*x_table=*/true);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  pos_[0] = 100;
  RunN(5000);
  EXPECT_EQ(corr_[0], 0);
  EXPECT_FALSE(comp_.reverse(0));
  pos_[0] = 99;  // one step back: within the hysteresis
  RunN(100);
  EXPECT_FALSE(comp_.reverse(0));
  pos_[0] = 100;  // and forward again: a dither
  RunN(100);
  pos_[0] = 98;  // two steps back from the furthest point: the drive reverses
  RunN(5000);
  EXPECT_TRUE(comp_.reverse(0));
  EXPECT_EQ(corr_[0], 3);  // the reverse table's +3 (and it does not turn the drive back)
  pos_[0] = 99;            // one step forward from the lowest point: still reverse
  RunN(100);
  EXPECT_TRUE(comp_.reverse(0));
  pos_[0] = 150;
  RunN(5000);
  EXPECT_FALSE(comp_.reverse(0));
  EXPECT_EQ(corr_[0], 0);
}

TEST_F(CompensatorTest, ZeroHysteresisTurnsOnEveryStepBack) {
  config_.axis[0].direction_hysteresis_steps = 0;
  ASSERT_TRUE(comp_.Configure(config_).ok());
  TableFixture f(0, 0, 0, /*x_table=*/true);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  pos_[0] = 100;
  RunN(100);
  pos_[0] = 99;
  RunN(5000);
  EXPECT_TRUE(comp_.reverse(0));
  EXPECT_EQ(corr_[0], 3);
  pos_[0] = 100;
  RunN(5000);
  EXPECT_FALSE(comp_.reverse(0));
  EXPECT_EQ(corr_[0], 0);
}

// SetAxisLimits() while running (the native LinuxCNC component's parameters): refused with kBusy
// while the axis's correction moves and nothing changes; at rest the new limits hold and the
// axis's state (its correction, its direction) carries on; the board's rules refuse the rest.
TEST_F(CompensatorTest, SetAxisLimitsWaitsForRestAndKeepsTheState) {
  TableFixture f(50, 0, 0, /*x_table=*/true);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  pos_[0] = 100;
  RunN(10);  // ramping in
  AxisConfig slow = config_.axis[0];
  slow.max_correction_rate_steps_s = 100;
  slow.max_correction_accel_steps_s2 = 50000;
  slow.direction_hysteresis_steps = 5;
  const uint32_t div = CompensationDivider(kTickHz);
  ASSERT_FALSE(comp_.at_rest(0));
  EXPECT_EQ(comp_.SetAxisLimits(0, slow, kTickHz, div).error(), Error::kBusy);
  RunN(10000);
  ASSERT_TRUE(comp_.at_rest(0));
  ASSERT_EQ(corr_[0], 50);
  ASSERT_TRUE(comp_.SetAxisLimits(0, slow, kTickHz, div).ok());
  EXPECT_EQ(comp_.applied_q8(0), 50 * 256);  // the correction carries on
  EXPECT_FALSE(comp_.reverse(0));
  pos_[0] = 96;  // 4 steps back: within the new hysteresis of 5
  RunN(100);
  EXPECT_FALSE(comp_.reverse(0));
  pos_[0] = 94;  // 6: reverse, +3 taken up at the switch limits
  RunN(5000);
  EXPECT_TRUE(comp_.reverse(0));
  EXPECT_EQ(corr_[0], 53);
  // Ramp-out at the new rate: 100 steps/s.
  comp_.SetEnabled(false);
  max_rate_ = 0;
  for (int i = 0; i < 5000; ++i) RunN(1);
  EXPECT_LE(max_rate_, 100.0 * CompensationDivider(kTickHz) / kTickHz + 1.0 / 256);
  EXPECT_GT(max_rate_, 0.0);
  AxisConfig bad = slow;
  bad.direction_switch_accel_steps_s2 = bad.max_correction_accel_steps_s2 - 1;
  EXPECT_EQ(comp_.SetAxisLimits(0, bad, kTickHz, div).error(), Error::kConfigInvalid);
  bad = slow;
  bad.max_correction_steps = table::kMaxCorrectionSteps + 1;
  EXPECT_EQ(comp_.SetAxisLimits(0, bad, kTickHz, div).error(), Error::kConfigInvalid);
  bad = slow;
  bad.max_correction_accel_steps_s2 = 0;
  EXPECT_EQ(comp_.SetAxisLimits(0, bad, kTickHz, div).error(), Error::kConfigInvalid);
  EXPECT_EQ(comp_.SetAxisLimits(3, slow, kTickHz, div).error(), Error::kInvalidArgument);
}

// RunWhole() is Run() with every refresh phase in the one run: after one RunWhole() the targets
// are the table's at the new position (Run() needs refresh_runs() runs for that).
TEST_F(CompensatorTest, RunWholeRefreshesEveryAxisInOneRun) {
  TableFixture f(10, -20, 30);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  comp_.RunWhole(pos_);
  EXPECT_EQ(comp_.target_q8(0), 10 * 256);
  EXPECT_EQ(comp_.target_q8(1), -20 * 256);
  EXPECT_EQ(comp_.target_q8(2), 30 * 256);
  EXPECT_GT(comp_.applied_q32(0), 0);
  for (int i = 0; i < 20000; ++i) comp_.RunWhole(pos_);
  EXPECT_EQ(comp_.applied_q32(1), int64_t{-20} * (int64_t{1} << 32));
}

// The drive, not the command, decides: with the command standing still, a correction that falls
// by 40 steps (a new table) moves the drive back, and the reverse table applies.
TEST_F(CompensatorTest, ACorrectionThatMovesTheDriveBackReversesIt) {
  TableFixture high(40, 0, 0, /*x_table=*/true), low(0, 0, 0, /*x_table=*/true);
  comp_.SetTable(Prepare(high), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  pos_[0] = 100;
  RunN(10000);
  EXPECT_EQ(corr_[0], 40);
  EXPECT_FALSE(comp_.reverse(0));
  comp_.SetTable(Prepare(low), pos_);
  RunN(10000);
  EXPECT_TRUE(comp_.reverse(0));
  EXPECT_EQ(corr_[0], 3);  // 0 from the grid, +3 from the reverse table
}

// A switch between the forward and reverse tables (the lost motion to take up) moves at the
// direction switch limits: the acceleration 0x2020 (default 10^8 steps/s^2) and the rate the
// drive has left beyond the input (2 MHz - 1 MHz), not at the correction's 1000 steps/s; it ends
// when the correction is at rest again. The bounds below are worked from those figures here, not
// taken from the limiter.
TEST_F(CompensatorTest, DirectionSwitchTakesUpAtTheSwitchLimits) {
  const double runs_per_s = static_cast<double>(kTickHz) / CompensationDivider(kTickHz);
  const double switch_accel = config_.axis[0].direction_switch_accel_steps_s2 /
                              (runs_per_s * runs_per_s);  // steps per run^2
  const double switch_rate =
      (config_.axis[0].drive.max_rate_hz - config_.axis[0].max_input_rate_hz) / runs_per_s;
  TableFixture f(0, 0, 0, /*x_table=*/true);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  pos_[0] = 100;
  RunN(2000);
  ASSERT_EQ(corr_[0], 0);
  EXPECT_FALSE(comp_.switching(0));
  pos_[0] = 98;  // the drive reverses: the reverse table's +3 steps
  std::vector<double> applied = {comp_.applied_q8(0) / kQ8};
  bool seen_switching = false;
  int runs_to_full = -1;
  for (int i = 0; i < 200; ++i) {
    comp_.Run(pos_, corr_);
    applied.push_back(comp_.applied_q8(0) / kQ8);
    seen_switching = seen_switching || comp_.switching(0);
    if (runs_to_full < 0 && comp_.applied_q8(0) == 3 * 256) runs_to_full = i + 1;
  }
  EXPECT_TRUE(seen_switching);
  EXPECT_EQ(corr_[0], 3);
  // Bang-bang over 3 steps takes 2 * sqrt(3 / a) runs, after at most one refresh cycle (the axis's
  // slice) and the run the direction turns in; at the correction's limits it would take over 50.
  const double bang_bang = 2 * std::sqrt(3 / switch_accel);
  ASSERT_GT(runs_to_full, 0);
  EXPECT_LE(runs_to_full, comp_.refresh_runs() + 1 + std::ceil(bang_bang) + 1);
  EXPECT_GT(3 / kStepsPerRun, 40.0);
  for (size_t i = 1; i < applied.size(); ++i) {
    ASSERT_LE(std::fabs(applied[i] - applied[i - 1]), switch_rate + 1.0 / 256) << i;
    if (i >= 2) {
      ASSERT_LE(std::fabs(applied[i] - 2 * applied[i - 1] + applied[i - 2]),
                switch_accel + 2.0 / 256)
          << i;
    }
  }
  // Caught up: back at the correction's limits.
  EXPECT_FALSE(comp_.switching(0));

  // A table change that moves the drive forward by 40 steps (the command stands still) turns the
  // drive forward in the middle of its ramp: the switch to the forward table (-3 steps) goes with
  // the ramp at the correction's 1000 steps/s (a ramp is never sped up).
  TableFixture g(40, 0, 0, /*x_table=*/true);
  comp_.SetTable(Prepare(g), pos_);
  last_[0] = comp_.applied_q8(0) / kQ8;
  max_rate_ = 0;
  for (int i = 0; i < 10000; ++i) {
    RunN(1);
    ASSERT_FALSE(comp_.switching(0)) << i;
  }
  EXPECT_FALSE(comp_.reverse(0));
  EXPECT_EQ(corr_[0], 40);
  EXPECT_LE(max_rate_, kStepsPerRun + 1.0 / 256);
}

// Engaging, or a fault during a switch, is not a switch: a direction that turned while the
// compensation was disengaged ramps in at the correction's limits, and a switch in progress when
// the compensation disengages comes to rest, then ramps out at the correction's limits.
TEST_F(CompensatorTest, EngagingAndDisengagingAreNotSwitches) {
  TableFixture f(0, 0, 0, /*x_table=*/true);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetReferenced(true);
  pos_[0] = 100;
  RunN(100);
  pos_[0] = 90;  // reversed while disengaged
  RunN(100);
  EXPECT_TRUE(comp_.reverse(0));
  comp_.SetEnabled(true);
  last_[0] = comp_.applied_q8(0) / kQ8;
  max_rate_ = 0;
  for (int i = 0; i < 5000; ++i) {
    RunN(1);
    EXPECT_FALSE(comp_.switching(0));
  }
  EXPECT_EQ(corr_[0], 3);
  EXPECT_LE(max_rate_, kStepsPerRun + 1.0 / 256);

  // Forward again (the forward table's 0), and a fault two runs into the refresh that switches.
  pos_[0] = 200;
  int runs = 0;
  while (!comp_.switching(0) && runs < 100) {
    RunN(1);
    ++runs;
  }
  ASSERT_TRUE(comp_.switching(0));
  RunN(1);
  comp_.SetFault(true);
  int braking = 0;
  while (comp_.switching(0) && braking < 100) {
    RunN(1);
    ++braking;
  }
  EXPECT_FALSE(comp_.switching(0));
  EXPECT_LT(braking, 20);
  last_[0] = comp_.applied_q8(0) / kQ8;
  max_rate_ = 0;
  RunN(10000);
  EXPECT_EQ(corr_[0], 0);
  EXPECT_TRUE(comp_.passthrough());
  EXPECT_LE(max_rate_, kStepsPerRun + 1.0 / 256);
}

TEST_F(CompensatorTest, ImageForAnotherBoardIsRefusedAndNothingChanges) {
  TableFixture f(1, 2, 3);
  PreparedTable t;
  BoardConfig other = config_;
  other.axis[1].resolution_e9 = 500000;  // a different steps/mm on Y
  t.table_id = 99;
  EXPECT_EQ(t.Prepare(f.view, other).error(), Error::kConfigResolutionMismatch);
  EXPECT_EQ(t.table_id, 99u);
  other = config_;
  other.axis[2].name = 'W';
  EXPECT_EQ(t.Prepare(f.view, other).error(), Error::kConfigAxisMismatch);
  other.axis_count = 2;
  EXPECT_EQ(t.Prepare(f.view, other).error(), Error::kConfigTooManyAxes);
}

// The target refresh (compensator.hpp): while engaged, part p of the refresh runs on the p-th run
// of a cycle of 3 + axis_count runs: the grid is located at the positions of part 0; on part 3 + a
// axis a gets clamp(grid component + its AXIS1D table at its position and direction of that run).
// Checked run by run against an evaluation written from that description with the reference
// lookups (GridLookup::Interpolate, AxisLookup::LookupReference) and independent direction and
// wrap tracking, for every element type, with random motion, reversals and wrap-around.
template <class Loader>
void CheckRefreshSchedule(table::ElementType type, uint64_t seed) {
  std::mt19937_64 rng(seed);
  testing::GridCase g = testing::RandomGrid(rng, type, 5, 3000, 40);
  std::vector<int16_t> v16[3];
  std::vector<int32_t> v32[3];
  std::vector<float> vf[3];
  table::Axis1dSpec axis1d[2];
  for (int t = 0; t < 2; ++t) {
    table::Axis1dSpec& a = axis1d[t];
    a.axis = static_cast<uint8_t>(t == 0 ? 0 : 2);  // X (forward/reverse/backlash), Z (wrap)
    a.frac_bits = type == table::ElementType::kFloat32 ? 0 : 4;
    a.dim = t == 0 ? table::Dimension{6, -7000, 2500} : table::Dimension{5, 100, 1000};
    if (t == 1) a.period_steps = 4000;
    const uint32_t n = a.dim.nodes;
    for (int k = 0; k < (t == 0 ? 2 : 1); ++k) {
      const int idx = t == 0 ? k : 2;
      for (uint32_t i = 0; i < n; ++i) {
        const int32_t val = static_cast<int32_t>(rng() % 1601) - 800;  // +-50 steps
        v16[idx].push_back(static_cast<int16_t>(val));
        v32[idx].push_back(val);
        vf[idx].push_back(static_cast<float>(val) / 16.0f);
      }
      if (t == 1) {  // continuous across the seam
        v16[idx].back() = v16[idx].front();
        v32[idx].back() = v32[idx].front();
        vf[idx].back() = vf[idx].front();
      }
    }
    const int f = t == 0 ? 0 : 2;
    a.forward = {type, v16[f].data(), v32[f].data(), vf[f].data()};
    if (t == 0) {
      a.has_reverse = true;
      a.reverse = {type, v16[1].data(), v32[1].data(), vf[1].data()};
      a.backlash_q8 = 77;
    }
  }
  const testing::AlignedBytes img = testing::WriteGridImage(g, 9, axis1d, 2);
  ASSERT_GT(img.size(), 0u);
  const auto view = table::ParseImage(img.data(), img.size());
  ASSERT_TRUE(view.ok()) << view.status().name();
  BoardConfig config = DefaultBoardConfig();
  for (int a = 0; a < 3; ++a) {
    config.axis[a].max_correction_steps = 30;  // some targets clamp
    config.axis[a].max_correction_rate_steps_s = 20000;
    config.axis[a].max_correction_accel_steps_s2 = 4000000;
  }
  Compensator comp;
  ASSERT_TRUE(comp.Configure(config).ok());
  PreparedTable table;
  ASSERT_TRUE(table.Prepare(*view, config).ok());
  int32_t pos[3] = {static_cast<int32_t>(rng() % 20000) - 10000, 0, 0};
  comp.SetTable(table, pos);
  comp.SetReferenced(true);
  comp.SetEnabled(true);

  // Independent tracking: the drive's direction (command + the last refresh's GRID3 part, against
  // its furthest point; default hysteresis 1 step), wrapped Z position.
  bool reverse[3] = {false, false, false};
  int64_t base[3] = {0, 0, 0}, extreme[3] = {pos[0], 0, 0};
  auto sensed = [&](int a) {
    return pos[a] + static_cast<int64_t>(std::floor(static_cast<double>(base[a] + 128) / 256.0));
  };
  auto wrapped = [](int64_t p) {
    int64_t o = (p - 100) % 4000;
    return static_cast<int32_t>((o < 0 ? o + 4000 : o) + 100);
  };
  const uint32_t cycle = Compensator::kGridPhases + 3;
  EXPECT_EQ(comp.refresh_runs(), cycle);
  int32_t grid_pos[3] = {};
  int32_t expect[3] = {0, 0, 0};
  int dir[3] = {1, -1, 1};
  int refreshes = 0;
  for (uint32_t run = 0; run < 6000; ++run) {
    for (int a = 0; a < 3; ++a) {
      if (rng() % 50 == 0) dir[a] = -dir[a];
      pos[a] += dir[a] * static_cast<int32_t>(rng() % 30);
      const int64_t s_now = sensed(a);
      if (!reverse[a]) {
        if (s_now > extreme[a]) extreme[a] = s_now;
        if (extreme[a] - s_now > 1) reverse[a] = true, extreme[a] = s_now;
      } else {
        if (s_now < extreme[a]) extreme[a] = s_now;
        if (s_now - extreme[a] > 1) reverse[a] = false, extreme[a] = s_now;
      }
    }
    const uint32_t part = run % cycle;
    if (part == 0) std::copy(pos, pos + 3, grid_pos);
    if (part >= Compensator::kGridPhases) {
      const int a = static_cast<int>(part - Compensator::kGridPhases);
      int32_t gq[3];
      table.grid.Interpolate<Loader>(grid_pos, gq);
      int32_t t = 0;
      for (int c = 0; c < 3; ++c) {
        if (table.grid.axis(c) == a) t += gq[c];
      }
      base[a] = t;
      if (a == 0) t += table.axis_table[0].LookupReference(pos[0], reverse[0]);
      if (a == 2) t += table.axis_table[1].LookupReference(wrapped(pos[2]), reverse[2]);
      const int32_t max = 30 * 256;
      expect[a] = t > max ? max : (t < -max ? -max : t);
      ++refreshes;
    }
    int32_t corr[3];
    comp.Run(pos, corr);
    for (int a = 0; a < 3; ++a) {
      ASSERT_EQ(comp.target_q8(a), expect[a]) << "run " << run << " axis " << a;
      ASSERT_EQ(comp.reverse(a), reverse[a]);
    }
  }
  EXPECT_EQ(refreshes, 3000);  // parts 3..5 of each 6-run cycle refresh one axis each
  // Disengaging zeroes the targets on the next run and restarts the cycle.
  comp.SetEnabled(false);
  int32_t corr[3];
  comp.Run(pos, corr);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(comp.target_q8(a), 0);
}

TEST(CompensatorRefresh, ScheduleAndValuesInt16) {
  CheckRefreshSchedule<LoadInt16>(table::ElementType::kInt16, 31);
}
TEST(CompensatorRefresh, ScheduleAndValuesInt32) {
  CheckRefreshSchedule<LoadInt32>(table::ElementType::kInt32, 32);
}
TEST(CompensatorRefresh, ScheduleAndValuesFloat32) {
  CheckRefreshSchedule<LoadFloat32>(table::ElementType::kFloat32, 33);
}

// A new target is in effect within refresh_runs() runs of engaging, of SetTable() and of
// Rebase() (the latency the refresh adds on top of the limiter).
TEST_F(CompensatorTest, NewTargetWithinOneRefreshCycle) {
  TableFixture f(10, -20, 30), g(-5, 6, 7);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  const uint32_t n = comp_.refresh_runs();
  EXPECT_EQ(n, 6u);
  for (uint32_t i = 0; i < n; ++i) comp_.Run(pos_, corr_);
  EXPECT_EQ(comp_.target_q8(0), 10 * 256);
  EXPECT_EQ(comp_.target_q8(1), -20 * 256);
  EXPECT_EQ(comp_.target_q8(2), 30 * 256);
  for (uint32_t i = 0; i < 2; ++i) comp_.Run(pos_, corr_);  // mid-cycle
  comp_.SetTable(Prepare(g), pos_);
  for (uint32_t i = 0; i < n; ++i) comp_.Run(pos_, corr_);
  EXPECT_EQ(comp_.target_q8(0), -5 * 256);
  EXPECT_EQ(comp_.target_q8(1), 6 * 256);
  EXPECT_EQ(comp_.target_q8(2), 7 * 256);
}

// RequestRebase() (the run's table switch or referencing) rebases in the next run's refresh
// slice: the refresh cycle restarts one run later, so the new target is in effect one run after
// a Rebase()'s would be. MoveAxis() makes a coordinate jump before then invisible as motion.
TEST_F(CompensatorTest, RequestedRebaseTakesOneRefreshSlice) {
  TableFixture f(10, -20, 30), g(-5, 6, 7);
  comp_.SetTable(Prepare(f), pos_);
  comp_.SetReferenced(true);
  comp_.SetEnabled(true);
  const uint32_t n = comp_.refresh_runs();
  for (uint32_t i = 0; i < n + 2; ++i) comp_.Run(pos_, corr_);  // mid-cycle
  const PreparedTable pg = Prepare(g);
  comp_.BindTable(&pg);
  comp_.RequestRebase();
  for (uint32_t i = 0; i < n; ++i) comp_.Run(pos_, corr_);
  EXPECT_EQ(comp_.target_q8(0), -5 * 256);
  EXPECT_EQ(comp_.target_q8(1), 6 * 256);
  EXPECT_EQ(comp_.target_q8(2), 30 * 256);  // axis 2's refresh comes one run later
  comp_.Run(pos_, corr_);
  EXPECT_EQ(comp_.target_q8(2), 7 * 256);

  // Forward motion, then a jump back (re-referencing) announced with MoveAxis(): not a reversal.
  pos_[0] += 10;
  comp_.Run(pos_, corr_);
  EXPECT_FALSE(comp_.reverse(0));
  pos_[0] -= 1000;
  comp_.MoveAxis(0, pos_[0]);
  comp_.RequestRebase();
  comp_.Run(pos_, corr_);
  EXPECT_FALSE(comp_.reverse(0));
  pos_[0] -= 1;  // real motion backwards is sensed: one step is within the hysteresis,
  comp_.Run(pos_, corr_);
  EXPECT_FALSE(comp_.reverse(0));
  pos_[0] -= 1;  // the second turns the direction
  comp_.Run(pos_, corr_);
  EXPECT_TRUE(comp_.reverse(0));
}

}  // namespace
}  // namespace volcomp
