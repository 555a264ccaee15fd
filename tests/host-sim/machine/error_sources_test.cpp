// The worn machine's error sources (host-sim/machine worn_profile.hpp), each on its own, against
// values worked out by hand from their definitions.
#include "volcomp/sim/error_sources.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "expected_value.hpp"
#include "volcomp/datasets/s500.hpp"
#include "volcomp/sim/machine.hpp"

namespace volcomp::sim {
namespace {

using volcomp::testing::ValueOf;

TEST(SimWear, LostMotionIsAPlayOperator) {
  LostMotion l(20);  // dead band 20 µm: the carriage trails the drive by 10 µm
  l.Reset(0);
  EXPECT_NEAR(l.Follow(0.1), -0.010, 1e-15);    // pushed forward: carriage at 0.090
  EXPECT_NEAR(l.Follow(0.095), -0.005, 1e-15);  // 5 µm back: the carriage stays at 0.090
  EXPECT_NEAR(l.Follow(0.080), 0.010, 1e-15);   // the band is taken up: carriage at 0.090
  EXPECT_NEAR(l.Follow(0.050), 0.010, 1e-15);   // pulled back: carriage at 0.060
  EXPECT_NEAR(l.Follow(0.065), -0.005, 1e-15);  // forward again, inside the band
}

// A machine with one source on; the S500 (travel X 0..400, Y 0..280, Z 0..200, power-up 10 %
// into the travel: 40, 28, 20 mm).
Machine WornWith(void (*set)(WornMachineProfile&)) {
  MachineOptions o;
  set(o.wear);
  return ValueOf(Machine::Create(o));
}

// The rigid-body S500 alone.
Machine Perfect() {
  return WornWith([](WornMachineProfile&) {});
}

TEST(SimWear, LostMotionFollowsTheDriveStepsAndWorksTheHomeSwitch) {
  Machine m = WornWith([](WornMachineProfile& w) {
    w.lost_motion = true;
    w.lost_motion_um = {20, 0, 0};
  });
  uint64_t t = 0;
  auto tick = [&](int64_t x) { m.OnDriveTick({x, 0, 0}, t += 20000); };
  for (int64_t x = 0; x <= 100; x += 10) tick(x);  // +0.1 mm
  EXPECT_NEAR(m.AxisPositions_mm({100, 0, 0}).x, 40.090, 1e-12);
  for (int64_t x = 100; x >= 90; x -= 5) tick(x);  // back 10 µm: still in the band
  EXPECT_NEAR(m.AxisPositions_mm({90, 0, 0}).x, 40.090, 1e-12);
  for (int64_t x = 90; x >= 60; x -= 5) tick(x);
  EXPECT_NEAR(m.AxisPositions_mm({60, 0, 0}).x, 40.070, 1e-12);
  EXPECT_NEAR(m.AxisPositions_mm({60, 0, 0}).y, 28.0, 1e-12);
  // Moving negative, the carriage leads the drive by 10 µm: the switch at -5 mm closes when the
  // drive is at -5.010 mm, i.e. 45010 steps below power-up.
  for (int64_t x = 60; x >= -45009; x -= 1000) tick(x);
  tick(-45009);
  EXPECT_FALSE(m.HomeSwitchClosed(0, -45009));
  tick(-45010);
  EXPECT_TRUE(m.HomeSwitchClosed(0, -45010));
}

TEST(SimWear, ScatterIsDrawnWhenAnAxisComesToRest) {
  Machine m = WornWith([](WornMachineProfile& w) {
    w.scatter = true;
    w.scatter_sigma_um = {0.8, 0, 0};
  });
  uint64_t t = 0;
  const int n = 4000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const int64_t x = (i % 2) * 1000;
    m.OnDriveTick({x, 0, 0}, t += 20000);  // moving
    const double moving = m.AxisPositions_mm({x, 0, 0}).x;
    m.OnDriveTick({x, 0, 0}, t += 19'000'000);  // 19 ms without a step: not yet at rest
    EXPECT_EQ(m.AxisPositions_mm({x, 0, 0}).x, moving);
    m.OnDriveTick({x, 0, 0}, t += 1'000'000);  // 20 ms: at rest, a new settling offset
    const double settled = m.AxisPositions_mm({x, 0, 0}).x;
    m.OnDriveTick({x, 0, 0}, t += 20000);  // still at rest: kept
    EXPECT_EQ(m.AxisPositions_mm({x, 0, 0}).x, settled);
    if (i > 0) {
      EXPECT_NE(settled, moving);
    }
    const double e_um = 1e3 * (settled - 40.0 - 1e-3 * static_cast<double>(x));
    sum += e_um;
    sum2 += e_um * e_um;
  }
  const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 0, 4 * 0.8 / std::sqrt(n));
  EXPECT_NEAR(sd, 0.8, 0.05 * 0.8);
}

TEST(SimWear, ScatterIsNotDrawnBetweenTheStepsOfASlowAxis) {
  Machine m = WornWith([](WornMachineProfile& w) {
    w.scatter = true;
    w.scatter_sigma_um = {0.8, 0, 0};
  });
  // A step every 15 ms (1 µm steps: 4 mm/min), ticks of 20 µs between: the carriage moves
  // with the drive, no settling offset appears.
  uint64_t t = 0;
  for (int64_t x = 1; x <= 200; ++x) {
    for (int tick = 0; tick < 750; ++tick) {
      m.OnDriveTick({x, 0, 0}, t += 20000);
      ASSERT_DOUBLE_EQ(m.AxisPositions_mm({x, 0, 0}).x, 40.0 + 1e-3 * static_cast<double>(x))
          << "step " << x << " tick " << tick;
    }
  }
}

TEST(SimWear, ShortPeriodScrewErrorOfTheDrivePosition) {
  Machine m = WornWith([](WornMachineProfile& w) { w.screw_error = true; });
  // X: A = 1.5 µm, P = 5 mm, φ = 0.4 rad; drive at 41.25 mm: 1.5 sin(2π·41.25/5 + 0.4) =
  // 1.5 sin(16.5π + 0.4) = 1.5 sin(π/2 + 0.4) = 1.3816 µm.
  m.OnDriveTick({1250, 0, 0}, 20000);
  EXPECT_NEAR(1e3 * (m.AxisPositions_mm({1250, 0, 0}).x - 41.25), 1.381591, 1e-6);
  // One lead further: the same error.
  EXPECT_NEAR(1e3 * (m.AxisPositions_mm({6250, 0, 0}).x - 46.25), 1.381591, 1e-6);
}

TEST(SimWear, ThermalGrowthAfterTheWarmUp) {
  Machine m = WornWith([](WornMachineProfile& w) { w.thermal = true; });
  const model::Vec3 q = {0, 100, 50};
  const double cold = datasets::S500Model().tool_offset_mm.z;  // 0: the tool point is q + e(q)
  const Machine perfect = Perfect();
  // t = 0, 60 min warm-up, τ = 60 min: spindle −30 (1 − e^−1) = −18.9636 µm; X screw at drive
  // 200 mm: 11.5 ppm/K · 4 K (1 − e^−1) · 200 mm = 5.8155 µm.
  m.OnDriveTick({160000, 0, 0}, 0);
  EXPECT_NEAR(1e3 * (m.ToolPoint_mm(q).z - perfect.ToolPoint_mm(q).z), -18.963617, 1e-6);
  EXPECT_NEAR(1e3 * (m.AxisPositions_mm({160000, 0, 0}).x - 200), 5.815509, 1e-6);
  // One hour later: −30 (1 − e^−2) = −25.9399 µm.
  m.OnDriveTick({160000, 0, 0}, 3600000000000ull);
  EXPECT_NEAR(1e3 * (m.ToolPoint_mm(q).z - perfect.ToolPoint_mm(q).z), -25.939942, 1e-6);
  EXPECT_EQ(cold, 0);
}

TEST(SimWear, CrossAxisSagDependsOnXAndY) {
  Machine m = WornWith([](WornMachineProfile& w) { w.cross_axis_sag = true; });
  const Machine perfect = Perfect();
  auto sag_um = [&](double x, double y) {
    const model::Vec3 q = {x, y, 100};
    return 1e3 * (m.ToolPoint_mm(q).z - perfect.ToolPoint_mm(q).z);
  };
  // S = 12 µm · ((x − 200)/200)² · (y/280)².
  EXPECT_NEAR(sag_um(200, 280), 0, 1e-9);
  EXPECT_NEAR(sag_um(0, 280), 12, 1e-9);
  EXPECT_NEAR(sag_um(400, 140), 3, 1e-9);
  EXPECT_NEAR(sag_um(100, 70), 0.1875, 1e-9);  // 12 · 0.25 · 0.0625
  EXPECT_NEAR(sag_um(0, 0), 0, 1e-9);
  // Not a sum of a function of x and a function of y (no 21-parameter table holds it):
  EXPECT_GT(std::fabs(sag_um(0, 280) - sag_um(0, 0) - sag_um(200, 280) + sag_um(200, 0)), 11.9);
}

}  // namespace
}  // namespace volcomp::sim
