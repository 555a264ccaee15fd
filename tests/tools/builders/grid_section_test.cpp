// The GRID3 section of a grid source: corrections at the nodes in mm and in steps, INFO entries.
#include "volcomp/builders/grid_section.hpp"

#include <gtest/gtest.h>

#include "expected_value.hpp"
#include "tracker_lattice_samples.hpp"

namespace volcomp::builders {
namespace {

using model::Vec3;
using testing::kSampleLattice;
using testing::SampleLattice;
using testing::ValueOf;

std::vector<image::AxisDef> MicrometreAxes() {
  std::vector<image::AxisDef> axes(3);
  for (int a = 0; a < 3; ++a) {
    axes[static_cast<std::size_t>(a)].name = "XYZ"[a];
    axes[static_cast<std::size_t>(a)].resolution_e9 = 1000000;
  }
  return axes;
}

TEST(builders_grid_section, HoldsTheInverseOfTheCrossAxisTerm) {
  // z += k·x·y does not involve z, so the exact inverse is q = T − (0, 0, k·Tx·Ty'), with the
  // x, y part of the inverse first; on a map whose x, y are the identity: c(T) = (0, 0, −k·Tx·Ty).
  const auto sag = [](const Vec3& q) { return Vec3{q.x, q.y, q.z + 3e-7 * q.x * q.y}; };
  const GridSource src = TrackerLatticeGridSource(
      ValueOf(model::TrackerLattice::Create(SampleLattice(sag, kSampleLattice))));
  EXPECT_EQ(src.min_mm[1], -20);
  EXPECT_EQ(src.max_mm[1], 100);
  EXPECT_EQ(src.natural_spacing_mm[2], 50);
  ASSERT_NE(src.forward_or_null(), nullptr);
  GridBuildOptions o;
  o.min_mm = src.min_mm;
  o.max_mm = src.max_mm;
  o.spacing_mm = {20, 20, 25};
  o.step_mm = {0.001, 0.001, 0.001};
  const GridSection g = ValueOf(BuildGridSection(o, MicrometreAxes(), src));
  const model::CorrectionGrid& grid = g.build.grid;
  for (uint32_t k = 0; k < grid.axes[2].nodes; ++k) {
    for (uint32_t j = 0; j < grid.axes[1].nodes; ++j) {
      for (uint32_t i = 0; i < grid.axes[0].nodes; ++i) {
        const Vec3 t = grid.NodePosition(i, j, k);
        const Vec3 c = grid.correction_mm[grid.Index(i, j, k)];
        EXPECT_NEAR(c.x * 1e3, 0, 1e-9);
        EXPECT_NEAR(c.z * 1e3, -3e-7 * t.x * t.y * 1e3, 1e-6);
      }
    }
  }
  // The section is in steps (1 µm): the largest correction, at (200, 100), is −6 µm.
  EXPECT_NEAR(g.section.correction_steps.back(), -3e-7 * 200 * 100 * 1e3, 1e-6);
  EXPECT_EQ(g.info.at("lattice_mm"), "0:20:200,-20:20:100,0:25:100");
  EXPECT_NE(g.info.at("method").find("lattice"), std::string::npos);
}

TEST(builders_grid_section, ALatticeOffTheAxesStepsIsRefused) {
  const auto identity = [](const Vec3& q) { return q; };
  const GridSource src = TrackerLatticeGridSource(
      ValueOf(model::TrackerLattice::Create(SampleLattice(identity, kSampleLattice))));
  GridBuildOptions o;
  o.min_mm = src.min_mm;
  o.max_mm = src.max_mm;
  o.spacing_mm = {20, 20, 25};
  o.step_mm = {0.001, 0.001, 0.001};
  std::vector<image::AxisDef> axes = MicrometreAxes();
  axes[1].resolution_e9 = 3000000;  // 3 µm per step: 20 mm is not a whole number of them
  const auto refused = BuildGridSection(o, axes, src);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, Error::kInputInvalid);
  EXPECT_EQ(refused.error().message, "axis Y grid origin is not a whole number of steps");
}

}  // namespace
}  // namespace volcomp::builders
