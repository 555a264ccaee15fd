// The grid sources shared by `volcomp build model|tracker|kmtpp` and the simulator: extents,
// spacings, INFO and maps, against machines given in closed form.
#include "volcomp/builders/grid_source.hpp"

#include <gtest/gtest.h>

#include "expected_value.hpp"
#include "tracker_lattice_samples.hpp"
#include "volcomp/datasets/s500.hpp"

namespace volcomp::builders {
namespace {

using model::CorrectionGrid;
using model::GridAxis;
using model::Vec3;
using testing::kSampleLattice;
using testing::SampleLattice;
using testing::ValueOf;

// Measured through a table in force that adds a constant (10, −5, 3) µm: the readings are of
// F(u + c); the new grid must hold F's own inverse correction, (0, 0, −k·x·y), i.e. the table in
// force is composed in, not forgotten.
TEST(builders_grid_source, ThroughATableInForceTheNewGridReplacesIt) {
  const Vec3 c = {0.010, -0.005, 0.003};
  const auto sag = [](const Vec3& q) { return Vec3{q.x, q.y, q.z + 3e-7 * q.x * q.y}; };
  const auto through = [&](const Vec3& u) { return sag(u + c); };
  CorrectionGrid in_force;
  in_force.axes = {GridAxis{-100, 300, 3}, GridAxis{-100, 300, 3}, GridAxis{-100, 300, 3}};
  in_force.correction_mm.assign(27, c);
  const GridSource src = TrackerLatticeThroughGridSource(
      ValueOf(model::TrackerLattice::Create(SampleLattice(through, kSampleLattice))), in_force);
  for (const Vec3& t : {Vec3{0, 0, 0}, Vec3{200, 100, 100}, Vec3{120, 40, 50}}) {
    const Vec3 q = ValueOf(src.inverse(t));
    EXPECT_NEAR((q.x - t.x) * 1e3, 0, 1e-6);
    EXPECT_NEAR((q.y - t.y) * 1e3, 0, 1e-6);
    EXPECT_NEAR((q.z - t.z) * 1e3, -3e-7 * t.x * t.y * 1e3, 1e-5);
    EXPECT_LT(Norm(src.forward(q) - t) * 1e3, 1e-5);  // what the builder verifies at the nodes
  }
}

TEST(builders_grid_source, ModelSourceIsTheModelsExtentSpacingAndMaps) {
  const model::Model s500 = datasets::S500Model();
  const GridSource src = ModelGridSource(s500);
  EXPECT_EQ(src.max_mm[0], 400);
  EXPECT_EQ(src.max_mm[2], 200);
  EXPECT_EQ(src.natural_spacing_mm[0], 20);  // Table 3.2 every 20 mm
  EXPECT_EQ(src.natural_spacing_mm[1], 10);
  const Vec3 q = {123, 45, 67};
  const Vec3 p = src.forward(q);
  EXPECT_LT(Norm(src.forward(ValueOf(src.inverse(p))) - p) * 1e3, 1e-5);
  EXPECT_EQ(src.info.at("formulation"), "physical, exact rotations, chain |XYZ");
}

TEST(builders_grid_source, KmtppSourceNeedsEquallySpacedTables) {
  model::TrackerOptions o;
  o.cosines = model::CosineSource::kSigned;
  const model::KmtppCalibration cal = model::KmtppCalibrationFromTracker(
      ValueOf(model::TrackerModel::Create(datasets::S500Tracker315(), o)), 1);
  std::array<model::AxisErrorTable, 3> tables = datasets::S500AxisTables();
  const GridSource src = ValueOf(KmtppGridSource(tables, cal, model::KmtppOptions{}));
  EXPECT_EQ(src.max_mm[1], 280);
  EXPECT_EQ(src.natural_spacing_mm[0], 20);
  EXPECT_EQ(src.forward_or_null(), nullptr);
  EXPECT_EQ(src.info.at("final_step"), "traced point");
  const Vec3 t = {50, 50, 50};
  const Vec3 q = ValueOf(src.inverse(t));
  EXPECT_EQ(Norm(q - ValueOf(model::Kmtpp(tables, cal, model::KmtppOptions{}, t)).command_mm), 0);
  // Y with one row moved: no longer equally spaced.
  std::vector<double> pos;
  std::vector<model::AxisErrorSample> rows;
  for (std::size_t i = 0; i < tables[1].size(); ++i) {
    pos.push_back(tables[1].position_mm(i) + (i == 3 ? 1.0 : 0.0));
    rows.push_back(tables[1].row(i));
  }
  tables[1] = ValueOf(model::AxisErrorTable::Create(pos, rows));
  const auto refused = KmtppGridSource(tables, cal, model::KmtppOptions{});
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, Error::kInvalidArgument);
  EXPECT_EQ(refused.error().message, "КМТПП needs equally spaced tables; axis Y is not");
}

}  // namespace
}  // namespace volcomp::builders
