// The native component's per-period compensation: the table at the machine position (against the
// independent double trilinear reference), ramps in and out within the limits, clamps visibly,
// wraps a rotary AXIS1D axis, gives the correction's velocity, takes new limits at run time
// without a jump and refuses limits the limiter cannot hold, switches tables within the limits,
// picks an AXIS1D table's direction row as the board does (its output turned back by more than
// the hysteresis, a parameter) and takes up a switch of rows at the switch limits (checked against
// the kinematics of a move at those limits, and against the same switch at the correction's).
#include "native/native_compensator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "native_tables.hpp"

namespace volcomp::linuxcnc {
namespace {

using testing::Grid;
using testing::kDegPerStep;
using testing::kMmPerStep;
using testing::Load;
using volcomp::testing::ExactTrilinear;
using volcomp::testing::WriteGridImage;

constexpr long kMs = 1000000;  // a 1 ms servo period
constexpr double kLsb = 1.0 / 256;

TEST(NativeCompensator, AppliesTheTableAtTheMachinePositionAndRampsOut) {
  const auto g = Grid(11, 40.0);
  const auto t = Load(WriteGridImage(g));
  ASSERT_NE(t, nullptr);
  NativeCompensator c;
  c.UseTable(t.get());
  ASSERT_TRUE(c.SetPeriod(kMs).ok());
  EXPECT_EQ(c.axis_count(), 3u);
  const int32_t at[3] = {static_cast<int32_t>(g.dim[0].spacing_steps / 3),
                         static_cast<int32_t>(g.dim[1].spacing_steps * 1.5),
                         static_cast<int32_t>(g.dim[2].spacing_steps / 2)};
  const double pos[3] = {at[0] * kMmPerStep, at[1] * kMmPerStep, at[2] * kMmPerStep};
  double corr[3], vel[3];
  for (int i = 0; i < 2000; ++i) c.Tick(pos, true, true, corr, vel);  // 2 s at 1 kHz: settled
  EXPECT_TRUE(c.engaged());
  EXPECT_FALSE(c.clamped());
  for (int a = 0; a < 3; ++a) {
    // The fixed-point lookup is within 1 LSB (1/256 step) of the exact value.
    EXPECT_NEAR(corr[a] / kMmPerStep, ExactTrilinear(g, at, a), kLsb + 1e-9) << a;
    EXPECT_EQ(vel[a], 0.0) << a;
  }
  for (int i = 0; i < 2000; ++i) c.Tick(pos, false, true, corr, vel);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(corr[a], 0.0) << a;
  EXPECT_FALSE(c.engaged());
  // Not referenced: zero as well, and no correction before a period is known.
  NativeCompensator fresh;
  fresh.UseTable(t.get());
  fresh.Tick(pos, true, true, corr, vel);
  EXPECT_FALSE(fresh.engaged());
  for (int a = 0; a < 3; ++a) EXPECT_EQ(corr[a], 0.0) << a;
}

// The limits hold per period at any thread rate (the limiter steps every period): at 50 kHz the
// correction moves at most rate / 50000 steps a period, and still reaches the table.
TEST(NativeCompensator, LimitsHoldPerPeriodOnAFastThread) {
  const auto g = Grid(14, 40.0);
  const auto t = Load(WriteGridImage(g));
  NativeCompensator c;
  c.UseTable(t.get());
  ASSERT_TRUE(c.SetPeriod(20000).ok());  // 50 kHz; default limits 2000 steps/s, 200000 steps/s^2
  const double pos[3] = {0.0, 0.0, 0.0};
  double corr[3], vel[3], last[3] = {0.0, 0.0, 0.0};
  double largest_step = 0, largest_vel = 0;
  for (int i = 0; i < 100000; ++i) {  // 2 s
    c.Tick(pos, true, true, corr, vel);
    for (int a = 0; a < 3; ++a) {
      largest_step = std::max(largest_step, std::fabs(corr[a] - last[a]) / kMmPerStep);
      largest_vel = std::max(largest_vel, std::fabs(vel[a]) / kMmPerStep);
      // The velocity output is the correction's change over the period.
      EXPECT_NEAR(vel[a] * 20e-6, corr[a] - last[a], 1e-12);
      last[a] = corr[a];
    }
  }
  EXPECT_GT(largest_step, 0.0);
  EXPECT_LE(largest_step, 2000.0 / 50000 + kLsb);
  EXPECT_LE(largest_vel, 2000.0 + kLsb * 50000);
  const int32_t at[3] = {0, 0, 0};
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(corr[a] / kMmPerStep, ExactTrilinear(g, at, a), kLsb + 1e-9) << a;
  }
}

TEST(NativeCompensator, ClampsVisibly) {
  const auto g = Grid(12, 200.0);
  const auto t = Load(WriteGridImage(g));
  NativeCompensator c;
  c.UseTable(t.get());
  ASSERT_TRUE(c.SetPeriod(kMs).ok());
  AxisLimits l = NativeCompensator::DefaultLimits(t->axis(0));
  l.max_correction = 5 * kMmPerStep;
  for (uint8_t a = 0; a < 3; ++a) ASSERT_TRUE(c.SetLimits(a, l).ok());
  const double pos[3] = {0.0, 0.0, 0.0};
  double corr[3], vel[3];
  for (int i = 0; i < 2000; ++i) c.Tick(pos, true, true, corr, vel);
  bool any_over = false;
  const int32_t at[3] = {0, 0, 0};
  for (int a = 0; a < 3; ++a) {
    EXPECT_LE(std::fabs(corr[a]), 5 * kMmPerStep + 1e-12) << a;
    any_over |= std::fabs(ExactTrilinear(g, at, a)) > 5.0;
  }
  ASSERT_TRUE(any_over);
  EXPECT_TRUE(c.clamped());
}

// A rotary axis (degrees) whose AXIS1D table wraps: the position is taken modulo the period, so
// 370.5 and -349.5 degrees read the table at 10.5 degrees.
TEST(NativeCompensator, WrapsARotaryAxis) {
  const auto g = Grid(15, 20.0);
  const auto t = Load(testing::XyzaImage(g));
  ASSERT_NE(t, nullptr);
  ASSERT_EQ(t->axis_count(), 4u);
  EXPECT_EQ(t->axis(3).kind, table::AxisKind::kRotary);
  EXPECT_EQ(t->axis(3).wrap_period_steps, 360000u);
  const double want = (testing::AValue(10) + testing::AValue(11)) / 2.0;  // steps at 10.5 degrees
  for (const double a_deg : {10.5, 370.5, -349.5, 730.5}) {
    NativeCompensator c;
    c.UseTable(t.get());
    ASSERT_TRUE(c.SetPeriod(kMs).ok());
    const double pos[4] = {0.0, 0.0, 0.0, a_deg};
    double corr[4], vel[4];
    for (int i = 0; i < 2000; ++i) c.Tick(pos, true, true, corr, vel);
    EXPECT_NEAR(corr[3] / kDegPerStep, want, kLsb + 1e-9) << a_deg;
  }
}

// New limits while the correction moves take effect once it is at rest: the correction's
// velocity never jumps (each period's change of velocity stays within the acceleration of the
// limits in force), and the new, lower velocity then holds.
TEST(NativeCompensator, TakesNewLimitsWithoutAJump) {
  const auto g = Grid(16, 300.0);
  const auto t = Load(WriteGridImage(g));
  NativeCompensator c;
  c.UseTable(t.get());
  ASSERT_TRUE(c.SetPeriod(kMs).ok());
  const double pos[3] = {0.0, 0.0, 0.0};
  double corr[3], vel[3], last_vel[3] = {0, 0, 0};
  const double accel_mm = 200000 * kMmPerStep;                      // the default
  for (int i = 0; i < 20; ++i) c.Tick(pos, true, true, corr, vel);  // ramping in
  AxisLimits slow = NativeCompensator::DefaultLimits(t->axis(0));
  slow.max_vel = 500 * kMmPerStep;
  slow.max_accel = 100000 * kMmPerStep;  // applied while moving, this would make velocity jump
  for (uint8_t a = 0; a < 3; ++a) ASSERT_TRUE(c.SetLimits(a, slow).ok());
  for (int a = 0; a < 3; ++a) last_vel[a] = vel[a];
  double max_vel_late = 0;
  for (int i = 0; i < 20000; ++i) {
    c.Tick(pos, i < 10000, true, corr, vel);  // ramp in, then out at the new limits
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(std::fabs(vel[a] - last_vel[a]), accel_mm * 1e-3 + kLsb * kMmPerStep * 1e3)
          << "period " << i << " axis " << a;
      last_vel[a] = vel[a];
      if (i >= 10000) max_vel_late = std::max(max_vel_late, std::fabs(vel[a]));
    }
  }
  EXPECT_GT(max_vel_late, 0.0);
  EXPECT_LE(max_vel_late, slow.max_vel + kLsb * kMmPerStep * 1e3);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(corr[a], 0.0);
}

TEST(NativeCompensator, RefusesLimitsTheLimiterCannotHold) {
  const auto t = Load(WriteGridImage(Grid(17, 10.0)));
  NativeCompensator c;
  c.UseTable(t.get());
  ASSERT_TRUE(c.SetPeriod(kMs).ok());
  const AxisLimits before = c.limits(0);
  AxisLimits l = before;
  l.max_accel = 1e6 * kMmPerStep;  // one step per period^2 at 1 kHz: more than the limiter takes
  EXPECT_EQ(c.SetLimits(0, l).error(), Error::kConfigInvalid);
  EXPECT_NEAR(c.MaxAccel(0), (1e6 - 1) * kMmPerStep, 1e-9);
  l = before;
  l.max_vel = -1;
  EXPECT_EQ(c.SetLimits(0, l).error(), Error::kConfigInvalid);
  l = before;
  l.max_accel = std::nan("");
  EXPECT_EQ(c.SetLimits(0, l).error(), Error::kConfigInvalid);
  l = before;
  l.max_vel = 1 * kMmPerStep;  // below one acceleration step per period
  EXPECT_EQ(c.SetLimits(0, l).error(), Error::kConfigInvalid);
  EXPECT_NEAR(c.MinVel(0, l.max_accel), 200 * kMmPerStep, 1e-12);
  EXPECT_EQ(c.limits(0).max_vel, before.max_vel);
  EXPECT_EQ(c.limits(0).max_accel, before.max_accel);
}

TEST(NativeCompensator, SwitchesTablesWithinTheLimits) {
  const auto g1 = Grid(18, 40.0), g2 = Grid(19, 40.0);
  const auto t1 = Load(WriteGridImage(g1)), t2 = Load(WriteGridImage(g2));
  NativeCompensator c;
  c.UseTable(t1.get());
  ASSERT_TRUE(c.SetPeriod(kMs).ok());
  const int32_t at[3] = {100, 200, 300};
  const double pos[3] = {at[0] * kMmPerStep, at[1] * kMmPerStep, at[2] * kMmPerStep};
  double corr[3], vel[3], last[3];
  for (int i = 0; i < 2000; ++i) c.Tick(pos, true, true, corr, vel);
  for (int a = 0; a < 3; ++a) last[a] = corr[a];
  c.UseTable(t2.get());
  for (int i = 0; i < 2000; ++i) {
    c.Tick(pos, true, true, corr, vel);
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(std::fabs(corr[a] - last[a]), 2000 * kMmPerStep * 1e-3 + 1e-12);
      last[a] = corr[a];
    }
  }
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(corr[a] / kMmPerStep, ExactTrilinear(g2, at, a), kLsb + 1e-9) << a;
  }
}

// X with an AXIS1D table whose direction rows differ: +10 steps forward, -10 steps reverse.
volcomp::testing::AlignedBytes DirectionImage() {
  static const int16_t kForward[3] = {10, 10, 10};
  static const int16_t kReverse[3] = {-10, -10, -10};
  table::ImageSpec img;
  img.table_id = 12;
  img.axis_count = 1;
  img.axes[0] = volcomp::testing::LinearAxis('X');
  img.axis1d_count = 1;
  table::Axis1dSpec& a = img.axis1d[0];
  a.axis = 0;
  a.dim = {3, 0, 100000};  // 0, 100, 200 mm
  a.forward.type = table::ElementType::kInt16;
  a.forward.i16 = kForward;
  a.has_reverse = true;
  a.reverse.type = table::ElementType::kInt16;
  a.reverse.i16 = kReverse;
  volcomp::testing::AlignedBytes out(*table::ImageSize(img));
  if (!table::WriteImage(img, out.data(), out.size()).ok()) out.resize(0);
  return out;
}

// The correction (whole steps) once settled with the joint at `step` (1 s at 1 kHz): the row of
// the direction the joint last moved in.
long SettleAt(NativeCompensator& c, int32_t step) {
  const double pos[1] = {step * kMmPerStep};
  double corr[1], vel[1];
  for (int i = 0; i < 1000; ++i) c.Tick(pos, true, true, corr, vel);
  return std::lround(corr[0] / kMmPerStep);
}

TEST(NativeCompensator, DirectionRowTurnsWhenTheOutputGoesBackMoreThanAStep) {
  const auto t = Load(DirectionImage());
  ASSERT_NE(t, nullptr);
  NativeCompensator c;
  c.UseTable(t.get());
  ASSERT_TRUE(c.SetPeriod(kMs).ok());
  const auto settle_at = [&](int32_t step) { return SettleAt(c, step); };
  EXPECT_EQ(settle_at(50000), 10);  // forward from the start
  EXPECT_EQ(settle_at(50001), 10);
  EXPECT_EQ(settle_at(50000), 10);   // one step back: within the hysteresis
  EXPECT_EQ(settle_at(49999), -10);  // two steps back from the furthest point: reverse
  EXPECT_EQ(settle_at(50000), -10);  // one step forward: still reverse
  EXPECT_EQ(settle_at(50001), 10);   // two: forward again
}

// The hysteresis is the axis's parameter: with 3 steps, a move back by 3 steps keeps the forward
// row, by 4 turns it.
TEST(NativeCompensator, DirectionHysteresisIsAParameterOfTheAxis) {
  const auto t = Load(DirectionImage());
  ASSERT_NE(t, nullptr);
  NativeCompensator c;
  c.UseTable(t.get());
  ASSERT_TRUE(c.SetPeriod(kMs).ok());
  AxisLimits l = NativeCompensator::DefaultLimits(t->axis(0));
  EXPECT_NEAR(l.direction_hysteresis, 1 * kMmPerStep, 1e-15);  // the board's default
  l.direction_hysteresis = 3 * kMmPerStep;
  ASSERT_TRUE(c.SetLimits(0, l).ok());
  const auto settle_at = [&](int32_t step) { return SettleAt(c, step); };
  EXPECT_EQ(settle_at(50000), 10);
  EXPECT_EQ(settle_at(49997), 10);  // 3 steps back: within the hysteresis
  EXPECT_EQ(settle_at(49996), -10);
  EXPECT_EQ(settle_at(49999), -10);  // 3 forward from the furthest point back
  EXPECT_EQ(settle_at(50000), 10);
}

// A switch between the rows (20 steps here) is taken up at the switch limits: within the switch
// acceleration in every period and the switch velocity, in the periods a move of 20 steps at that
// acceleration takes (a triangle profile), faster than the correction's own limits allow, which
// the same switch then needs when the switch limits are set to them.
TEST(NativeCompensator, TakesUpADirectionSwitchAtTheSwitchLimits) {
  const auto t = Load(DirectionImage());
  ASSERT_NE(t, nullptr);
  constexpr double kDistance = 20, kSwitchAccel = 400000, kSwitchVel = 10000;  // steps, /s, /s^2
  const auto reversal = [&](double switch_accel, double switch_vel, double* peak_vel) {
    NativeCompensator c;
    c.UseTable(t.get());
    EXPECT_TRUE(c.SetPeriod(kMs).ok());
    AxisLimits l = NativeCompensator::DefaultLimits(t->axis(0));
    l.switch_accel = switch_accel * kMmPerStep;
    l.switch_vel = switch_vel * kMmPerStep;
    EXPECT_TRUE(c.SetLimits(0, l).ok());
    double corr[1], vel[1], last_vel = 0;
    const double fwd[1] = {50000 * kMmPerStep}, back[1] = {49990 * kMmPerStep};
    for (int i = 0; i < 1000; ++i) c.Tick(fwd, true, true, corr, vel);
    EXPECT_NEAR(corr[0] / kMmPerStep, 10, 1e-9);
    *peak_vel = 0;
    int periods = 0;
    for (int i = 0; i < 1000; ++i) {
      c.Tick(back, true, true, corr, vel);
      const double v = vel[0] / kMmPerStep, dv = std::fabs(v - last_vel);
      EXPECT_LE(dv, std::max(switch_accel, 200000.0) * 1e-3 + 1e-6) << "period " << i;
      EXPECT_LE(std::fabs(v), std::max(switch_vel, 2000.0) + 1e-6) << "period " << i;
      *peak_vel = std::max(*peak_vel, std::fabs(v));
      last_vel = v;
      if (std::fabs(corr[0] / kMmPerStep + 10) > 1e-9) periods = i + 1;
    }
    EXPECT_NEAR(corr[0] / kMmPerStep, -10, 1e-9);
    return periods;
  };
  // Periods a move of d steps needs from rest to rest at a T^2 velocity change per period: m
  // periods up and m - 1 down cover a T^2 m^2, so 2 sqrt(d / (a T^2)) - 1 at the least.
  const auto periods_for = [&](double accel) { return 2 * std::sqrt(kDistance / (accel * 1e-6)); };
  double peak = 0, peak_slow = 0;
  const int fast = reversal(kSwitchAccel, kSwitchVel, &peak);
  EXPECT_GE(fast, std::ceil(periods_for(kSwitchAccel)) - 1);  // 14.1: 14
  EXPECT_LE(fast, std::ceil(periods_for(kSwitchAccel)) + 1);
  EXPECT_GT(peak, 2000.0);  // beyond the correction's velocity limit
  // The same switch at the correction's limits (200000 steps/s^2, 2000 steps/s): 19 periods at
  // the least.
  const int slow = reversal(200000, 2000, &peak_slow);
  EXPECT_GE(slow, std::ceil(periods_for(200000)) - 1);
  EXPECT_LE(peak_slow, 2000.0 + 1e-6);
  EXPECT_LT(fast, slow);
}

// The board's rules hold here too: a switch slower than the correction, a maximum correction
// beyond the table format's, a negative hysteresis are refused and change nothing; the maximum
// correction rounds down to whole steps; a switch
// acceleration above what the period represents is taken as that, and said.
TEST(NativeCompensator, RefusesSwitchLimitsTheBoardWouldRefuseAndSaysTheBound) {
  const auto t = Load(DirectionImage());
  NativeCompensator c;
  c.UseTable(t.get());
  ASSERT_TRUE(c.SetPeriod(kMs).ok());
  const AxisLimits before = c.limits(0);
  AxisLimits l = before;
  l.switch_accel = before.max_accel / 2;
  EXPECT_EQ(c.SetLimits(0, l).error(), Error::kConfigInvalid);
  l = before;
  l.max_correction = (table::kMaxCorrectionSteps + 1) * kMmPerStep;
  EXPECT_EQ(c.SetLimits(0, l).error(), Error::kConfigInvalid);
  l = before;
  l.direction_hysteresis = -kMmPerStep;
  EXPECT_EQ(c.SetLimits(0, l).error(), Error::kConfigInvalid);
  EXPECT_EQ(c.limits(0).switch_accel, before.switch_accel);
  // The maximum correction in whole steps, rounded down: never a larger correction than asked.
  l = before;
  l.max_correction = 2.54 * kMmPerStep;
  ASSERT_TRUE(c.SetLimits(0, l).ok());
  EXPECT_NEAR(c.MaxCorrectionInForce(0), 2 * kMmPerStep, 1e-15);
  l.max_correction = 3 * kMmPerStep;
  ASSERT_TRUE(c.SetLimits(0, l).ok());
  EXPECT_NEAR(c.MaxCorrectionInForce(0), 3 * kMmPerStep, 1e-15);
  // The default 10^8 steps/s^2 at a 1 ms period: below one step per period^2, 10^6 - 1.
  double accel = 0;
  EXPECT_EQ(c.SwitchAccel(0, &accel), SwitchAccelBound::kPeriod);
  EXPECT_NEAR(accel, (1e6 - 1) * kMmPerStep, 1e-9);
  l = before;
  l.switch_accel = 500000 * kMmPerStep;
  ASSERT_TRUE(c.SetLimits(0, l).ok());
  EXPECT_EQ(c.SwitchAccel(0, &accel), SwitchAccelBound::kNone);
  EXPECT_NEAR(accel, 500000 * kMmPerStep, 1e-9);
}

}  // namespace
}  // namespace volcomp::linuxcnc
