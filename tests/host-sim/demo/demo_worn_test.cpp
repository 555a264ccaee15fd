// `volcomp-sim demo --machine worn --quick`: the worn machine's goals, asserted, and what each
// compensation does about each error source, against the simulated machine's own truth.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "circle_fit.hpp"
#include "sanitized_build.hpp"
#include "volcomp/firmware/board_objects.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/sim/demo.hpp"

namespace volcomp::sim {
namespace {

using volcomp::testing::kSanitized;

// `--machine worn --quick` (without the benchmark moves under sanitizers). 50 random points in
// both builds: with 30 the sag check below (the lattice pass lowers the true maximum by 1 um)
// depended on the seed (seeds 1 and 5 of 1-7 failed the worn goals, seed 7 before the two-rate
// tick); with 50, seeds 1-8 pass.
DemoOptions WornQuick() {
  DemoOptions o;
  UseWornMachine(&o);
  o.random_points = 50;
  o.diagonal_targets = 6;
  o.gost_targets = 6;
  o.benchmark_moves = kSanitized ? 0 : 2;
  o.axis_run_pitch_mm = 40;
  return o;
}

double Reduction(double before, double after) { return 100 * (1 - after / before); }

TEST(SimDemo, WornQuickMeetsTheGoals) {
  std::ostringstream log;
  const DemoOptions o = WornQuick();
  const Expected<DemoResult> run = RunDemo(o, log);
  ASSERT_TRUE(run.ok()) << run.error().message;
  const DemoResult& r = run.value();
  EXPECT_TRUE(r.failures.empty()) << log.str();
  ASSERT_EQ(r.intermediate.size(), 2u);
  const PhaseResults& model_only = r.intermediate[0].results;
  const PhaseResults& with_axis = r.intermediate[1].results;
  {
    SCOPED_TRACE("the goals of the worn profile, each checked here from the figures");
    EXPECT_GE(Reduction(r.before.Ed(), r.after.Ed()), 90);
    EXPECT_GE(Reduction(r.before.points.max_um, r.after.points.max_um), 90);
    const auto before = r.before.Gost(), after = r.after.Gost();
    for (size_t a = 0; a < 3; ++a) EXPECT_GE(Reduction(before[a].B, after[a].B), 80) << a;
    const ErrorBudget& b = r.budget;
    EXPECT_LE(r.after.points.true_max_um, b.three_sigma_um + model::Norm(b.drift_since_table_um) +
                                              b.step_um + b.short_period_norm_um);
    // ISO 230-4: G(b) and H each >= 80 % below uncompensated in every plane.
    for (size_t k = 0; k < 3; ++k) {
      const auto& u = r.before.circular.at(k).result;
      const auto& c = r.after.circular.at(k).result;
      EXPECT_GE(Reduction(u.G_b_um, c.G_b_um), 80) << k;
      EXPECT_GE(Reduction(u.H_um, c.H_um), 80) << k;
    }
    // The thermal step (docs/simulator.md 7.6): drift over the verification cycle >= 80 %
    // below table 3 alone on every axis, no change of the correction faster than its slew limit,
    // both injected sensor faults flagged within 2 s with the correction held.
    const ThermalPhase& t = r.thermal;
    ASSERT_TRUE(t.ran);
    EXPECT_GE(t.verification_h, 4);
    for (size_t a = 0; a < 3; ++a) {
      EXPECT_GT(t.drift_before_um[a], 5) << a;  // every axis drifts
      EXPECT_GE(Reduction(t.drift_before_um[a], t.drift_after_um[a]), 80) << a;
      EXPECT_LE(t.compensated.max_rate_um_s[a], t.model.slew_um_s * 1.001) << a;
    }
    ASSERT_EQ(t.compensated.faults.size(), 2u);
    for (const FaultOutcome& f : t.compensated.faults) {
      EXPECT_GE(f.detected_after_s, 0);
      EXPECT_LE(f.detected_after_s, 2);
      EXPECT_EQ(f.change_while_held_um, 0);
    }
    EXPECT_EQ(t.compensated.lost_steps, 0u);
    EXPECT_EQ(t.compensated.overruns, 0u);
    // Twenty goals, every one asserted and holding: the six above, the six ISO 230-4 ones and the
    // eight thermal ones.
    ASSERT_EQ(r.goals.size(), 20u);
    for (size_t i = 0; i < r.goals.size(); ++i) {
      const Goal& g = r.goals[i];
      EXPECT_TRUE(g.asserted) << g.what;
      EXPECT_TRUE(g.holds) << g.what;
      EXPECT_EQ(g.holds, g.value >= g.limit || !g.at_least) << g.what;
    }
    for (size_t k = 0; k < 3; ++k) {
      const auto& u = r.before.circular.at(k).result;
      const auto& c = r.after.circular.at(k).result;
      EXPECT_NEAR(r.goals[6 + 2 * k].value, Reduction(u.G_b_um, c.G_b_um), 1e-9);
      EXPECT_NEAR(r.goals[7 + 2 * k].value, Reduction(u.H_um, c.H_um), 1e-9);
    }
  }
  {
    SCOPED_TRACE("the ISO 230-4 circular tests in every phase");
    const std::vector<const PhaseResults*> phases = {&r.before, &model_only, &with_axis, &r.after};
    for (const PhaseResults* p : phases) {
      ASSERT_EQ(p->circular.size(), 3u);
      const char* planes[] = {"XY", "XZ", "YZ"};
      for (size_t k = 0; k < 3; ++k) {
        const CircularTestResult& t = p->circular[k];
        EXPECT_EQ(t.plane, planes[k]);
        // A reading per degree and direction over the measured 360 degrees.
        EXPECT_GE(t.result.points_cw, 359u);
        EXPECT_GE(t.result.points_ccw, 359u);
        // G(b) of the demo's readings as an evaluation sharing no code with tools/metrology's
        // sees it (a geometric circle fit of both paths: tests/support/circle_fit.hpp).
        const double radius_um = 1e3 * o.circle_radius_mm;
        std::vector<testing::PlanePoint> both =
            testing::PathPoints(t.data.cw.angle_deg, t.data.cw.deviation_um, radius_um);
        const std::vector<testing::PlanePoint> ccw =
            testing::PathPoints(t.data.ccw.angle_deg, t.data.ccw.deviation_um, radius_um);
        both.insert(both.end(), ccw.begin(), ccw.end());
        EXPECT_NEAR(t.result.G_b_um, testing::RadialSpread(both, testing::FitCircle(both)), 0.02)
            << t.plane;
      }
    }
    // The lost motion makes H before (Y's 20 um dead band in XY and YZ, X's 15 um in XZ), the
    // 21-parameter table leaves it, the AXIS1D tables with the direction switch take it out.
    for (size_t k = 0; k < 3; ++k) {
      const double before = r.before.circular[k].result.H_um;
      EXPECT_GT(before, 12.0) << k;
      EXPECT_NEAR(model_only.circular[k].result.H_um, before, 4.0) << k;
      EXPECT_LT(with_axis.circular[k].result.H_um, 0.35 * before) << k;
      EXPECT_LT(r.after.circular[k].result.H_um, 0.35 * before) << k;
      // The geometry: the 21-parameter table removes most of G(b).
      EXPECT_LT(model_only.circular[k].result.G_b_um, 0.7 * r.before.circular[k].result.G_b_um)
          << k;
    }
  }
  {
    SCOPED_TRACE("what each compensation does");
    // Lost motion: before, every axis reverses by about its dead band (15, 20, 8 µm); the
    // 21-parameter table leaves it (it is direction-dependent); the AXIS1D tables take it out.
    const auto before = r.before.Gost(), model = model_only.Gost(), axis = with_axis.Gost();
    for (size_t a = 0; a < 3; ++a) {
      EXPECT_NEAR(before[a].B, o.wear.lost_motion_um[a], 3.0) << a;
      EXPECT_NEAR(model[a].B, o.wear.lost_motion_um[a], 3.0) << a;
      EXPECT_LT(axis[a].B, 0.25 * o.wear.lost_motion_um[a]) << a;
    }
    EXPECT_GT(model_only.Bd(), 15.0);
    EXPECT_LT(with_axis.Bd(), 3.0);
    // The cross-axis sag (12 µm at the front corners) is beyond the 21-parameter model: after
    // 21-param + AXIS1D the residual still holds part of it; the lattice pass takes it out.
    EXPECT_GT(with_axis.points.true_max_um, r.after.points.true_max_um + 1.0);
    // The geometry: hundreds of µm before, tens after the 21-parameter table.
    EXPECT_GT(r.before.Ed(), 300.0);
    EXPECT_LT(model_only.Ed(), 0.1 * r.before.Ed());
  }
  {
    SCOPED_TRACE("tables, budget, the chain");
    EXPECT_EQ(r.earlier_tables.size(), 2u);
    const Expected<image::LoadedImage> last =
        image::LoadedImage::FromBytes(r.table.image, "table 3");
    ASSERT_TRUE(last.ok()) << last.error().message;
    EXPECT_TRUE(last->view().grid.present);
    EXPECT_EQ(last->view().axis1d_count, 3);  // GRID3 and AXIS1D in force together
    EXPECT_EQ(r.activation.active_crc, r.table.crc32);
    EXPECT_NE(r.activation.device_state & canopen::kStateEngaged, 0);
    // Repeatability measured by GOST 27843 before compensation: the machine's scatter
    // (0.7, 0.8, 0.6 µm), within what 6 targets x 10 approaches can estimate.
    for (size_t a = 0; a < 3; ++a) {
      EXPECT_NEAR(r.budget.sigma_um[a], o.wear.scatter_sigma_um[a],
                  0.3 * o.wear.scatter_sigma_um[a])
          << a;
    }
    EXPECT_GT(r.drift.size(), 20u);
    EXPECT_EQ(r.audit.lost_steps, 0u);
    EXPECT_EQ(r.audit.tick_mismatches, 0u);
    EXPECT_EQ(r.audit.timing_violations, 0u);
    EXPECT_EQ(r.latency.unmatched, 0u);
    EXPECT_LE(r.latency.max_ticks, 2.0);
  }
}

}  // namespace
}  // namespace volcomp::sim
