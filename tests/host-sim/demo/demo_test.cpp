// `volcomp-sim demo` end to end: the figures the issue asks for, asserted on the default demo run
// (README Quick start command 1; a smaller run with the same code path under sanitizers), and
// checked against references computed here directly from the machine model, without the
// simulation. One test case per demo run, because ctest runs every case in its own process.
#include "volcomp/sim/demo.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "sanitized_build.hpp"
#include "volcomp/datasets/s500.hpp"
#include "volcomp/firmware/board_objects.hpp"
#include "volcomp/image/image_reader.hpp"

namespace volcomp::sim {
namespace {

using volcomp::testing::kSanitized;

DemoOptions TestOptions() {
  DemoOptions o;  // the default demo
  if (kSanitized) {
    o.random_points = 40;
    o.gost_targets = 6;
    o.diagonal_targets = 6;
    o.benchmark_moves = 2;
  }
  return o;
}

void CheckReductions(const DemoResult& r) {
  // ISO 230-6 E_d: the S500 is hundreds of um off along its body diagonals.
  EXPECT_GT(r.before.Ed(), 100.0);
  EXPECT_LE(r.after.Ed(), 0.05 * r.before.Ed());
  EXPECT_EQ(r.after.diagonals.evaluation.diagonals.size(), 4u);
  // Max volumetric error over the random points (tracker).
  EXPECT_GT(r.before.points.max_um, 100.0);
  EXPECT_LE(r.after.points.max_um, 0.05 * r.before.points.max_um);
  // Without the tracker's noise the residual is within one step (1 um) of resolution.
  EXPECT_LE(r.after.points.true_max_um, 1.0);
  // GOST 27843 accuracy on every axis: down to quantisation plus instrument noise.
  const auto before = r.before.Gost(), after = r.after.Gost();
  for (size_t a = 0; a < 3; ++a) {
    EXPECT_GT(before[a].A, 5.0) << a;
    EXPECT_LT(after[a].A, 2.0) << a;
  }
}

void CheckSteps(const DemoResult& r) {
  const StepAudit& a = r.audit;
  EXPECT_GT(a.rest_checks, 300u);
  EXPECT_EQ(a.lost_steps, 0u);
  EXPECT_EQ(a.owed_at_rest, 0u);
  EXPECT_EQ(a.tick_mismatches, 0u);
  EXPECT_EQ(a.timing_violations, 0u);
  EXPECT_EQ(a.overruns, 0u);
  EXPECT_GT(a.input_steps, 10000000u);
  EXPECT_NEAR(r.peak_input_rate_hz, 1e6, 1);  // the CNC did run axes at 1 MHz
  // Latency at the default 50 kHz tick, every input step matched to its output step.
  EXPECT_DOUBLE_EQ(r.tick_us, 20.0);
  EXPECT_EQ(r.latency.samples, a.input_steps);
  EXPECT_EQ(r.latency.unmatched, 0u);
  EXPECT_EQ(r.latency.over_2_ticks, 0u);
  EXPECT_LE(r.latency.max_ticks, 2.0);
}

void CheckUpload(const DemoResult& r) {
  EXPECT_EQ(r.upload.bytes, r.table.image.size());
  EXPECT_EQ(r.upload.staged_crc, r.table.crc32);
  EXPECT_EQ(r.activation.active_crc, r.table.crc32);
  EXPECT_NE(r.activation.device_state & canopen::kStateEngaged, 0);
  EXPECT_TRUE(r.reference_agrees);
  // 1 Mbit/s: a block transfer cannot beat ~60 kB/s; this one is far from a stall.
  EXPECT_GT(r.upload.rate_bytes_s, 40000.0);
  EXPECT_LT(r.upload.rate_bytes_s, 66000.0);
}

// Before compensation the drives sit exactly on the commanded steps, so E_i is max - min over the
// targets of e(target) projected on the diagonal (the datum cancels).
void CheckDiagonalsAgainstTheModel(const DemoResult& r) {
  const model::Model s500 = datasets::S500Model();
  ASSERT_EQ(r.before.diagonals.programs.size(), r.before.diagonals.evaluation.diagonals.size());
  for (size_t i = 0; i < r.before.diagonals.programs.size(); ++i) {
    const TestProgram& p = r.before.diagonals.programs[i];
    double hi = -1e9, lo = 1e9;
    for (const MeasuredStop& s : p.stops) {
      if (s.datum) continue;
      model::Vec3 q;
      for (int a = 0; a < 3; ++a) {
        q[a] = std::round(s.point_mm[static_cast<size_t>(a)] * 1e3) / 1e3;
      }
      const model::Vec3 e = model::ToolPointError_um(s500, q);
      const double dev = e.x * p.direction[0] + e.y * p.direction[1] + e.z * p.direction[2];
      hi = std::max(hi, dev);
      lo = std::min(lo, dev);
    }
    const metrology::DiagonalResult& d = r.before.diagonals.evaluation.diagonals[i];
    EXPECT_EQ(d.name.text, p.name);
    EXPECT_NEAR(d.E.value, hi - lo, 0.2) << p.name;  // instrument noise only
  }
}

// Uncompensated: e(T) - e(reference point); compensated: the uploaded image looked up with the
// firmware's code (ImageEvaluator), rounded half up to whole steps like the board's output, and
// the model at that drive position. The simulated chain must put the axes exactly there.
void CheckPointsAgainstTheModel(const DemoResult& r, int points) {
  const model::Model s500 = datasets::S500Model();
  const model::Vec3 e0 = model::ToolPointError_um(s500, {0, 0, 0});
  ASSERT_EQ(r.before.points.targets_mm.size(), static_cast<size_t>(points));
  ASSERT_EQ(r.after.points.targets_mm.size(), static_cast<size_t>(points));
  const Expected<image::LoadedImage> img =
      image::LoadedImage::FromBytes(r.table.image, "demo table");
  ASSERT_TRUE(img.ok()) << img.error().message;
  const Expected<image::ImageEvaluator> evaluator = image::ImageEvaluator::Create(*img);
  ASSERT_TRUE(evaluator.ok()) << evaluator.error().message;
  const image::ImageEvaluator& eval = *evaluator;
  double worst = 0;
  for (size_t i = 0; i < static_cast<size_t>(points); ++i) {
    int32_t pos[3], q8[3];
    model::Vec3 target, q;
    for (int a = 0; a < 3; ++a) {
      pos[a] = static_cast<int32_t>(
          std::lround(r.after.points.targets_mm[i][static_cast<size_t>(a)] * 1e3));
      target[a] = pos[a] * 1e-3;
    }
    const model::Vec3 before = model::ToolPointError_um(s500, target) - e0;
    EXPECT_LT(model::Norm(r.before.points.true_error_um[i] - before), 1e-6) << i;
    const bool reverse[3] = {false, false, false};
    eval.CorrectionQ8(pos, reverse, q8);
    for (int a = 0; a < 3; ++a) q[a] = (pos[a] + ((q8[a] + 128) >> 8)) * 1e-3;
    const model::Vec3 after = 1e3 * (q - target) + (model::ToolPointError_um(s500, q) - e0);
    EXPECT_LT(model::Norm(r.after.points.true_error_um[i] - after), 1e-6) << i;
    worst = std::max(worst, model::Norm(after));
  }
  EXPECT_LE(worst, 1.0);  // within one step of resolution
}

TEST(SimDemo, DefaultRunShowsTheIssueFigures) {
  std::ostringstream log;
  const DemoOptions o = TestOptions();
  const Expected<DemoResult> run = RunDemo(o, log);
  ASSERT_TRUE(run.ok()) << run.error().message;
  const DemoResult& r = run.value();
  EXPECT_TRUE(r.failures.empty()) << log.str();
  {
    SCOPED_TRACE("residual after compensation");
    CheckReductions(r);
  }
  {
    SCOPED_TRACE("steps, timing, latency");
    CheckSteps(r);
  }
  {
    SCOPED_TRACE("upload and activation");
    CheckUpload(r);
  }
  {
    SCOPED_TRACE("diagonals against the model");
    CheckDiagonalsAgainstTheModel(r);
  }
  {
    SCOPED_TRACE("points against the model and the image");
    CheckPointsAgainstTheModel(r, o.random_points);
  }
}

// A model file that cannot be read ends the run before it starts, as a failure naming the file
// (kIoError: the file, not its contents).
TEST(SimDemo, AModelFileThatCannotBeReadIsAFailure) {
  DemoOptions o;
  o.model_spec = "/nonexistent/machine.conf";
  std::ostringstream log;
  const Expected<DemoResult> run = RunDemo(o, log);
  ASSERT_FALSE(run.ok());
  EXPECT_EQ(run.error().code, Error::kIoError);
  EXPECT_EQ(run.error().message.rfind("/nonexistent/machine.conf: ", 0), 0u) << run.error().message;
  EXPECT_EQ(log.str(), "");
}

// A reduced run (2 approaches, few targets and points), twice: same seed, same figures.
TEST(SimDemo, SameSeedSameFigures) {
  DemoOptions o;
  o.random_points = 10;
  o.gost_targets = 4;
  o.gost_runs = 2;
  o.diagonal_targets = 4;
  o.diagonal_runs = 2;
  o.parametric_step_mm = 40;
  o.benchmark_moves = 0;
  std::ostringstream l1, l2;
  const Expected<DemoResult> ra = RunDemo(o, l1);
  const Expected<DemoResult> rb = RunDemo(o, l2);
  ASSERT_TRUE(ra.ok() && rb.ok());
  const DemoResult& a = ra.value();
  const DemoResult& b = rb.value();
  EXPECT_EQ(a.before.Ed(), b.before.Ed());
  EXPECT_EQ(a.after.Ed(), b.after.Ed());
  EXPECT_EQ(a.before.points.max_um, b.before.points.max_um);
  EXPECT_EQ(a.after.points.max_um, b.after.points.max_um);
  EXPECT_EQ(a.after.Gost()[1].A, b.after.Gost()[1].A);
  EXPECT_EQ(a.table.crc32, b.table.crc32);
  EXPECT_EQ(a.audit.input_steps, b.audit.input_steps);
  EXPECT_EQ(a.latency.max_ticks, b.latency.max_ticks);
  EXPECT_EQ(a.latency.p50_ticks, b.latency.p50_ticks);
}

}  // namespace
}  // namespace volcomp::sim
