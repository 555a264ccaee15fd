// Properties of the correction grids: exactness of trilinear interpolation where theory says so,
// the inverse at every node, the predicted interpolation error, the spacing choice and the bounds.
#include "volcomp/builders/grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "expected_value.hpp"
#include "volcomp/datasets/s500.hpp"
#include "volcomp/model/rigid_body.hpp"

namespace volcomp::builders {
namespace {

using datasets::S500DissertationModel;
using datasets::S500Model;
using datasets::S500Options;
using model::CorrectionGrid;
using model::GridAxes;
using model::Model;
using model::Order;
using model::Vec3;
using testing::ValueOf;

// The model's inverse (the command that lands on each target) as an inverse map.
InverseMap ModelInverse(const Model& m) {
  return [&m](const Vec3& t) -> Expected<Vec3> { return SolveCommand(m, t).command_mm; };
}

GridBuildOptions S500Grid(double step_mm = 0.001) {
  GridBuildOptions o;
  o.min_mm = {0, 0, 0};
  o.max_mm = {400, 280, 200};
  o.natural_spacing_mm = {20, 10, 10};  // the measurement nodes of Tables 3.2-3.4
  o.step_mm = {step_mm, step_mm, step_mm};
  return o;
}

// The forward error as a "map" whose sampled correction is the error itself.
InverseMap ForwardErrorAsMap(const Model& m) {
  return [&m](const Vec3& p) -> Expected<Vec3> { return p + 1e-3 * ToolPointError_um(m, p); };
}

double MaxTrilinearDeviationUm(const Model& m, int samples) {
  const CorrectionGrid g =
      ValueOf(SampleGrid(ValueOf(MakeGridAxes(S500Grid(), {20, 10, 10})), ForwardErrorAsMap(m)));
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> ux(0, 400), uy(0, 280), uz(0, 200);
  double worst = 0;
  for (int i = 0; i < samples; ++i) {
    const Vec3 p = {ux(rng), uy(rng), uz(rng)};
    worst = std::fmax(worst, 1e3 * Norm(g.Interpolate(p) - 1e-3 * ToolPointError_um(m, p)));
  }
  return worst;
}

TEST(builders_grid, TrilinearIsExactForFirstOrderSumOfAxisFunctions) {
  // ch. 3 digest D5: the first-order model is a sum of univariate piecewise-linear functions, so a
  // grid on the product of the measurement nodes reproduces it exactly between nodes too.
  EXPECT_LT(MaxTrilinearDeviationUm(S500DissertationModel(Order::kFirst), 3000), 1e-9);
  // The physical first-order model adds products ε_x(x)·z etc. and linear squareness terms: each
  // is multilinear inside a cell, so it is reproduced exactly as well.
  S500Options o;
  o.order = Order::kFirst;
  o.tool_offset_mm = {0, 0, 100};
  EXPECT_LT(MaxTrilinearDeviationUm(S500Model(o), 3000), 1e-9);
  // Exact rotations are not multilinear, but the difference is tiny.
  o.order = Order::kSecond;
  const double exact = MaxTrilinearDeviationUm(S500Model(o), 3000);
  EXPECT_GT(exact, 1e-9);
  EXPECT_LT(exact, 0.01);
}

TEST(builders_grid, InterpolateClampsAndHitsNodes) {
  GridBuildOptions o = S500Grid();
  const GridAxes spec = ValueOf(MakeGridAxes(o, {200, 140, 100}));
  EXPECT_EQ(spec[0].nodes, 3u);
  EXPECT_EQ(spec[1].nodes, 3u);
  EXPECT_EQ(spec[2].nodes, 3u);
  const InverseMap f = [](const Vec3& p) -> Expected<Vec3> {
    return p + Vec3{p.x * p.y * 1e-6, 0.001, 0};
  };
  const CorrectionGrid g = ValueOf(SampleGrid(spec, f));
  EXPECT_NEAR(g.Interpolate({200, 140, 100}).x, 200 * 140 * 1e-6, 1e-12);
  EXPECT_NEAR(g.Interpolate({500, 140, -50}).x, 400 * 140 * 1e-6, 1e-12);  // clamped
  EXPECT_NEAR(g.Interpolate({100, 70, 50}).x, 100 * 70 * 1e-6, 1e-12);     // bilinear: exact
}

TEST(builders_grid, InverseGridOfTheS500) {
  const Model m = S500Model();
  const ForwardMap forward = [&m](const Vec3& q) { return q + 1e-3 * ToolPointError_um(m, q); };
  const GridBuildResult r = ValueOf(BuildCorrectionGrid(S500Grid(), ModelInverse(m), &forward));
  EXPECT_EQ(r.grid.axes[0].nodes, 21u);
  EXPECT_EQ(r.grid.axes[1].nodes, 29u);
  EXPECT_EQ(r.grid.axes[2].nodes, 21u);
  EXPECT_LE(r.stats.max_residual_um, 0.01);   // the requirement at every node
  EXPECT_GT(r.stats.max_correction_um, 100);  // the S500 errors are hundreds of µm ...
  EXPECT_LT(r.interpolation.max_um, 0.5);     // ... and a grid on the table nodes captures them
  EXPECT_GT(r.interpolation.samples, 10000u);
}

TEST(builders_grid, SpacingChosenFromTheInterpolationBound) {
  const Model m = S500Model();
  const InverseMap inverse = ModelInverse(m);
  GridBuildOptions o = S500Grid();
  o.max_interp_error_um = 2.0;
  const GridBuildResult r = ValueOf(BuildCorrectionGrid(o, inverse));
  EXPECT_LE(r.interpolation.max_um, 2.0);
  ASSERT_FALSE(r.tried.empty());
  // Every coarser spacing tried before the chosen one missed the bound.
  for (std::size_t i = 0; i + 1 < r.tried.size(); ++i) EXPECT_GT(r.tried[i].second, 2.0);
  // A bound no grid within the limits can meet is refused with a message.
  o.max_interp_error_um = 1e-9;
  o.max_nodes = 20000;
  const auto refused = BuildCorrectionGrid(o, inverse);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, Error::kInputInvalid);
  EXPECT_EQ(refused.error().message.rfind(
                "no grid within the node limits predicts an interpolation error below 1e-09 µm; "
                "the finest tried",
                0),
            0u)
      << refused.error().message;
}

TEST(builders_grid, RefusesCorrectionsBeyondTheBound) {
  const Model m = S500Model();
  GridBuildOptions o = S500Grid();
  o.max_correction_um = 50;
  const auto refused = BuildCorrectionGrid(o, ModelInverse(m));
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, Error::kOutOfRange);
  EXPECT_EQ(refused.error().message,
            "correction of 421.9 µm at (400, 280, 200) mm exceeds the configured bound of 50.0 µm; "
            "check the input units or raise the bound");
}

TEST(builders_grid, SpacingMustBeWholeSteps) {
  GridBuildOptions o = S500Grid(0.0003);               // 0.3 µm per step
  const auto refused = MakeGridAxes(o, {20, 10, 10});  // 66666.67 steps
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, Error::kInvalidArgument);
  EXPECT_EQ(refused.error().message,
            "axis X: spacing 20 mm is not a whole number of steps (0.0003 mm/step)");
  EXPECT_TRUE(MakeGridAxes(o, {19.9998, 9.9999, 9.9999}).ok());
  o.min_mm = {0.0001, 0, 0};
  const auto origin = MakeGridAxes(o, {19.9998, 9.9999, 9.9999});
  ASSERT_FALSE(origin.ok());
  EXPECT_EQ(origin.error().code, Error::kInvalidArgument);
  EXPECT_EQ(origin.error().message,
            "axis X: grid origin 0.0001 mm is not a whole number of steps (0.0003 mm/step)");
}

// Each refusal says which check refused by its code, which the command line acts on (the hint of
// `volcomp build`: --max-correction-um for the bound only; a lattice the options cannot lay out
// is a usage error).
TEST(builders_grid, RefusalsAreTyped) {
  const Model m = S500Model();
  const InverseMap inverse = ModelInverse(m);
  auto code_of = [&](const GridBuildOptions& o, const ForwardMap* forward) {
    const auto r = BuildCorrectionGrid(o, inverse, forward);
    return r.ok() ? Error::kOk : r.error().code;
  };
  GridBuildOptions o = S500Grid();
  o.max_correction_um = 50;
  EXPECT_EQ(code_of(o, nullptr), Error::kOutOfRange);
  o = S500Grid();
  o.max_interp_error_um = 1e-9;
  o.max_nodes = 20000;
  EXPECT_EQ(code_of(o, nullptr), Error::kInputInvalid);
  // A forward map the inverse does not invert (the identity) misses every target.
  const ForwardMap identity = [](const Vec3& p) { return p; };
  o = S500Grid();
  const auto missed = BuildCorrectionGrid(o, inverse, &identity);
  ASSERT_FALSE(missed.ok());
  EXPECT_EQ(missed.error().code, Error::kInputInvalid);
  EXPECT_NE(missed.error().message.find("the inverse misses its target by"), std::string::npos);
  o.spacing_mm = {20.0005, 10, 10};
  EXPECT_EQ(code_of(o, nullptr), Error::kInvalidArgument);
}

// An inverse map that fails (a singular matrix in a method) ends the build with its failure.
TEST(builders_grid, AFailingInverseEndsTheBuild) {
  const InverseMap failing = [](const Vec3& t) -> Expected<Vec3> {
    if (t.x > 100) return Fail(Error::kInputInvalid, "singular here");
    return t;
  };
  const auto r = BuildCorrectionGrid(S500Grid(), failing);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, Error::kInputInvalid);
  EXPECT_EQ(r.error().message, "singular here");
}

}  // namespace
}  // namespace volcomp::builders
