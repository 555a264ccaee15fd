// End to end: builders → BuildImage → the firmware's own lookup code (ImageEvaluator) → the model
// as the machine. This is the predicted residual of compensating the S500 with its own table.
#include "volcomp/builders/image_glue.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>

#include "expected_value.hpp"
#include "volcomp/builders/axis1d.hpp"
#include "volcomp/builders/grid.hpp"
#include "volcomp/datasets/s500.hpp"
#include "volcomp/image/image_builder.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/model/rigid_body.hpp"

namespace volcomp::builders {
namespace {

using model::Model;
using model::PositioningData;
using model::Vec3;
using testing::ValueOf;

std::vector<image::AxisDef> Axes(uint32_t pm_per_step) {
  std::vector<image::AxisDef> axes(3);
  for (int a = 0; a < 3; ++a) {
    axes[static_cast<std::size_t>(a)].name = "XYZ"[a];
    axes[static_cast<std::size_t>(a)].resolution_e9 = pm_per_step;
  }
  return axes;
}

struct Residuals {
  double uncompensated_max_um = 0, compensated_max_um = 0, compensated_rms_um = 0;
};

// Random targets on whole steps; command = target + table correction (exact Q8 value, as the
// board's target before step rounding); residual = where the model puts the tool − target.
Residuals Evaluate(const Model& m, const std::vector<uint8_t>& bytes, double mm_per_step) {
  const image::LoadedImage img = ValueOf(image::LoadedImage::FromBytes(bytes, "test"));
  const image::ImageEvaluator eval = ValueOf(image::ImageEvaluator::Create(img));
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int32_t> ux(0, 400000), uy(0, 280000), uz(0, 200000);
  Residuals r;
  double sum_sq = 0;
  const int n = 3000;
  for (int i = 0; i < n; ++i) {
    const int32_t pos[3] = {static_cast<int32_t>(ux(rng) * (0.001 / mm_per_step)),
                            static_cast<int32_t>(uy(rng) * (0.001 / mm_per_step)),
                            static_cast<int32_t>(uz(rng) * (0.001 / mm_per_step))};
    const bool rev[3] = {false, false, false};
    int32_t q8[3];
    eval.CorrectionQ8(pos, rev, q8);
    const Vec3 target = {pos[0] * mm_per_step, pos[1] * mm_per_step, pos[2] * mm_per_step};
    const Vec3 command = {(pos[0] + q8[0] / 256.0) * mm_per_step,
                          (pos[1] + q8[1] / 256.0) * mm_per_step,
                          (pos[2] + q8[2] / 256.0) * mm_per_step};
    const double before = Norm(ToolPointError_um(m, target));
    const double after = Norm(command + 1e-3 * ToolPointError_um(m, command) - target) * 1e3;
    r.uncompensated_max_um = std::fmax(r.uncompensated_max_um, before);
    r.compensated_max_um = std::fmax(r.compensated_max_um, after);
    sum_sq += after * after;
  }
  r.compensated_rms_um = std::sqrt(sum_sq / n);
  return r;
}

TEST(builders_image_glue, S500GridThroughTheFirmwareLookup) {
  const Model m = datasets::S500Model();
  const InverseMap inverse = [&m](const Vec3& t) -> Expected<Vec3> {
    return SolveCommand(m, t).command_mm;
  };
  GridBuildOptions o;
  o.max_mm = {400, 280, 200};
  o.natural_spacing_mm = {20, 10, 10};
  o.step_mm = {0.001, 0.001, 0.001};
  const GridBuildResult g = ValueOf(BuildCorrectionGrid(o, inverse));
  image::ImageRequest req;
  req.axes = Axes(1000000);  // 1 µm per step
  req.grid = ValueOf(ToGridCorrections(g.grid, req.axes));
  const std::vector<uint8_t> bytes = ValueOf(image::BuildImage(req));
  const Residuals r = Evaluate(m, bytes, 0.001);
  // The S500 errors reach ~460 µm; with the table the residual is the predicted interpolation
  // error plus the element quantisation (int16 with 6 fraction bits: 1/64 µm).
  EXPECT_GT(r.uncompensated_max_um, 400);
  EXPECT_LT(r.compensated_max_um, g.interpolation.max_um + 0.05);
  EXPECT_LT(r.compensated_max_um, 0.2);
  EXPECT_LT(r.compensated_rms_um, 0.05);
  std::printf(
      "S500, 20/10/10 mm grid, 1 um/step: uncompensated max %.1f um, compensated max "
      "%.4f um, rms %.4f um (predicted interpolation max %.4f um)\n",
      r.uncompensated_max_um, r.compensated_max_um, r.compensated_rms_um, g.interpolation.max_um);
}

TEST(builders_image_glue, AxisTablesThroughTheFirmwareLookup) {
  // dev↑ = 5 µm + 20 µm/m·p, dev↓ = dev↑ − 3 µm, on 0..100 mm: forward and reverse tables.
  PositioningData d;
  for (int i = 0; i <= 10; ++i) {
    d.position.push_back(10.0 * i);
    d.dev_forward.push_back(5 + 0.02 * 10.0 * i);
    d.dev_reverse.push_back(2 + 0.02 * 10.0 * i);
  }
  Axis1dOptions o;
  o.unit_per_step = 0.0005;
  const Axis1dTable t = ValueOf(BuildAxis1d(d, o));
  image::ImageRequest req;
  image::AxisDef x;
  x.resolution_e9 = 500000;  // 0.5 µm per step
  req.axes = {x};
  req.axis_tables.push_back(ValueOf(ToAxisCorrections(t, 0, x, false, false)));
  const image::LoadedImage img =
      ValueOf(image::LoadedImage::FromBytes(ValueOf(image::BuildImage(req)), "axis"));
  const image::ImageEvaluator eval = ValueOf(image::ImageEvaluator::Create(img));
  for (int32_t p : {0, 20000, 100000, 150000, 200000}) {  // 0, 10, 50, 75, 100 mm
    for (bool rev : {false, true}) {
      int32_t q8;
      eval.CorrectionQ8(&p, &rev, &q8);
      const double target = p * 0.0005;
      const double command = (p + q8 / 256.0) * 0.0005;
      const double dev_um = (rev ? 2 : 5) + 0.02 * command;
      EXPECT_NEAR((command + dev_um * 1e-3 - target) * 1e3, 0.0, 0.5 * 0.0005e3 / 256 + 1e-6)
          << p << (rev ? " reverse" : " forward");
    }
  }
}

}  // namespace
}  // namespace volcomp::builders
