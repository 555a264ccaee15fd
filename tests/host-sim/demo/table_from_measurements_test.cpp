// The table from parametric measurements: the measured model reproduces the machine, and the
// image built from it lands the tool on its targets. Reference: the machine's own model
// (tools/model S500Model), evaluated directly.
#include "volcomp/sim/table_from_measurements.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "volcomp/datasets/s500.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/sim/measurements.hpp"
#include "volcomp/sim/random.hpp"

namespace volcomp::sim {
namespace {

class SimTable : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    WorldOptions wo;
    const Expected<Machine> machine = Machine::Create(wo.machine);
    ASSERT_TRUE(machine.ok()) << machine.error().message;
    wo.board = BoardSettingsFor(*machine);
    const Expected<std::unique_ptr<World>> world = World::Create(wo);
    ASSERT_TRUE(world.ok()) << world.error().message;
    World& w = **world;
    ASSERT_TRUE(w.Start().ok());
    w.cnc().QueueHome(7);
    ASSERT_TRUE(w.RunUntilCncIdle(60000000000ull));
    InterferometerOptions perfect;
    perfect.linear_um = {0, 1, 0, 0};
    perfect.angular_urad = {0, 1, 0, 0};
    LaserInterferometer laser(&w.machine(), perfect, 1);
    CycleOptions c;
    c.runs = 1;
    c.overrun_mm = 2;
    const double travel[3] = {400, 280, 200};
    for (int a = 0; a < 3; ++a) {
      std::vector<double> pos;
      for (double x = 0; x <= travel[a] + 1e-9; x += 10) pos.push_back(x);
      Expected<ParametricResult> run = MeasureParametric(w, laser, a, {0, 0, 0}, pos, c);
      ASSERT_TRUE(run.ok()) << run.error().message;
      runs_[static_cast<size_t>(a)] = run.value();
    }
    const Expected<model::Model> measured = ModelFromParametric(runs_, datasets::S500Model().chain);
    ASSERT_TRUE(measured.ok()) << measured.error().message;
    measured_ = new model::Model(measured.value());
  }
  static void TearDownTestSuite() { delete measured_; }

  static std::array<ParametricResult, 3> runs_;
  static model::Model* measured_;
};

std::array<ParametricResult, 3> SimTable::runs_;
model::Model* SimTable::measured_ = nullptr;

TEST_F(SimTable, MeasuredModelReproducesTheMachineUpToItsValueAtTheReference) {
  const model::Model truth = datasets::S500Model();
  const model::Vec3 e0 = model::ToolPointError_um(truth, {0, 0, 0});
  Random rng(11);
  double worst = 0;
  for (int i = 0; i < 2000; ++i) {
    const model::Vec3 q = {rng.Uniform(0, 400), rng.Uniform(0, 280), rng.Uniform(0, 200)};
    const model::Vec3 want = model::ToolPointError_um(truth, q) - e0;
    const model::Vec3 got = model::ToolPointError_um(*measured_, q);
    worst = std::max(worst, model::Norm(got - want));
  }
  EXPECT_LT(worst, 0.01) << "um";  // second-order terms only (measured: ~1e-4 um)
}

TEST_F(SimTable, ImageLandsTheToolOnItsTargets) {
  const Expected<TableBuildResult> built = BuildTableImage(
      *measured_, LatticeOptions({0, 0, 0}, {400, 280, 200}, {10, 10, 10}, {1e-3, 1e-3, 1e-3}), 3);
  ASSERT_TRUE(built.ok()) << built.error().message;
  const TableBuildResult& t = *built;
  const Expected<image::LoadedImage> img = image::LoadedImage::FromBytes(t.image, "built");
  ASSERT_TRUE(img.ok()) << img.error().message;
  const Expected<image::ImageEvaluator> evaluator = image::ImageEvaluator::Create(*img);
  ASSERT_TRUE(evaluator.ok()) << evaluator.error().message;
  const image::ImageEvaluator& eval = *evaluator;
  const model::Model truth = datasets::S500Model();
  const model::Vec3 e0 = model::ToolPointError_um(truth, {0, 0, 0});
  Random rng(12);
  double worst = 0, before = 0;
  for (int i = 0; i < 3000; ++i) {
    int32_t pos[3];
    model::Vec3 target;
    for (int a = 0; a < 3; ++a) {
      const double hi = a == 0 ? 400 : a == 1 ? 280 : 200;
      pos[a] = static_cast<int32_t>(std::lround(rng.Uniform(0, hi) * 1000));
      target[a] = pos[a] * 1e-3;
    }
    const bool reverse[3] = {false, false, false};
    int32_t q8[3];
    eval.CorrectionQ8(pos, reverse, q8);
    model::Vec3 q;
    for (int a = 0; a < 3; ++a) q[a] = target[a] + q8[a] / 256.0 * 1e-3;
    // Actual tool point relative to where the machine puts the reference point.
    const model::Vec3 landed = q + 1e-3 * (model::ToolPointError_um(truth, q) - e0);
    worst = std::max(worst, 1e3 * model::Norm(landed - target));
    before = std::max(before, model::Norm(model::ToolPointError_um(truth, target) - e0));
  }
  EXPECT_GT(before, 300);  // the uncompensated machine is off by hundreds of um
  EXPECT_LT(worst, 0.15);  // interpolation (0.09 um predicted) + LSB + measurement
  EXPECT_LT(t.grid->build.interpolation.max_um, 0.15);
}

}  // namespace
}  // namespace volcomp::sim
