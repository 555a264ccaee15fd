// Properties of the physical 21-parameter model: hand-computed single-error cases (expected values
// worked out in the comments, not taken from the code), the inverse, and first vs exact order.
#include "volcomp/model/rigid_body.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "expected_value.hpp"
#include "volcomp/datasets/s500.hpp"

namespace volcomp::model {
namespace {

using datasets::S500DissertationModel;
using datasets::S500Model;
using datasets::S500Options;
using testing::CheckOk;
using testing::ValueOf;

AxisErrorTable Constant(const Vec3& linear_um, const Vec3& angular_urad) {
  return ValueOf(AxisErrorTable::Create({0.0, 1000.0},
                                        {{linear_um, angular_urad}, {linear_um, angular_urad}}));
}

Model Zero() {
  Model m;
  for (auto& t : m.axes) t = Constant({}, {});
  return m;
}

// Multiplies every error of the model (linear, angular, squareness) by s.
Model Scaled(Model m, double s) {
  for (auto& t : m.axes) {
    std::vector<double> pos;
    std::vector<AxisErrorSample> rows;
    for (std::size_t i = 0; i < t.size(); ++i) {
      pos.push_back(t.position_mm(i));
      rows.push_back({s * t.row(i).linear_um, s * t.row(i).angular_urad});
    }
    t = ValueOf(AxisErrorTable::Create(pos, rows));
  }
  m.squareness.c0y_urad *= s;
  m.squareness.b0z_urad *= s;
  m.squareness.a0z_urad *= s;
  return m;
}

TEST(model_rigid_body, NoErrorsNoError) {
  Model m = Zero();
  m.tool_offset_mm = {5, -3, 120};
  const Vec3 e = ToolPointError_um(m, {123, 45, 67});
  EXPECT_EQ(Norm(e), 0.0);
}

TEST(model_rigid_body, PitchOfXActsThroughTheLaterAxes) {
  // E_BX = 100 µrad (rotation about +y) on X; chain X → Y → Z → tool. At (0, 50, 200) the lever
  // arm of X's rotation is (0, 50, 200) mm; (0, 1e-4, 0) × (0, 50, 200) = (0.02, 0, 0) mm, i.e.
  // +20 µm in x. Exact: x = 200·sin(1e-4) mm, z = 200·(cos(1e-4) − 1) mm = −0.001 µm.
  Model m = Zero();
  m.axes[0] = Constant({}, {0, 100, 0});
  m.order = Order::kFirst;
  Vec3 e = ToolPointError_um(m, {0, 50, 200});
  EXPECT_NEAR(e.x, 20.0, 1e-12);
  EXPECT_NEAR(e.y, 0.0, 1e-12);
  EXPECT_NEAR(e.z, 0.0, 1e-12);
  m.order = Order::kSecond;
  e = ToolPointError_um(m, {0, 50, 200});
  EXPECT_NEAR(e.x, 200e3 * std::sin(1e-4), 1e-9);
  EXPECT_NEAR(e.z, 200e3 * (std::cos(1e-4) - 1.0), 1e-9);
  // With Z first in the chain (Z carries the workpiece, X and Y the tool), X's rotation no longer
  // sees the Z travel: lever (0, 50, 0) is parallel to the axis of rotation → no error.
  m.chain = ValueOf(KinematicChain::Parse("Z", "XY"));
  m.order = Order::kFirst;
  EXPECT_NEAR(Norm(ToolPointError_um(m, {0, 50, 200})), 0.0, 1e-12);
  // The tool offset is a lever arm too: r = (0, 0, 100) mm adds 1e-4 · 100 mm = 10 µm in x.
  m.tool_offset_mm = {0, 0, 100};
  EXPECT_NEAR(ToolPointError_um(m, {0, 50, 200}).x, 10.0, 1e-12);
}

TEST(model_rigid_body, SquarenessSignConvention) {
  // C0Y = +100 µrad: Y runs along (−sin C0Y, cos C0Y, 0); at y = 100 mm the tool is 10 µm toward
  // −x.
  Model m = Zero();
  m.squareness.c0y_urad = 100;
  EXPECT_NEAR(ToolPointError_um(m, {0, 100, 0}).x, -100e3 * std::sin(1e-4), 1e-9);
  // B0Z = +50 µrad: Z tilts toward +x; A0Z = +50 µrad: Z tilts toward −y. At z = 200 mm: 10 µm.
  m = Zero();
  m.squareness.b0z_urad = 50;
  m.squareness.a0z_urad = 50;
  m.order = Order::kFirst;
  const Vec3 e = ToolPointError_um(m, {0, 0, 200});
  EXPECT_NEAR(e.x, 10.0, 1e-12);
  EXPECT_NEAR(e.y, -10.0, 1e-12);
}

TEST(model_rigid_body, LinearErrorsAddAndCarriageConventionFlipsWorkpieceAxes) {
  Model m = Zero();
  m.axes[0] = Constant({3, 1, 0}, {});
  m.axes[1] = Constant({0, -2, 4}, {});
  const Vec3 e = ToolPointError_um(m, {10, 20, 30});
  EXPECT_NEAR(e.x, 3, 1e-9);
  EXPECT_NEAR(e.y, -1, 1e-9);
  EXPECT_NEAR(e.z, 4, 1e-9);
  // Y carries the workpiece and its table is measured as the carriage's own motion: negate it.
  m.chain = ValueOf(KinematicChain::Parse("Y", "XZ"));
  m.chain.workpiece_errors = ErrorSide::kCarriage;
  const Vec3 f = ToolPointError_um(m, {10, 20, 30});
  EXPECT_NEAR(f.x, 3, 1e-9);
  EXPECT_NEAR(f.y, 1 + 2, 1e-9);
  EXPECT_NEAR(f.z, -4, 1e-9);
}

TEST(model_rigid_body, ChainParsing) {
  EXPECT_EQ(ValueOf(KinematicChain::Parse("XY", "Z")).ToString(), "XY|Z");
  EXPECT_EQ(ValueOf(KinematicChain::Parse("", "XYZ")).ToString(), "|XYZ");
  const struct {
    const char* workpiece;
    const char* tool;
    const char* message;
  } refused[] = {{"X", "XZ", "chain: axis X appears twice"},
                 {"X", "Z", "chain: each of X, Y, Z must appear exactly once"},
                 {"Q", "XYZ", "chain: unknown axis 'Q'"}};
  for (const auto& r : refused) {
    const auto chain = KinematicChain::Parse(r.workpiece, r.tool);
    ASSERT_FALSE(chain.ok()) << r.message;
    EXPECT_EQ(chain.error().code, Error::kInvalidArgument);
    EXPECT_EQ(chain.error().message, r.message);
  }
}

TEST(model_rigid_body, ForwardOfInverseIsIdentityOnRandomPoints) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> ux(-10, 410), uy(-10, 290), uz(-10, 210);
  S500Options tool;
  tool.tool_offset_mm = {0, 0, 150};
  const Model models[] = {S500Model(), S500Model(tool), Scaled(S500Model(), 20.0),
                          S500DissertationModel(Order::kFirst),
                          S500DissertationModel(Order::kSecond, DissertationCase::kMinus, 100)};
  for (const Model& m : models) {
    double worst_um = 0;
    for (int i = 0; i < 2000; ++i) {
      const Vec3 target = {ux(rng), uy(rng), uz(rng)};
      const CommandSolution s = SolveCommand(m, target);
      ASSERT_TRUE(s.converged);
      const Vec3 reached = s.command_mm + 1e-3 * ToolPointError_um(m, s.command_mm);
      worst_um = std::fmax(worst_um, 1e3 * Norm(reached - target));
    }
    EXPECT_LE(worst_um, 0.01) << m.name;
    EXPECT_LE(worst_um, 1e-4) << m.name;  // in practice far below the requirement
  }
}

TEST(model_rigid_body, FirstAndExactOrderAgreeToSecondOrder) {
  // Scaling every error by s: exact − first = O(s²), so (exact − first)/s² stays constant while
  // the error itself grows like s.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> ux(0, 400), uy(0, 280), uz(0, 200);
  S500Options o;
  o.tool_offset_mm = {0, 0, 100};
  double ratio_min = 1e300, ratio_max = 0;
  for (int i = 0; i < 50; ++i) {
    const Vec3 p = {ux(rng), uy(rng), uz(rng)};
    double d[3];
    const double s[3] = {5, 10, 20};
    for (int k = 0; k < 3; ++k) {
      Model m = Scaled(S500Model(o), s[k]);
      m.order = Order::kSecond;
      const Vec3 exact = ToolPointError_um(m, p);
      m.order = Order::kFirst;
      d[k] = Norm(exact - ToolPointError_um(m, p)) / (s[k] * s[k]);
    }
    ratio_min = std::fmin(ratio_min, std::fmin(d[1] / d[0], d[2] / d[0]));
    ratio_max = std::fmax(ratio_max, std::fmax(d[1] / d[0], d[2] / d[0]));
  }
  EXPECT_GT(ratio_min, 0.9);
  EXPECT_LT(ratio_max, 1.1);
  // At the real size (s = 1) the two orders differ by less than half a micrometre; the largest
  // part is the squareness: 280 mm · (1 − cos 1108.5 µrad) = 0.17 µm.
  const Model exact = S500Model(o);
  Model first = exact;
  first.order = Order::kFirst;
  EXPECT_LT(
      Norm(ToolPointError_um(exact, {400, 280, 200}) - ToolPointError_um(first, {400, 280, 200})),
      0.5);
}

TEST(model_rigid_body, S500BuiltInIsTheTables) {
  // Spot values of Tables 3.2-3.4 (as printed) through the model's own tables.
  const Model m = S500Model();
  EXPECT_DOUBLE_EQ(m.axes[0].Sample(380).angular_urad.z, 59.823);  // ε_xz row 19: 0.059823 µm/mm
  EXPECT_DOUBLE_EQ(m.axes[1].Sample(270).linear_um.y, 76.75);      // δ_yy row "24" (= 27)
  EXPECT_DOUBLE_EQ(m.axes[2].Sample(70).linear_um.z, -11.833333);  // δ_zz row 7
  EXPECT_DOUBLE_EQ(m.axes[1].Sample(55).linear_um.y, 0.5 * (20.85 + 23.85));  // linear between
  EXPECT_DOUBLE_EQ(m.axes[2].Sample(-5).linear_um.x, -4.133333);  // held below the table
  // Squareness from the 315 mm tracker data (ch. 2 digest §3.7).
  EXPECT_DOUBLE_EQ(m.squareness.c0y_urad, -1108.5);
  CheckOk(ValidateModel(m));
}

TEST(model_rigid_body, ValidateModelRejectsBrokenModels) {
  const auto expect_refused = [](const Model& m, const std::string& message) {
    const Outcome r = ValidateModel(m);
    ASSERT_FALSE(r.ok()) << message;
    EXPECT_EQ(r.error().code, Error::kInvalidArgument);
    EXPECT_EQ(r.error().message, message);
  };
  expect_refused(Model{}, "model: axis X has no error table");
  Model m = Zero();
  m.angle_scale = NAN;
  expect_refused(m, "model: a parameter is not finite");
  m = Zero();
  m.chain.order = {0, 0, 2};
  expect_refused(m, "model: the kinematic chain must list X, Y, Z once each");
  const auto table = AxisErrorTable::Create({0, 0}, {{}, {}});
  ASSERT_FALSE(table.ok());
  EXPECT_EQ(table.error().code, Error::kInvalidArgument);
  EXPECT_EQ(table.error().message, "axis table: positions must increase strictly (row 1)");
}

}  // namespace
}  // namespace volcomp::model
