// An hour of warm-up with the real firmware in the loop (host-sim/demo thermal_loop.hpp): the
// board applies the image's thermal model to the drives from the readings the PLC sends, what
// the laser reads moves by the model evaluated here by hand from those readings, and injected
// sensor faults are flagged within 2 s with the correction held.
#include "volcomp/sim/thermal_loop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "expected_value.hpp"
#include "volcomp/image/image_builder.hpp"

namespace volcomp::sim {
namespace {

using volcomp::testing::ValueOf;

// An hour: 40 min of spindle and X, 20 min standing.
DutyCycle AnHour() {
  DutyCycle c;
  c.name = "an hour";
  c.start_ambient_C = 20;
  c.segments = {{2400, 1.0, 6, 20}, {1200, 0, 0, 20}};
  return c;
}

// A model in round numbers, not fitted: Z offset -3 um/K on the spindle channel (1), X slope
// +10 um/(K m) on the screw channel (0) from p0 = 0, both referred to 20.00 C.
thermal::ThermalModel HandModel() {
  thermal::ThermalModel m;
  m.axis_count = 3;
  m.channel_mask = 0b011;
  for (int j = 0; j < 3; ++j) {
    m.reference_cC[j] = 2000;
    m.calibrated_low_cC[j] = 1500;
    m.calibrated_high_cC[j] = 6000;
  }
  m.axis[2].offset_um_per_K[1] = -3;
  m.axis[0].slope_um_per_K_m[0] = 10;
  m.axis[0].reach_mm = 400;
  m.axis[1].reach_mm = 280;
  m.axis[2].reach_mm = 200;
  return m;
}

// The hand model at the check point's position, from the channels' readings, um.
double HandCorrection_um(int axis, double position_mm, const std::vector<int16_t>& cC) {
  if (axis == 2) return -3 * (cC[1] - 2000) / 100.0;
  if (axis == 0) return 10 * (cC[0] - 2000) / 100.0 * position_mm / 1000;
  return 0;
}

std::vector<uint8_t> ImageWith(const thermal::ThermalModel& model) {
  image::ImageRequest req;
  for (char n : {'X', 'Y', 'Z'}) req.axes.push_back({n, table::AxisKind::kLinear, 1000000});
  image::AxisCorrections zero;  // the geometric part: a zero AXIS1D on X
  zero.lattice = {2, 0, 400000};
  zero.forward_steps = {0, 0};
  req.axis_tables.push_back(zero);
  req.thermal = model;
  return ValueOf(image::BuildImage(req));
}

ThermalLoopOptions Options() {
  ThermalLoopOptions o;
  o.cycle = AnHour();
  o.run.check_interval_s = 600;
  return o;
}

TEST(ThermalLoop, TheBoardAppliesTheModelFromThePlcsReadings) {
  std::ostringstream log;
  const ThermalLoopResult plain = ValueOf(RunThermalLoop(Options(), log));
  ThermalLoopOptions o = Options();
  o.image = ImageWith(HandModel());
  const ThermalLoopResult comp = ValueOf(RunThermalLoop(o, log));
  ASSERT_EQ(plain.run.readings.size(), comp.run.readings.size());
  ASSERT_EQ(comp.run.readings.size(), 7u * 6u);  // checks at 0, 10, ..., 60 min; 6 points
  double largest = 0;
  for (size_t i = 0; i < comp.run.readings.size(); ++i) {
    const DriftReading& c = comp.run.readings[i];
    const DriftReading& u = plain.run.readings[i];
    const double expected = HandCorrection_um(c.axis, c.position_mm, c.channels_cC);
    largest = std::max(largest, std::fabs(expected));
    // Allowance: the sensors' noise between the two runs' readings (0.03 K x 3 um/K, twice),
    // the drives' 1 um step.
    EXPECT_NEAR(c.deviation_um - u.deviation_um, expected, 1.5)
        << "reading " << i << " axis " << c.axis << " at " << c.time_s << " s";
  }
  EXPECT_GT(largest, 10);  // the spindle warmed: the model asks for over 10 um on Z
  EXPECT_EQ(comp.lost_steps, 0u);
  EXPECT_EQ(comp.overruns, 0u);
  for (int a = 0; a < 3; ++a) EXPECT_LE(comp.max_rate_um_s[a], 1.0 + 1e-3) << a;
}

TEST(ThermalLoop, AnOpenAndAStuckSensorAreFlaggedWithinTwoSecondsAndTheCorrectionHolds) {
  ThermalLoopOptions o = Options();
  o.image = ImageWith(HandModel());
  o.faults = {{1, SensorFault::kOpenCircuit, 1200, 30}, {0, SensorFault::kStuck, 2000, 30}};
  std::ostringstream log;
  const ThermalLoopResult r = ValueOf(RunThermalLoop(o, log));
  ASSERT_EQ(r.faults.size(), 2u);
  for (const FaultOutcome& f : r.faults) {
    EXPECT_GE(f.detected_after_s, 0) << f.injected.sensor;
    EXPECT_LE(f.detected_after_s, 2.0) << f.injected.sensor;
    EXPECT_EQ(f.change_while_held_um, 0) << f.injected.sensor;  // the hold (60 s) outlasts it
  }
}

}  // namespace
}  // namespace volcomp::sim
