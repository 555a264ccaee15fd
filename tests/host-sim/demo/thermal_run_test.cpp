// A duty cycle on the heat-balance machine (host-sim/demo thermal_run.hpp): the drift the laser
// reads at the check points is the bodies' deformation, worked out here from their temperatures
// (the run's truth record) with the expansion formulas of docs/simulator.md "Heat balance".
#include "volcomp/sim/thermal_run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "expected_value.hpp"

namespace volcomp::sim {
namespace {

using volcomp::testing::ValueOf;

const DriftReading& At(const ThermalRun& run, double t_s, int axis, bool high) {
  const DriftReading* found = nullptr;
  for (const DriftReading& r : run.readings) {
    if (r.time_s != t_s || r.axis != axis) continue;
    if (!found || (high ? r.position_mm > found->position_mm : r.position_mm < found->position_mm))
      found = &r;
  }
  EXPECT_NE(found, nullptr) << t_s << " " << axis;
  return *found;
}

TEST(ThermalRun, TheLaserReadsTheBodiesDeformation) {
  Machine machine = ValueOf(Machine::Create(MachineOptions{}));
  ThermalRunOptions o;
  o.check_interval_s = 1800;
  const ThermalRun run = RunDutyCycle(machine, CalibrationDutyCycle(), o);
  ASSERT_GE(run.bodies_C.size(), 8u);
  const auto& first = run.bodies_C.front();
  const auto& b = run.bodies_C[6];  // 3 h in: the spindle running, every body warm
  const double t = b[0];
  ASSERT_EQ(t, 3 * 3600);
  ASSERT_GT(b[1] - first[1], 5);  // the spindle warmed
  // Temperatures of the bodies (spindle, head, screw, structure) relative to 20 C.
  const double a = 11.5e-3;  // um per K and mm
  auto z_um = [&](const std::array<double, 5>& c) {
    return -a * (120 * (c[1] - 20) + 300 * (c[2] - 20)) + a * 250 * (c[4] - 20);
  };
  auto y_um = [&](const std::array<double, 5>& c) {
    return a * 150 * (0.7 * (c[2] - 20) + 0.3 * (c[1] - 20));
  };
  for (bool high : {false, true}) {
    EXPECT_NEAR(At(run, t, 2, high).deviation_um - At(run, 0, 2, high).deviation_um,
                z_um(b) - z_um(first), 2e-3);
    EXPECT_NEAR(At(run, t, 1, high).deviation_um - At(run, 0, 1, high).deviation_um,
                y_um(b) - y_um(first), 2e-3);
  }
  // X: the screw's expansion grows with the distance from its fixed end (x = 0): between the two
  // check points the drift differs by 11.5 ppm/K * dT * (x_high - x_low).
  const DriftReading& lo = At(run, t, 0, false);
  const DriftReading& hi = At(run, t, 0, true);
  const double drift_lo = lo.deviation_um - At(run, 0, 0, false).deviation_um;
  const double drift_hi = hi.deviation_um - At(run, 0, 0, true).deviation_um;
  const double screw_ppm = 11.5 * (b[3] - first[3]);
  EXPECT_NEAR(drift_hi - drift_lo, screw_ppm * 1e-3 * (hi.position_mm - lo.position_mm), 0.01);
  EXPECT_NEAR(drift_lo, screw_ppm * 1e-3 * lo.position_mm, 0.01);
}

TEST(ThermalRun, ReadsEveryPointAtEveryCheckWithTheChannels) {
  Machine machine = ValueOf(Machine::Create(MachineOptions{}));
  ThermalRunOptions o;
  o.check_interval_s = 600;
  const DutyCycle cycle = VerificationDutyCycle();
  const ThermalRun run = RunDutyCycle(machine, cycle, o);
  const size_t checks = static_cast<size_t>(std::floor(cycle.duration_s() / 600)) + 1;
  EXPECT_EQ(run.readings.size(), checks * 6);  // two points on each of three axes
  ASSERT_EQ(run.channel_names.size(), 3u);
  for (const DriftReading& r : run.readings) ASSERT_EQ(r.channels_cC.size(), 3u);
  // The ambient sensor sees the 3 K step of the verification cycle (its offset is 0.2 K).
  EXPECT_NEAR(run.readings.front().channels_cC[2] / 100.0, 20.2, 0.2);
  EXPECT_NEAR(run.readings.back().channels_cC[2] / 100.0, 23.2, 0.2);
}

// A correction the board would add at the check points is in the readings: a constant 5 um on Z.
TEST(ThermalRun, AppliesTheBoardsCorrection) {
  Machine m1 = ValueOf(Machine::Create(MachineOptions{}));
  Machine m2 = ValueOf(Machine::Create(MachineOptions{}));
  ThermalRunOptions o;
  o.check_interval_s = 3600;
  const ThermalRun plain = RunDutyCycle(m1, CalibrationDutyCycle(), o);
  const ThermalRun corrected = RunDutyCycle(
      m2, CalibrationDutyCycle(), o, [](int axis, const model::Vec3&, const std::vector<int16_t>&) {
        return axis == 2 ? 5.0 : 0;
      });
  ASSERT_EQ(plain.readings.size(), corrected.readings.size());
  for (size_t i = 0; i < plain.readings.size(); ++i) {
    const double d = corrected.readings[i].deviation_um - plain.readings[i].deviation_um;
    EXPECT_NEAR(d, plain.readings[i].axis == 2 ? 5.0 : 0.0, 1e-9);
  }
}

TEST(ThermalRun, WritesTheDriftTestCsv) {
  ThermalRun run;
  run.cycle = "calibration";
  run.channel_names = {"screw_x", "ambient"};
  run.readings.push_back({300, 0, 40, -1.25, {2512, 1999}});
  const std::string csv = DriftTestCsv(run, "S500");
  EXPECT_NE(csv.find("# machine: S500\n"), std::string::npos);
  EXPECT_NE(csv.find("time_s,axis,position_mm,deviation_um,T_screw_x_C,T_ambient_C\n"
                     "300,X,40.000,-1.250,25.12,19.99\n"),
            std::string::npos)
      << csv;
}

// The largest drift per axis is against each point's own first reading.
TEST(ThermalRun, MaxDriftIsPerPointAgainstItsFirstReading) {
  ThermalRun run;
  run.readings = {{0, 0, 40, 100, {}},   {0, 0, 360, -50, {}},   {0, 2, 20, 7, {}},
                  {300, 0, 40, 103, {}}, {300, 0, 360, -58, {}}, {300, 2, 20, 6.5, {}},
                  {600, 0, 40, 96, {}},  {600, 0, 360, -52, {}}, {600, 2, 20, 7.25, {}}};
  const std::array<double, 3> m = MaxDrift_um(run);
  EXPECT_EQ(m[0], 8);  // -58 against -50
  EXPECT_EQ(m[1], 0);
  EXPECT_EQ(m[2], 0.5);
}

}  // namespace
}  // namespace volcomp::sim
