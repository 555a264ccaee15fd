// Virtual instruments on a hand-made machine whose errors are known in closed form, and the
// instruments' error statistics.
#include "volcomp/sim/instruments.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sim_machines.hpp"
#include "volcomp/sim/machine.hpp"
#include "volcomp/sim/random.hpp"

namespace volcomp::sim {
namespace {

using volcomp::testing::LinearErrorModel;
using volcomp::testing::MachineOf;

// X: 0..100 mm; at 100 mm: E_XX = 10, E_YX = -4, E_ZX = 2 um, E_BX = 100 urad (linear between);
// Y and Z: no errors. Chain X -> Y -> Z from the workpiece to the tool, tool offset 0.
Machine SimpleMachine() {
  model::AxisErrorSample x_at_100mm;
  x_at_100mm.linear_um = {10, -4, 2};
  x_at_100mm.angular_urad = {0, 100, 0};
  return MachineOf(LinearErrorModel({x_at_100mm, {}, {}}));
}

InterferometerOptions Perfect() {
  InterferometerOptions o;
  o.linear_um = {0, 1, 0, 0};
  o.angular_urad = {0, 1, 0, 0};
  return o;
}

// At q = (50, 50, 20) relative to q0 = (0, 50, 20): E_X(50) = (5, -2, 1) um plus the rotation of X
// (50 urad about +y) acting on the lever (0, 50, 20) mm: (50e-6 * 20 mm, 0, 0) = (1, 0, 0) um.
// The model rotates exactly; the second-order part (20 mm * (cos 50 urad - 1) = -2.5e-5 um) is
// within the tolerance kTolUm.
constexpr double kTolUm = 1e-4;
const model::Vec3 kQ0 = {0, 50, 20};
const model::Vec3 kQ = {50, 50, 20};
const model::Vec3 kExpectedUm = {6, -2, 1};

TEST(SimInstruments, InterferometerReadsTheToolPointOfTheModel) {
  Machine machine = SimpleMachine();
  LaserInterferometer laser(&machine, Perfect(), 1);
  laser.Zero(kQ0, kQ0);
  EXPECT_NEAR(laser.Deviation_um(kQ, kQ, {1, 0, 0}), kExpectedUm.x, kTolUm);
  EXPECT_NEAR(laser.Deviation_um(kQ, kQ, {0, 1, 0}), kExpectedUm.y, kTolUm);
  EXPECT_NEAR(laser.Deviation_um(kQ, kQ, {0, 0, 1}), kExpectedUm.z, kTolUm);
  // Along a diagonal beam: the projection.
  const double r = 1 / std::sqrt(3.0);
  EXPECT_NEAR(laser.Deviation_um(kQ, kQ, {r, r, r}), r * (6 - 2 + 1), kTolUm);
  // The deviation is relative to the commanded displacement.
  EXPECT_NEAR(laser.Deviation_um(kQ, {50.002, 50, 20}, {1, 0, 0}), kExpectedUm.x - 2, kTolUm);
}

TEST(SimInstruments, SixDofReadsLinearAndAngularErrorMotions) {
  Machine machine = SimpleMachine();
  LaserInterferometer laser(&machine, Perfect(), 1);
  laser.Zero(kQ0, kQ0);
  const SixDofReading r = laser.SixDof(kQ, kQ, 0);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(r.linear_um[i], kExpectedUm[i], kTolUm) << i;
  EXPECT_NEAR(r.angular_urad.x, 0, 1e-4);
  EXPECT_NEAR(r.angular_urad.y, 50, 1e-4);
  EXPECT_NEAR(r.angular_urad.z, 0, 1e-4);
}

// A beam 1 mrad off the line of motion reads cos(1 mrad) of the 50.006 mm the tool moved along x:
// 50.006 mm · (1 − cos 1e-3) = 0.0250 µm short. Only the linear channel along the beam.
TEST(SimInstruments, MisalignedBeamHasTheCosineError) {
  Machine machine = SimpleMachine();
  InterferometerOptions o = Perfect();
  o.misalignment_mrad = 1.0;
  LaserInterferometer laser(&machine, o, 1);
  laser.Zero(kQ0, kQ0);
  EXPECT_NEAR(laser.Deviation_um(kQ, kQ, {1, 0, 0}), kExpectedUm.x - 0.025003, kTolUm);
  const SixDofReading r = laser.SixDof(kQ, kQ, 0);
  EXPECT_NEAR(r.linear_um.x, kExpectedUm.x - 0.025003, kTolUm);
  EXPECT_NEAR(r.linear_um.y, kExpectedUm.y, kTolUm);
  EXPECT_NEAR(r.angular_urad.y, 50, 1e-4);
}

TEST(SimInstruments, ReadingScatterMatchesNoiseAveragingAndRepeatability) {
  Machine machine = SimpleMachine();
  InterferometerOptions o = Perfect();
  o.linear_um = {0.5, 4, 0.3, 0};
  LaserInterferometer laser(&machine, o, 42);
  laser.Zero(kQ0, kQ0);
  const int n = 4000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const double v = laser.Deviation_um(kQ, kQ, {1, 0, 0}) - kExpectedUm.x;
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / n;
  const double sd = std::sqrt(sum2 / n - mean * mean);
  const double expected = std::sqrt(0.5 * 0.5 / 4 + 0.3 * 0.3);
  EXPECT_NEAR(mean, 0, 4 * expected / std::sqrt(n));
  EXPECT_NEAR(sd, expected, 0.05 * expected);
}

TEST(SimInstruments, ReadingsAreQuantisedToTheResolution) {
  Machine machine = SimpleMachine();
  InterferometerOptions o = Perfect();
  o.linear_um = {0.2, 1, 0, 0.01};
  LaserInterferometer laser(&machine, o, 3);
  laser.Zero(kQ0, kQ0);
  for (int i = 0; i < 200; ++i) {
    const double v = laser.Deviation_um(kQ, kQ, {1, 0, 0});
    EXPECT_NEAR(v / 0.01, std::round(v / 0.01), 1e-6) << v;
  }
}

TEST(SimInstruments, TrackerIsRegisteredAtItsDatum) {
  Machine machine = SimpleMachine();
  TrackerOptions o;
  o.coordinate_um = {0, 1, 0, 0};
  LaserTracker tracker(&machine, o, 5);
  tracker.Zero(kQ0, kQ0);
  const model::Vec3 at_datum = tracker.Measure_mm(kQ0);
  const model::Vec3 at_q = tracker.Measure_mm(kQ);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(at_datum[i], kQ0[i], 1e-9) << i;
    EXPECT_NEAR(1e3 * (at_q[i] - kQ[i]), kExpectedUm[i], kTolUm) << i;
  }
}

}  // namespace
}  // namespace volcomp::sim
