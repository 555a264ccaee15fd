// The worn machine's steps of `volcomp-sim demo`: drift checks, the ISO 230-2 runs and their
// AXIS1D tables, the tracker lattice and its GRID3, the error budget and the goals.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "demo_session.hpp"

namespace volcomp::sim::demo {

Outcome CheckDrift(Session& s, DemoResult& r, const std::string& after) {
  // Three approaches, each from 5 mm below on every axis (by input motion, so the lost motion is
  // taken up the same way whatever moved before), averaging the settling scatter.
  const Point3 cp = s.check_point;
  const TestProgram p = PointSetProgram("drift check", {cp, cp, cp}, s.o.dwell_s, 5);
  VOLCOMP_TRY_ASSIGN(const std::vector<StopState> stops, RunTestProgram(s.world, p));
  if (r.drift.empty()) s.drift_tracker.Zero(stops[0].q_mm, stops[0].cmd_mm);
  model::Vec3 sum;
  int n = 0;
  for (size_t k = 0; k < stops.size(); ++k) {
    for (int i = 0; i < std::max(1, s.o.drift_readings); ++i, ++n) {
      sum += s.drift_tracker.Measure_mm(stops[k].q_mm) - stops[k].cmd_mm;
    }
  }
  DriftCheck c;
  c.after = after;
  c.time_s = s.world.machine().time_s();
  c.epoch = s.epoch;
  c.reading_um = (1e3 / n) * sum;
  r.drift.push_back(c);
  return Outcome::Ok();
}

model::Vec3 DriftBetween(
    const std::vector<DriftCheck>& checks, size_t from, size_t to, double* span_s, double* gap_s) {
  model::Vec3 d;
  *span_s = *gap_s = 0;
  for (size_t i = from; i < to && i + 1 < checks.size(); ++i) {
    const double dt = checks[i + 1].time_s - checks[i].time_s;
    if (checks[i + 1].epoch == checks[i].epoch) {
      d += checks[i + 1].reading_um - checks[i].reading_um;
      *span_s += dt;
    } else {
      *gap_s += dt;
    }
  }
  return d;
}

void PrintWarmUp(Session& s) {
  const WornMachineProfile& w = s.world.machine().wear();
  if (!w.thermal) return;
  const double x = s.check_point[0];
  const double z0 = ThermalGrowth::SpindleZ_um(w, 0), z1 = ThermalGrowth::SpindleZ_um(w, 60);
  const double x0 = ThermalGrowth::XScrew_um(w, x, 0), x1 = ThermalGrowth::XScrew_um(w, x, 60);
  char b[300];
  std::snprintf(b, sizeof b,
                "warm-up: %.0f min of running before the demo (not simulated step by step: only "
                "the thermal state): spindle grown %.1f um, drifting %.1f um/h toward the table; "
                "X screw ahead by %.1f um at X %.0f mm, drifting %.1f um/h",
                w.warmup_min, -z0, -60 * (z1 - z0), x0, x, 60 * (x1 - x0));
  s.progress.Line(b);
}

namespace {

// Targets at whole multiples of `pitch` inside [lo, hi].
std::vector<double> PitchTargets(double lo, double hi, double pitch) {
  std::vector<double> t;
  for (double p = std::ceil(lo / pitch - 1e-9) * pitch; p <= hi + 1e-9; p += pitch) {
    t.push_back(std::round(p * 1e6) / 1e6);
  }
  return t;
}

}  // namespace

Expected<std::vector<builders::AxisSection>> MeasureAxisTables(Session& s, DemoResult& r) {
  std::vector<builders::AxisSection> tables;
  const double quarter_lead = 0.25 * s.o.gost_pitch_mm;
  for (int a = 0; a < 3; ++a) {
    const size_t i = static_cast<size_t>(a);
    const auto t0 = Clock::now();
    // Each node t measured at t ∓ P/4 (half a lead apart): the mean of the pair cancels the
    // screw's once-per-revolution error, which a table at this pitch cannot hold and would
    // otherwise pick up at whatever phase the node happens to sample.
    const std::vector<double> nodes =
        PitchTargets(s.layout.inner_lo[i] + quarter_lead, s.layout.inner_hi[i] - quarter_lead,
                     s.o.axis_run_pitch_mm);
    GostPlan plan;
    for (double t : nodes) {
      plan.targets_mm.push_back(t - quarter_lead);
      plan.targets_mm.push_back(t + quarter_lead);
    }
    plan.line_point_mm = s.layout.centre;
    plan.cycle.runs = s.o.gost_runs;
    plan.cycle.dwell_s = s.o.dwell_s;
    plan.cycle.feed_mm_s = s.o.test_feed_mm_s;
    VOLCOMP_TRY_ASSIGN(r.axis_runs[i], MeasureGostAxis(s.world, s.laser, a, plan));
    VOLCOMP_TRY(CheckDrift(s, r, std::string("ISO 230-2 run ") + "XYZ"[a]));
    // `volcomp build axis --reverse tables` on the pairs' mean deviations x̄↑, x̄↓.
    VOLCOMP_TRY_ASSIGN(builders::AxisSection table,
                       BuildAxisTable(PairMeans(MeanDeviations(r.axis_runs[i].iso)), a,
                                      s.o.axis_run_pitch_mm, s.step_mm()));
    tables.push_back(std::move(table));
    const builders::Axis1dTable& t = tables.back().table;
    double largest = 0;
    for (double f : t.forward)
      largest = std::max({largest, std::fabs(f), std::fabs(f + t.backlash)});
    char b[300];
    std::snprintf(b, sizeof b,
                  "%c: %zu nodes every %.0f mm, each at +-%.2f mm, %d runs each way (table 1 "
                  "active): AXIS1D forward table and backlash %.2f um (the mean reversal), "
                  "largest correction %.2f um   (%.1f s)",
                  "XYZ"[a], nodes.size(), s.o.axis_run_pitch_mm, quarter_lead, s.o.gost_runs,
                  t.backlash, largest, Since(t0));
    s.progress.Line(b);
  }
  return tables;
}

Expected<builders::GridSection> MeasureTrackerLattice(Session& s,
                                                      DemoResult& r,
                                                      const std::vector<uint8_t>& in_force) {
  const auto t0 = Clock::now();
  const double machine_t0 = s.world.machine().time_s();
  const double h = s.o.lattice_spacing_mm;
  model::TrackerLatticeData& data = r.lattice;
  data.name = "volcomp-sim demo: tracker lattice";
  // Each node u is read at u ∓ P/4 on every axis (half a lead apart) and the pair averaged, as
  // for the AXIS1D runs. Both readings stay inside the travel, where table 2 corrects (beyond it
  // the table holds its edge values and the pair would not average to the node): the nodes run
  // from P/4 inside one end to at most P/4 inside the other, at the largest whole-µm spacing that
  // needs no more intervals than `lattice_spacing_mm` would. The grid over the whole travel
  // extends the outer cells by those last millimetres.
  const double q = 0.25 * s.o.gost_pitch_mm;
  for (size_t a = 0; a < 3; ++a) {
    const double span = s.layout.hi[a] - s.layout.lo[a] - 2 * q;
    const double cells = std::ceil(span / h - 1e-9);
    const double spacing = std::floor(span / cells * 1e3 + 1e-6) / 1e3;
    data.lattice[a] = {s.layout.lo[a] + q, spacing, static_cast<uint32_t>(cells) + 1};
  }
  const model::GridAxes& g = data.lattice;
  // Serpentine order (short moves), the reference point first as the tracker's datum.
  std::vector<Point3> points = {s.layout.reference};
  std::vector<size_t> index;
  for (uint32_t k = 0; k < g[2].nodes; ++k) {
    for (uint32_t jj = 0; jj < g[1].nodes; ++jj) {
      const uint32_t j = k % 2 == 0 ? jj : g[1].nodes - 1 - jj;
      for (uint32_t ii = 0; ii < g[0].nodes; ++ii) {
        const uint32_t i = (k * g[1].nodes + jj) % 2 == 0 ? ii : g[0].nodes - 1 - ii;
        const Point3 u = {g[0].origin_mm + i * g[0].spacing_mm,
                          g[1].origin_mm + j * g[1].spacing_mm,
                          g[2].origin_mm + k * g[2].spacing_mm};
        points.push_back({u[0] - q, u[1] - q, u[2] - q});
        points.push_back({u[0] + q, u[1] + q, u[2] + q});
        index.push_back((static_cast<size_t>(k) * g[1].nodes + j) * g[0].nodes + i);
      }
    }
  }
  // Every node approached from 2 mm below on every axis: the input of each axis moves positive
  // into the node, so the board's AXIS1D direction and the lost motion of the carriages agree
  // even where table 2's GRID3 moves an axis whose input stands still (docs/simulator.md §6).
  VOLCOMP_TRY_ASSIGN(const PointSetResult ps,
                     MeasurePointSet(s.world, s.tracker, points, s.o.dwell_s, 2.0));
  VOLCOMP_TRY(CheckDrift(s, r, "tracker lattice"));
  data.position_mm.assign(index.size(), model::Vec3{});
  for (size_t n = 0; n < index.size(); ++n) {
    const Point3& a = ps.targets_mm[2 * n];
    const Point3& b = ps.targets_mm[2 * n + 1];
    const model::Vec3 node = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])};
    data.position_mm[index[n]] =
        node + 0.5e-3 * (ps.measured_error_um[2 * n] + ps.measured_error_um[2 * n + 1]);
  }
  const double gs = s.o.grid_spacing_mm;
  // `volcomp build tracker --lattice FILE --through TABLE2` on these readings.
  VOLCOMP_TRY_ASSIGN(
      builders::GridSection grid,
      BuildTrackerLatticeGridSection(
          data, in_force, LatticeOptions(s.layout.lo, s.layout.hi, {gs, gs, gs}, s.step_mm())));
  const model::GridAxes& gg = grid.build.grid.axes;
  char b[400];
  std::snprintf(b, sizeof b,
                "%ux%ux%u nodes every ~%.0f mm (%zu readings in pairs, %.0f s of machine time); "
                "inverse "
                "GRID3 (as `volcomp build tracker --lattice --through`): %ux%ux%u nodes every "
                "%.0f mm, "
                "largest correction %.1f um, predicted interpolation error %.3f um max   (%.1f s)",
                g[0].nodes, g[1].nodes, g[2].nodes, g[0].spacing_mm, ps.targets_mm.size(),
                s.world.machine().time_s() - machine_t0, gg[0].nodes, gg[1].nodes, gg[2].nodes,
                gg[0].spacing_mm, grid.build.stats.max_correction_um,
                grid.build.interpolation.max_um, Since(t0));
  s.progress.Line(b);
  return grid;
}

void AddGoal(DemoResult& r,
             const std::string& what,
             double value,
             double limit,
             bool at_least,
             bool asserted,
             const std::string& unit) {
  Goal g;
  g.unit = unit;
  g.what = what;
  g.value = value;
  g.limit = limit;
  g.at_least = at_least;
  g.holds = at_least ? value >= limit : value <= limit;
  g.asserted = asserted;
  r.goals.push_back(g);
  if (!g.holds && asserted) r.failures.push_back("goal: " + what);
}

namespace {

double Reduction(double before, double after) {
  return before > 0 ? 100.0 * (1.0 - after / before) : 0.0;
}

}  // namespace

void EvaluateWornGoals(Session& s, DemoResult& r, size_t first_check_of_last_table) {
  ErrorBudget& b = r.budget;
  // σ of each axis pooled over its targets and directions (the largest of a dozen 5-sample
  // estimates would overstate it by half).
  double sum2 = 0;
  for (size_t a = 0; a < 3; ++a) {
    double s2 = 0;
    int n = 0;
    for (const metrology::PositionStats& p : r.before.gost[a].gost.positions) {
      for (const auto& d : {p.up, p.down}) {
        if (d) {
          s2 += d->s * d->s;
          ++n;
        }
      }
    }
    b.sigma_um[a] = n > 0 ? std::sqrt(s2 / n) : 0;
    sum2 += b.sigma_um[a] * b.sigma_um[a];
  }
  b.three_sigma_um = 3 * std::sqrt(sum2);
  const size_t last = r.drift.size() - 1;
  b.drift_since_table_um = DriftBetween(r.drift, first_check_of_last_table, last,
                                        &b.drift_since_table_s, &b.unmeasured_s);
  double span = 0, gap = 0;
  b.drift_during_points_um = DriftBetween(r.drift, last - 1, last, &span, &gap);
  const WornMachineProfile& w = s.world.machine().wear();
  if (w.screw_error) b.short_period_um = w.screw_amplitude_um;
  const ChannelErrors& t = s.o.tracker.coordinate_um;
  b.tracker_three_sigma_um =
      3 * std::sqrt(t.noise * t.noise / std::max(1, t.samples) + t.repeatability * t.repeatability);
  double longest = 0;
  for (size_t a = 0; a < 3; ++a) {
    const double d = s.layout.inner_hi[a] - s.layout.inner_lo[a];
    longest += d * d;
  }
  b.laser_cosine_um = 1e3 * std::sqrt(longest) * (1 - std::cos(1e-3 * s.o.laser.misalignment_mrad));
  b.step_um = 1e3 * s.world.machine().step_mm(0);
  b.limit_um = b.three_sigma_um + model::Norm(b.drift_since_table_um) + b.step_um;
  // The short-period screw error is below every measuring pitch, so it stays at every point;
  // 3σ + drift + 1 step has no term for it (docs/simulator.md, "Goals").
  b.short_period_norm_um = std::sqrt(b.short_period_um[0] * b.short_period_um[0] +
                                     b.short_period_um[1] * b.short_period_um[1] +
                                     b.short_period_um[2] * b.short_period_um[2]);
  b.goal_limit_um = b.limit_um + b.short_period_norm_um;

  AddGoal(r, "ISO 230-6 E_d >= 90 % below uncompensated", Reduction(r.before.Ed(), r.after.Ed()),
          90, true);
  AddGoal(r, "max volumetric error (tracker) >= 90 % below uncompensated",
          Reduction(r.before.points.max_um, r.after.points.max_um), 90, true);
  const auto gb = r.before.Gost(), ga = r.after.Gost();
  for (size_t a = 0; a < 3; ++a) {
    AddGoal(r, std::string("GOST 27843 ") + "XYZ"[a] + " B (reversal) >= 80 % below uncompensated",
            Reduction(gb[a].B, ga[a].B), 80, true);
  }
  AddGoal(r,
          "max residual at the points (machine, no instrument error) <= 3 sigma + drift + 1 "
          "step + short-period",
          r.after.points.true_max_um, b.goal_limit_um, false);
  // ISO 230-4 (issue 28): G(b) and H each >= 80 % below uncompensated in every plane. What
  // remains is mostly the short-period screw error and the settling scatter at the circle's
  // reversals (docs/simulator.md 8.1).
  for (size_t k = 0; k < r.before.circular.size() && k < r.after.circular.size(); ++k) {
    const CircularTestResult& u = r.before.circular[k];
    const CircularTestResult& c = r.after.circular[k];
    AddGoal(r, "ISO 230-4 " + u.plane + " G(b) (ballbar) >= 80 % below uncompensated",
            Reduction(u.result.G_b_um, c.result.G_b_um), 80, true);
    AddGoal(r, "ISO 230-4 " + u.plane + " H (ballbar) >= 80 % below uncompensated",
            Reduction(u.result.H_um, c.result.H_um), 80, true);
  }
}

}  // namespace volcomp::sim::demo
