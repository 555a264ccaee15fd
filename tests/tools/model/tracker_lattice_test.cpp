// The tracker lattice (trilinear forward map of readings at every node, its inverse): against
// machines given in closed form.
#include "volcomp/model/tracker_lattice.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "expected_value.hpp"
#include "tracker_lattice_samples.hpp"

namespace volcomp::model {
namespace {

using testing::kSampleLattice;
using testing::SampleLattice;
using testing::ValueOf;

// A machine with squareness-like shear, a scale error and a cross-axis term z += k·x·y, which is
// multilinear: trilinear interpolation reproduces it exactly, the three-line methods cannot (their
// map is a sum of one-variable functions).
Vec3 Multilinear(const Vec3& q) {
  return {q.x * (1 + 40e-6) - 0.0011 * q.y + 0.003, q.y + 0.0005 * q.z, q.z + 2e-7 * q.x * q.y};
}

TEST(model_tracker_lattice, ReproducesAMultilinearMachineEverywhereIncludingBeyond) {
  const TrackerLattice t =
      ValueOf(TrackerLattice::Create(SampleLattice(Multilinear, kSampleLattice)));
  for (const Vec3& q : {Vec3{0, -20, 0}, Vec3{200, 100, 100}, Vec3{13.7, 41.2, 77.7},
                        Vec3{-5, -30, -8}, Vec3{210, 110, 106}}) {
    const Vec3 want = Multilinear(q);
    EXPECT_LT(Norm(t.Position_mm(q) - want) * 1e3, 1e-9) << q.x << " " << q.y << " " << q.z;
  }
  // The inverse lands within its tolerance, and on the machine itself (the map is exact here).
  const Vec3 target = {123.4, 56.7, 89.0};
  const InverseSolution s = t.ExactInverse(target);
  EXPECT_TRUE(s.converged);
  EXPECT_LT(Norm(Multilinear(s.command_mm) - target) * 1e3, 1e-5);
}

TEST(model_tracker_lattice, InsideACellItIsTrilinearInTheNodes) {
  // A non-multilinear machine: between nodes the lattice gives the mean of the cell's corners at
  // the centre, and the node readings at the nodes.
  const auto bumpy = [](const Vec3& q) {
    return Vec3{q.x, q.y, q.z + 1e-3 * std::sin(q.x / 17.0) * std::cos(q.y / 11.0)};
  };
  const TrackerLattice t = ValueOf(TrackerLattice::Create(SampleLattice(bumpy, kSampleLattice)));
  EXPECT_LT(Norm(t.Position_mm({80, 10, 50}) - bumpy({80, 10, 50})), 1e-12);
  Vec3 mean;
  for (double x : {40.0, 80.0}) {
    for (double y : {10.0, 40.0}) {
      for (double z : {0.0, 50.0}) mean += 0.125 * bumpy({x, y, z});
    }
  }
  EXPECT_LT(Norm(t.Position_mm({60, 25, 25}) - mean), 1e-12);
}

TEST(model_tracker_lattice, MalformedLatticesAreRefused) {
  const auto identity = [](const Vec3& q) { return q; };
  const auto expect_refused = [](TrackerLatticeData d, const std::string& message) {
    const auto r = TrackerLattice::Create(std::move(d));
    ASSERT_FALSE(r.ok()) << message;
    EXPECT_EQ(r.error().code, Error::kInvalidArgument);
    EXPECT_EQ(r.error().message, message);
  };
  TrackerLatticeData d = SampleLattice(identity, kSampleLattice);
  d.position_mm.pop_back();
  expect_refused(d, "tracker lattice: 89 readings for 90 nodes");
  d = SampleLattice(identity, kSampleLattice);
  d.position_mm[7].y = NAN;
  expect_refused(d, "tracker lattice: a reading is not finite");
  d = SampleLattice(identity, kSampleLattice);
  d.lattice[2].nodes = 1;
  expect_refused(d, "tracker lattice: every axis needs >= 2 nodes at a positive spacing");
}

}  // namespace
}  // namespace volcomp::model
