// The heat balance, the sensors and the duty cycles (host-sim/machine) against closed-form
// solutions worked out here: a body's first-order response, the network's steady state from its
// linear equations solved by hand, the energy balance, a sensor's lag, the machine's deformation.
#include "volcomp/sim/heat_balance.hpp"

#include <gtest/gtest.h>

#include <climits>
#include <cmath>

#include "expected_value.hpp"
#include "volcomp/sim/duty_cycle.hpp"
#include "volcomp/sim/machine.hpp"
#include "volcomp/sim/thermal_sensors.hpp"

namespace volcomp::sim {
namespace {

using volcomp::testing::ValueOf;

constexpr int kX = static_cast<int>(ThermalBody::kXScrew);

// The X screw alone is one body between its friction heat and the air: T(t) = Ta + P/G (1 -
// exp(-t G / C)). 15 kJ/K and 5 W/K: tau = 3000 s; 5 m/min at 6 W per m/min: 30 W, final +6 K.
TEST(HeatBalance, TheScrewFollowsAFirstOrderResponse) {
  HeatBalance h(HeatBalanceParams{}, 20);
  const ThermalLoad load{0, 5, 20};
  for (double t : {600.0, 3000.0, 9000.0}) {
    h.Step(t - h.time_s(), load);
    EXPECT_NEAR(h.temperature_C(ThermalBody::kXScrew), 20 + 6 * (1 - std::exp(-t / 3000)), 1e-6)
        << t;
  }
  // The others did not move: nothing heats them and they started at the air's temperature.
  EXPECT_EQ(h.temperature_C(ThermalBody::kSpindle), 20);
  EXPECT_EQ(h.temperature_C(ThermalBody::kStructure), 20);
}

// The spindle at full speed until every body settles: the steady state solves
//   600 = 4 (Ts - 20) + 60 (Ts - Th)
//   60 (Ts - Th) = 18 (Th - 20) + 6 (Th - Tb)
//   6 (Th - Tb) = 150 (Tb - 20)
// With u = rises over 20: ub = 6 uh / 156 = uh / 26; 60 (us - uh) = 18 uh + 6 uh (25/26)
//   = uh (18 + 75/13) = uh 309/13; 600 = 4 us + 60 us - 60 uh -> us = (600 + 60 uh) / 64.
// Then 60 ((600 + 60 uh)/64 - uh) = uh 309/13: 562.5 + 56.25 uh - 60 uh = 23.769 uh
//   -> uh = 562.5 / 27.519 = 20.440; us = (600 + 1226.4) / 64 = 28.538; ub = 0.786.
TEST(HeatBalance, TheSpindleSettlesWhereTheNetworkBalances) {
  HeatBalance h(HeatBalanceParams{}, 20);
  h.Step(400 * 3600.0, ThermalLoad{1, 0, 20});  // 400 h: many times the structure's 5.3 h
  const double uh = 562.5 / (3.75 + 309.0 / 13);
  EXPECT_NEAR(h.temperature_C(ThermalBody::kHead) - 20, uh, 1e-3);
  EXPECT_NEAR(h.temperature_C(ThermalBody::kSpindle) - 20, (600 + 60 * uh) / 64, 1e-3);
  EXPECT_NEAR(h.temperature_C(ThermalBody::kStructure) - 20, uh / 26, 1e-3);
  EXPECT_NEAR(h.temperature_C(ThermalBody::kXScrew), 20, 1e-9);
}

// What went in is stored or went to the air, under a changing load.
TEST(HeatBalance, EnergyIsConserved) {
  HeatBalance h(HeatBalanceParams{}, 20);
  const DutyCycle cycle = VerificationDutyCycle();
  for (double t = 0; t < cycle.duration_s(); t += 10) h.Step(10, cycle.LoadAt(t));
  EXPECT_GT(h.heat_in_J(), 1e6);
  EXPECT_NEAR(h.heat_in_J() - h.heat_to_air_J(), h.heat_stored_J(), 1e-6 * h.heat_in_J());
}

// The air warms by 3 K with the machine off: every body ends at the new temperature.
TEST(HeatBalance, TheMachineFollowsTheAir) {
  HeatBalance h(HeatBalanceParams{}, 20);
  h.Step(400 * 3600.0, ThermalLoad{0, 0, 23});
  for (double t : h.temperatures_C()) EXPECT_NEAR(t, 23, 1e-6);
}

// Deformation by hand (11.5e-3 um per K and mm): the spindle alone +10 K and the screw +2 K
// give z = -11.5e-3 * 120 * 10 = -13.8 um, y through the bore's wall 5.175 um and x 23 ppm; every
// body at +4 K gives y = 11.5e-3 * 150 * 4 = 6.9 um, z = 11.5e-3 * 4 * (250 - 120 - 300) = -7.82 um
// and x 46 ppm.
TEST(HeatBalance, DeformationFromTheBodiesTemperatures) {
  HeatBalanceParams p;
  // Bodies that hold their heat (no coupling): one step with a load sets each rise exactly.
  p.to_air_W_K = {0, 0, 0, 0};
  p.spindle_to_head_W_K = 0;
  p.head_to_structure_W_K = 0;
  p.capacity_J_K = {1, 1, 1, 1};
  p.spindle_power_W = 10;
  p.screw_W_per_m_min = 1;
  HeatBalance h(p, 20);
  h.Step(1, ThermalLoad{1, 2, 20});  // spindle +10 K, screw +2 K
  ASSERT_NEAR(h.temperature_C(ThermalBody::kSpindle), 30, 1e-9);
  ASSERT_NEAR(h.temperature_C(ThermalBody::kHead), 20, 1e-9);
  const ThermalDeformation d = h.Deformation();
  EXPECT_NEAR(d.x_screw_ppm, 23, 1e-9);
  EXPECT_NEAR(d.tool_um.z, -13.8, 1e-9);
  EXPECT_NEAR(d.tool_um.y, 5.175, 1e-9);      // the bore's wall: 11.5e-3 * 150 * 0.3 * 10
  HeatBalance warm(HeatBalanceParams{}, 24);  // every body at 24 C: +4 K
  const ThermalDeformation w = warm.Deformation();
  EXPECT_NEAR(w.tool_um.y, 6.9, 1e-9);
  EXPECT_NEAR(w.tool_um.z, -7.82, 1e-9);
  EXPECT_NEAR(w.x_screw_ppm, 46, 1e-9);
}

// The machine model applies the deformation: the carriage runs ahead by ppm * (x - fixed end),
// the tool point moves by tool_um, the other axes' carriages stay.
TEST(HeatBalance, TheMachineAppliesTheDeformation) {
  Machine m = ValueOf(Machine::Create(MachineOptions{}));
  const std::array<int64_t, 3> steps = {300000, 100000, 50000};  // 1 um steps: +300/100/50 mm
  const model::Vec3 q0 = m.AxisPositions_mm(steps);
  const model::Vec3 t0 = m.ToolPoint_mm(q0);
  ThermalDeformation d;
  d.x_screw_ppm = 20;
  d.x_screw_fixed_end_mm = 40;
  d.tool_um = {1, -2, -30};
  m.SetThermalDeformation(d);
  const model::Vec3 q1 = m.AxisPositions_mm(steps);
  EXPECT_NEAR(q1.x - q0.x, 20e-6 * (q0.x - 40), 1e-12);
  EXPECT_EQ(q1.y, q0.y);
  EXPECT_EQ(q1.z, q0.z);
  const model::Vec3 t1 = m.ToolPoint_mm(q0);
  EXPECT_NEAR(t1.x - t0.x, 1e-3, 1e-12);
  EXPECT_NEAR(t1.y - t0.y, -2e-3, 1e-12);
  EXPECT_NEAR(t1.z - t0.z, -30e-3, 1e-12);
}

// A sensor follows a step of its surface with its lag and reads with its offset; noise-free and
// quantised to 0.01 K.
TEST(ThermalSensor, FollowsItsSurfaceWithItsLagAndOffset) {
  ThermalSensorParams p;
  p.body_weight[kX] = 0.75;
  p.air_weight = 0.25;
  p.lag_s = 100;
  p.offset_K = 0.4;
  p.noise_K = 0;
  HeatBalanceParams hp;
  hp.to_air_W_K = {0, 0, 0, 0};
  hp.capacity_J_K = {1, 1, 1, 1};
  hp.screw_W_per_m_min = 8;
  HeatBalance h(hp, 20);
  ThermalSensor s(p, h, 20, 1);
  EXPECT_EQ(s.Read_cC(), 2040);
  h.Step(1, ThermalLoad{0, 1, 20});  // the screw +8 K at once: the surface 20 + 6 K
  ASSERT_NEAR(h.temperature_C(ThermalBody::kXScrew), 28, 1e-9);
  s.Step(100, h, 20);  // one time constant: 1 - 1/e of the step
  EXPECT_NEAR(s.body_C(), 20 + 6 * (1 - std::exp(-1.0)), 1e-9);
  EXPECT_EQ(s.Read_cC(),
            static_cast<int16_t>(std::lround((20 + 6 * (1 - std::exp(-1.0)) + 0.4) * 100)));
}

TEST(ThermalSensor, NoiseHasItsStandardDeviation) {
  ThermalSensorParams p;
  p.air_weight = 1;
  p.noise_K = 0.05;
  HeatBalance h(HeatBalanceParams{}, 20);
  ThermalSensor s(p, h, 20, 7);
  double sum = 0, sum2 = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double r = s.Read_cC() / 100.0 - 20;
    sum += r;
    sum2 += r * r;
  }
  const double mean = sum / n;
  EXPECT_NEAR(mean, 0, 0.002);
  // Quantisation to 0.01 adds 0.01^2 / 12 to the variance.
  EXPECT_NEAR(std::sqrt(sum2 / n - mean * mean), std::sqrt(0.05 * 0.05 + 1e-4 / 12), 0.002);
}

TEST(ThermalSensor, AnOpenCircuitReadsNoValueAndAStuckOneRepeats) {
  ThermalSensorParams p;
  p.air_weight = 1;
  HeatBalance h(HeatBalanceParams{}, 20);
  ThermalSensor s(p, h, 20, 3);
  const int16_t last = s.Read_cC();
  s.InjectFault(SensorFault::kStuck);
  s.Step(3600, h, 30);  // the air warms 10 K: a working sensor would read it
  EXPECT_EQ(s.Read_cC(), last);
  EXPECT_EQ(s.Read_cC(), last);
  s.InjectFault(SensorFault::kOpenCircuit);
  EXPECT_EQ(s.Read_cC(), INT16_MIN);
  s.InjectFault(SensorFault::kNone);
  EXPECT_NEAR(s.Read_cC(), 3000, 20);
}

TEST(DutyCycle, LoadsBySegmentAndAmbientRamps) {
  DutyCycle c;
  c.start_ambient_C = 19;
  c.segments = {{600, 0.5, 2, 21}, {300, 1, 0, 21}};
  EXPECT_EQ(c.duration_s(), 900);
  EXPECT_EQ(c.LoadAt(0).ambient_C, 19);
  EXPECT_EQ(c.LoadAt(300).ambient_C, 20);  // halfway up the ramp
  EXPECT_EQ(c.LoadAt(300).spindle_fraction, 0.5);
  EXPECT_EQ(c.LoadAt(300).x_speed_m_min, 2);
  EXPECT_EQ(c.LoadAt(700).spindle_fraction, 1);
  EXPECT_EQ(c.LoadAt(700).ambient_C, 21);
  const ThermalLoad after = c.LoadAt(1000);  // after the end: stopped, at the last ambient
  EXPECT_EQ(after.spindle_fraction, 0);
  EXPECT_EQ(after.x_speed_m_min, 0);
  EXPECT_EQ(after.ambient_C, 21);
}

// The two built-in cycles are different in the way the verification needs: the verification
// has an ambient change of 3 K and stops between bursts; both run for hours.
TEST(DutyCycle, TheVerificationCycleDiffersFromTheCalibration) {
  const DutyCycle cal = CalibrationDutyCycle(), ver = VerificationDutyCycle();
  EXPECT_GE(cal.duration_s(), 4 * 3600);
  EXPECT_GE(ver.duration_s(), 4 * 3600);
  double lo = 1e9, hi = -1e9;
  int stops = 0;
  for (const DutySegment& s : ver.segments) {
    lo = std::min(lo, s.ambient_end_C);
    hi = std::max(hi, s.ambient_end_C);
    if (s.spindle_fraction == 0) ++stops;
  }
  EXPECT_NEAR(hi - lo, 3, 1e-9);
  EXPECT_GE(stops, 3);
}

}  // namespace
}  // namespace volcomp::sim
