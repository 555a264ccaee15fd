// The demo's summary: the figures of every phase, steps and timing, and (worn machine) the goals
// and the error budget.
#include <cstdio>
#include <string>
#include <vector>

#include "volcomp/sim/demo.hpp"

namespace volcomp::sim {
namespace {

double Reduction(double before, double after) {
  return before > 0 ? 100.0 * (1.0 - after / before) : 0.0;
}

// How a row's last column reads: the reduction, or why there is none.
enum class RowKind { kReduce, kNoise, kScatter };

class FigureTable {
 public:
  FigureTable(const DemoResult& r, std::ostream& out) : out_(out) {
    phases_.push_back(&r.before);
    labels_.push_back("before");
    for (const NamedPhase& p : r.intermediate) {
      phases_.push_back(&p.results);
      labels_.push_back(p.label);
    }
    phases_.push_back(&r.after);
    labels_.push_back(r.after_label);
  }

  void Header() {
    std::string h(44, ' ');
    char b[32];
    for (size_t i = 0; i < labels_.size(); ++i) {
      std::snprintf(b, sizeof b, i == 0 ? "%12s" : "%13s", labels_[i].c_str());
      h += b;
    }
    out_ << h << "   reduction\n";
  }

  template <typename Figure>
  void Row(const std::string& label, Figure figure, RowKind kind) {
    char b[64];
    std::snprintf(b, sizeof b, "%-44s", label.c_str());
    std::string line = b;
    for (const PhaseResults* p : phases_) {
      std::snprintf(b, sizeof b, " %9.3f um", figure(*p));
      line += b;
    }
    if (kind == RowKind::kReduce) {
      std::snprintf(b, sizeof b, "   %6.2f %%",
                    Reduction(figure(*phases_.front()), figure(*phases_.back())));
      line += b;
    } else {
      line += kind == RowKind::kNoise ? "   (noise)" : "   (scatter)";
    }
    out_ << line << "\n";
  }

 private:
  std::ostream& out_;
  std::vector<const PhaseResults*> phases_;
  std::vector<std::string> labels_;
};

void PrintFigures(const DemoResult& r, std::ostream& out) {
  const bool worn = r.options.machine == MachineProfile::kWorn;
  // Ideal machine: no backlash and no random positioning error, so R, B and B_d are instrument
  // noise. Worn machine: B and B_d are the lost motion, R the scatter.
  const RowKind reversal = worn ? RowKind::kReduce : RowKind::kNoise;
  const RowKind repeatability = worn ? RowKind::kScatter : RowKind::kNoise;
  FigureTable t(r, out);
  t.Header();
  t.Row(
      "ISO 230-6 E_d (4 body diagonals)", [](const PhaseResults& p) { return p.Ed(); },
      RowKind::kReduce);
  t.Row(
      "ISO 230-6 B_d", [](const PhaseResults& p) { return p.Bd(); }, reversal);
  t.Row(
      "volumetric error, max of " + std::to_string(r.after.points.targets_mm.size()) +
          " points (tracker)",
      [](const PhaseResults& p) { return p.points.max_um; }, RowKind::kReduce);
  t.Row(
      "  rms (tracker)", [](const PhaseResults& p) { return p.points.rms_um; }, RowKind::kReduce);
  t.Row(
      worn ? "  max, machine (no instrument error)" : "  max, machine model (no instrument error)",
      [](const PhaseResults& p) { return p.points.true_max_um; }, RowKind::kReduce);
  for (size_t a = 0; a < 3; ++a) {
    const std::string axis = std::string("GOST 27843 ") + "XYZ"[a];
    t.Row(
        axis + "  A (accuracy)", [a](const PhaseResults& p) { return p.Gost()[a].A; },
        RowKind::kReduce);
    t.Row(
        axis + "  R (repeatability)", [a](const PhaseResults& p) { return p.Gost()[a].R; },
        repeatability);
    t.Row(
        axis + "  B (reversal)", [a](const PhaseResults& p) { return p.Gost()[a].B; }, reversal);
  }
}

void PrintGoals(const DemoResult& r, std::ostream& out) {
  out << "\n== goals of the worn profile =============================================\n";
  char b[300];
  for (const Goal& g : r.goals) {
    const bool percent = g.at_least;
    std::snprintf(b, sizeof b, "%-84s %8.2f %s %s %6.2f %s  %s\n", g.what.c_str(), g.value,
                  percent ? "%" : "um", g.at_least ? ">=" : "<=", g.limit, percent ? "%" : "um",
                  g.holds ? "holds" : "FAILS");
    out << b;
  }
}

void PrintBudget(const DemoResult& r, std::ostream& out) {
  const ErrorBudget& e = r.budget;
  const WornMachineProfile& w = r.options.wear;
  out << "\n== error budget: what remains after the last compensation ================\n";
  char b[400];
  std::snprintf(b, sizeof b,
                "repeatability: GOST 27843 S (uncompensated, pooled over the targets) X %.2f, "
                "Y %.2f, Z %.2f um -> 3 sigma (3-D) %.2f um\n",
                e.sigma_um[0], e.sigma_um[1], e.sigma_um[2], e.three_sigma_um);
  out << b;
  std::snprintf(b, sizeof b,
                "thermal drift at the check point since the tracker lattice was measured "
                "(%.0f s; %.0f s of table changes not covered): (%.2f, %.2f, %.2f) um, |.| "
                "%.2f um\n",
                e.drift_since_table_s, e.unmeasured_s, e.drift_since_table_um.x,
                e.drift_since_table_um.y, e.drift_since_table_um.z,
                model::Norm(e.drift_since_table_um));
  out << b;
  std::snprintf(b, sizeof b, "  of which during the final point test: (%.2f, %.2f, %.2f) um\n",
                e.drift_during_points_um.x, e.drift_during_points_um.y, e.drift_during_points_um.z);
  out << b;
  std::snprintf(
      b, sizeof b,
      "short-period screw error (the machine's, period %.0f mm: not seen at the %.0f/%.0f "
      "mm measuring pitch): amplitude X %.2f, Y %.2f, Z %.2f um\n",
      w.screw_period_mm, r.options.axis_run_pitch_mm, r.options.lattice_spacing_mm,
      e.short_period_um[0], e.short_period_um[1], e.short_period_um[2]);
  out << b;
  std::snprintf(b, sizeof b,
                "the instrument: tracker 3 sigma %.2f um per coordinate (in the tracker figures, "
                "and in every node of the lattice table); laser cosine error %.2f um over the "
                "longest line\n",
                e.tracker_three_sigma_um, e.laser_cosine_um);
  out << b;
  std::snprintf(b, sizeof b,
                "resolution: 1 step = %.2f um\n"
                "limit for the max residual: 3 sigma + |drift| + 1 step = %.2f um (the max "
                "residual, %.2f um, %s it); + the short-period error |A| %.2f um = %.2f um\n",
                e.step_um, e.limit_um, r.after.points.true_max_um,
                r.after.points.true_max_um <= e.limit_um ? "is within" : "exceeds",
                e.short_period_norm_um, e.goal_limit_um);
  out << b;
}

}  // namespace

void PrintSummary(const DemoResult& r, std::ostream& out) {
  const bool worn = r.options.machine == MachineProfile::kWorn;
  char b[256];
  out << "\n== before / after compensation ==========================================\n";
  PrintFigures(r, out);
  if (worn) {
    PrintGoals(r, out);
    PrintBudget(r, out);
  }
  out << "\n== steps, timing, latency, speed =========================================\n";
  std::snprintf(b, sizeof b,
                "input steps %llu, output steps %llu, peak input rate %.3f MHz per axis\n",
                static_cast<unsigned long long>(r.audit.input_steps),
                static_cast<unsigned long long>(r.audit.output_steps), r.peak_input_rate_hz / 1e6);
  out << b;
  std::snprintf(b, sizeof b,
                "lost steps: %llu (drive == CNC steps + correction at %llu rest points; drive == "
                "board output at every one of %llu ticks: %llu mismatches)\n",
                static_cast<unsigned long long>(r.audit.lost_steps),
                static_cast<unsigned long long>(r.audit.rest_checks),
                static_cast<unsigned long long>(r.audit.ticks),
                static_cast<unsigned long long>(r.audit.tick_mismatches));
  out << b;
  std::snprintf(b, sizeof b,
                "pulse timing violations at the drives: %llu; backlog overruns: %u, largest "
                "backlog %u steps\n",
                static_cast<unsigned long long>(r.audit.timing_violations), r.audit.overruns,
                r.audit.max_backlog);
  out << b;
  std::snprintf(b, sizeof b,
                "latency input step -> output step (tick %.0f us, %llu steps): p50 %.2f, p90 "
                "%.2f, p99 %.2f, p99.9 %.2f, max %.3f ticks; > 2 ticks: %llu; unmatched: %llu\n",
                r.tick_us, static_cast<unsigned long long>(r.latency.samples), r.latency.p50_ticks,
                r.latency.p90_ticks, r.latency.p99_ticks, r.latency.p999_ticks, r.latency.max_ticks,
                static_cast<unsigned long long>(r.latency.over_2_ticks),
                static_cast<unsigned long long>(r.latency.unmatched));
  out << b;
  std::snprintf(b, sizeof b,
                "simulator speed: %.1f M steps/s (3 axes at 1 MHz; goal >= 10 M/s); whole demo: "
                "%.1f s of machine time, %.1f M steps in %.1f s wall (%.1f M steps/s)\n",
                r.benchmark.steps_per_s / 1e6, r.virtual_s,
                static_cast<double>(r.audit.input_steps) / 1e6, r.wall_s,
                static_cast<double>(r.audit.input_steps) / r.wall_s / 1e6);
  out << b;
  if (r.failures.empty()) {
    out << (worn ? "\nall checks passed: every goal of the worn profile holds, zero lost steps, "
                   "zero timing violations, latency <= 2 ticks\n"
                 : "\nall checks passed: residual >= 95 % below uncompensated (E_d and random "
                   "points), zero lost steps, zero timing violations, latency <= 2 ticks\n");
  } else {
    out << "\nFAILED:";
    for (const std::string& f : r.failures) out << " " << f << ";";
    out << "\n";
  }
}

}  // namespace volcomp::sim
