// The demo's summary: the figures of every phase, steps and timing, and (worn machine) the goals
// and the error budget. SummaryData builds one document with every figure; the text is printed
// from that document only (and --report writes it as summary.json), so the text cannot show a
// figure the JSON lacks.
#include <cctype>
#include <cstdio>
#include <string>
#include <vector>

#include "demo_session.hpp"
#include "summary_document.hpp"
#include "volcomp/metrology/circular_report.hpp"
#include "volcomp/sim/demo.hpp"

namespace volcomp::sim {
namespace {

using demo::Fmt;
using summary_document::At;
using summary_document::Num;
using tools::JsonValue;

double Reduction(double before, double after) {
  return before > 0 ? 100.0 * (1.0 - after / before) : 0.0;
}

std::string Hex32(uint32_t v) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%08X", v);
  return b;
}

JsonValue Vec(const model::Vec3& v) { return JsonValue::Array().Push(v.x).Push(v.y).Push(v.z); }
JsonValue Vec(const std::array<double, 3>& v) {
  return JsonValue::Array().Push(v[0]).Push(v[1]).Push(v[2]);
}

// How a row's last column reads: the reduction, or why there is none.
enum class RowKind { kReduce, kNoise, kScatter };

class FigureRows {
 public:
  explicit FigureRows(const DemoResult& r) {
    phases_.push_back(&r.before);
    for (const NamedPhase& p : r.intermediate) phases_.push_back(&p.results);
    phases_.push_back(&r.after);
  }

  template <typename Figure>
  void Row(const std::string& key, const std::string& name, Figure figure, RowKind kind) {
    JsonValue row = JsonValue::Object();
    row.Set("key", key).Set("name", name).Set("unit", "um");
    JsonValue values = JsonValue::Array();
    for (const PhaseResults* p : phases_) values.Push(figure(*p));
    row.Set("values", std::move(values));
    if (kind == RowKind::kReduce) {
      row.Set("reduction_pct", Reduction(figure(*phases_.front()), figure(*phases_.back())));
    } else {
      row.Set("reduction_pct", JsonValue());
      row.Set("note", kind == RowKind::kNoise ? "noise" : "scatter");
    }
    rows_.Push(std::move(row));
  }

  JsonValue Take() { return std::move(rows_); }

 private:
  std::vector<const PhaseResults*> phases_;
  JsonValue rows_ = JsonValue::Array();
};

JsonValue Figures(const DemoResult& r) {
  const bool worn = r.options.machine == MachineProfile::kWorn;
  // Ideal machine: no backlash and no random positioning error, so R, B and B_d are instrument
  // noise. Worn machine: B and B_d are the lost motion, R the scatter.
  const RowKind reversal = worn ? RowKind::kReduce : RowKind::kNoise;
  const RowKind repeatability = worn ? RowKind::kScatter : RowKind::kNoise;
  FigureRows t(r);
  t.Row(
      "ed", "ISO 230-6 E_d (4 body diagonals)", [](const PhaseResults& p) { return p.Ed(); },
      RowKind::kReduce);
  t.Row(
      "bd", "ISO 230-6 B_d", [](const PhaseResults& p) { return p.Bd(); }, reversal);
  t.Row(
      "points_max",
      "volumetric error, max of " + std::to_string(r.after.points.targets_mm.size()) +
          " points (tracker)",
      [](const PhaseResults& p) { return p.points.max_um; }, RowKind::kReduce);
  t.Row(
      "points_rms", "  rms (tracker)", [](const PhaseResults& p) { return p.points.rms_um; },
      RowKind::kReduce);
  t.Row(
      "points_true_max",
      worn ? "  max, machine (no instrument error)" : "  max, machine model (no instrument error)",
      [](const PhaseResults& p) { return p.points.true_max_um; }, RowKind::kReduce);
  for (size_t a = 0; a < 3; ++a) {
    const std::string axis = std::string("GOST 27843 ") + "XYZ"[a];
    const std::string k = std::string("gost_") + "xyz"[a];
    t.Row(
        k + "_a", axis + "  A (accuracy)", [a](const PhaseResults& p) { return p.Gost()[a].A; },
        RowKind::kReduce);
    t.Row(
        k + "_r", axis + "  R (repeatability)",
        [a](const PhaseResults& p) { return p.Gost()[a].R; }, repeatability);
    t.Row(
        k + "_b", axis + "  B (reversal)", [a](const PhaseResults& p) { return p.Gost()[a].B; },
        reversal);
  }
  // The ISO 230-4 circular tests (worn machine): G(b) and H per plane.
  for (size_t k = 0; k < r.before.circular.size(); ++k) {
    const std::string plane = r.before.circular[k].plane;
    std::string key = "circle_" + plane;
    for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    auto of = [k](const PhaseResults& p) -> const metrology::CircularResult* {
      return k < p.circular.size() ? &p.circular[k].result : nullptr;
    };
    t.Row(
        key + "_gb", "ISO 230-4 circle " + plane + "  G(b) (ballbar)",
        [of](const PhaseResults& p) { return of(p) ? of(p)->G_b_um : 0.0; }, RowKind::kReduce);
    t.Row(
        key + "_h", "ISO 230-4 circle " + plane + "  H (hysteresis)",
        [of](const PhaseResults& p) { return of(p) ? of(p)->H_um : 0.0; }, RowKind::kReduce);
  }
  return t.Take();
}

// Every figure of the circular tests, per plane and phase (the summary prints G(b) and H; the
// rest, for a program reading them, as `volcomp evaluate circular --json` names them).
JsonValue Circular(const DemoResult& r) {
  JsonValue c = JsonValue::Object();
  c.Set("radius_mm", r.options.circle_radius_mm)
      .Set("feed_mm_min", r.options.circle_feed_mm_min)
      .Set("centre_mm", Vec(r.circle_centre_mm));
  std::vector<const PhaseResults*> phases = {&r.before};
  std::vector<std::string> labels = {"before"};
  for (const NamedPhase& p : r.intermediate) {
    phases.push_back(&p.results);
    labels.push_back(p.label);
  }
  phases.push_back(&r.after);
  labels.push_back(r.after_label);
  JsonValue planes = JsonValue::Array();
  for (size_t k = 0; k < r.before.circular.size(); ++k) {
    JsonValue plane = JsonValue::Object();
    plane.Set("plane", r.before.circular[k].plane);
    JsonValue by_phase = JsonValue::Array();
    for (size_t i = 0; i < phases.size(); ++i) {
      if (k >= phases[i]->circular.size()) continue;
      const CircularTestResult& t = phases[i]->circular[k];
      const metrology::CircularResult& e = t.result;
      JsonValue o = JsonValue::Object();
      o.Set("phase", labels[i]);
      for (auto& [key, value] : metrology::CircularFiguresJson(e).object) {
        o.Set(key, std::move(value));
      }
      o.Set("cutting_max_error_um", t.cutting_max_error_um);
      by_phase.Push(std::move(o));
    }
    plane.Set("phases", std::move(by_phase));
    planes.Push(std::move(plane));
  }
  c.Set("planes", std::move(planes));
  return c;
}

JsonValue Xyz(const std::array<double, 3>& v) { return JsonValue::Numbers({v[0], v[1], v[2]}); }

// The worn machine's thermal step (docs/simulator.md 7.6, summary.json "thermal").
JsonValue Thermal(const ThermalPhase& t) {
  JsonValue o = JsonValue::Object();
  o.Set("calibration_h", t.calibration_h)
      .Set("calibration_readings", uint64_t{t.calibration_readings})
      .Set("calibration_drift_um", Xyz(t.calibration_drift_um));
  JsonValue channels = JsonValue::Array();
  for (const builders::ThermalFitChannel& c : t.fit.channels) {
    channels.Push(JsonValue::Object()
                      .Set("name", c.name)
                      .Set("number", uint64_t{c.number})
                      .Set("reference_C", c.reference_C)
                      .Set("min_C", c.min_C)
                      .Set("max_C", c.max_C));
  }
  o.Set("channels", std::move(channels));
  JsonValue axes = JsonValue::Array();
  for (const builders::ThermalAxisFit& a : t.fit.axes) {
    axes.Push(JsonValue::Object()
                  .Set("axis", std::string(1, a.name))
                  .Set("p0_mm", a.p0_mm)
                  .Set("offset_um_per_K", JsonValue::Numbers(a.offset_um_per_K))
                  .Set("slope_um_per_K_m", JsonValue::Numbers(a.slope_um_per_K_m))
                  .Set("residual_rms_um", a.residual_rms_um)
                  .Set("residual_max_um", a.residual_max_um)
                  .Set("explained", a.explained)
                  .Set("explained_pct", 100 * a.explained)
                  .Set("condition", a.condition));
  }
  o.Set("fit", std::move(axes));
  o.Set("image_bytes", uint64_t{t.image.size()});
  std::array<double, 3> reduction = {0, 0, 0};
  for (size_t a = 0; a < 3; ++a) {
    if (t.drift_before_um[a] > 0)
      reduction[a] = 100 * (1 - t.drift_after_um[a] / t.drift_before_um[a]);
  }
  o.Set("verification_h", t.verification_h)
      .Set("drift_table3_um", Xyz(t.drift_before_um))
      .Set("drift_thermal_um", Xyz(t.drift_after_um))
      .Set("reduction_pct", Xyz(reduction))
      .Set("max_rate_um_s", Xyz({t.compensated.max_rate_um_s[0], t.compensated.max_rate_um_s[1],
                                 t.compensated.max_rate_um_s[2]}))
      .Set("slew_limit_um_s", t.slew_limit_um_s);
  JsonValue faults = JsonValue::Array();
  for (const FaultOutcome& f : t.compensated.faults) {
    faults.Push(
        JsonValue::Object()
            .Set("channel", int64_t{f.injected.sensor})
            .Set("kind", f.injected.kind == SensorFault::kOpenCircuit ? "open circuit" : "stuck")
            .Set("at_s", f.injected.at_s)
            .Set("for_s", f.injected.for_s)
            .Set("detected_after_s", f.detected_after_s)
            .Set("change_while_held_um", f.change_while_held_um));
  }
  o.Set("faults", std::move(faults));
  o.Set("loop", JsonValue::Object()
                    .Set("tick_hz", uint64_t{t.tick_hz})
                    .Set("ticks", t.compensated.ticks)
                    .Set("ticks_table3", t.uncompensated.ticks)
                    .Set("lost_steps", t.compensated.lost_steps)
                    .Set("overruns", uint64_t{t.compensated.overruns})
                    .Set("wall_s_table3", t.uncompensated.wall_s)
                    .Set("wall_s_thermal", t.compensated.wall_s));
  o.Set("wall_s", t.wall_s);
  return o;
}

const std::string& Str(const JsonValue& v, const std::string& key);

void PrintThermal(const JsonValue& t, std::ostream& out) {
  out << "\n== thermal: drift test, fit, verification with the firmware in the loop ===\n";
  char b[300];
  const auto xyz = [&](const char* key) {
    const auto& v = At(t, key).array;
    std::snprintf(b, sizeof b, "X %.1f / Y %.1f / Z %.1f", v[0].number, v[1].number, v[2].number);
    return std::string(b);
  };
  out << Fmt("drift test (calibration duty cycle): %.1f h, largest drift ", Num(t, "calibration_h"))
      << xyz("calibration_drift_um") << " um\n";
  for (const JsonValue& a : At(t, "fit").array) {
    std::string coef;
    const auto& channels = At(t, "channels").array;
    for (size_t j = 0; j < channels.size(); ++j) {
      std::snprintf(b, sizeof b, "  %s %+.2f um/K %+.2f um/(K m)", Str(channels[j], "name").c_str(),
                    At(a, "offset_um_per_K").array[j].number,
                    At(a, "slope_um_per_K_m").array[j].number);
      coef += b;
    }
    std::snprintf(b, sizeof b, "fit %s: residual rms %.2f um, max %.2f um;", Str(a, "axis").c_str(),
                  Num(a, "residual_rms_um"), Num(a, "residual_max_um"));
    out << b << coef << "\n";
  }
  out << Fmt("verification duty cycle: %.1f h; drift with table 3 alone ", Num(t, "verification_h"))
      << xyz("drift_table3_um") << " um, with the thermal model " << xyz("drift_thermal_um")
      << " um (" << xyz("reduction_pct") << " % less)\n";
  out << "fastest change of the correction " << xyz("max_rate_um_s")
      << Fmt(" um/s (slew limit %.2f um/s)\n", Num(t, "slew_limit_um_s"));
  for (const JsonValue& f : At(t, "faults").array) {
    std::snprintf(b, sizeof b,
                  "sensor fault on channel %.0f (%s, at %.0f s for %.0f s): flagged after %.2f s, "
                  "the correction moved %.2f um while flagged\n",
                  Num(f, "channel"), Str(f, "kind").c_str(), Num(f, "at_s"), Num(f, "for_s"),
                  Num(f, "detected_after_s"), Num(f, "change_while_held_um"));
    out << b;
  }
  const JsonValue& l = At(t, "loop");
  std::snprintf(b, sizeof b,
                "firmware in the loop at %.0f Hz: %.0f ticks, %.0f lost steps, %.0f overruns; "
                "%.1f + %.1f s wall\n",
                Num(l, "tick_hz"), Num(l, "ticks"), Num(l, "lost_steps"), Num(l, "overruns"),
                Num(l, "wall_s_table3"), Num(l, "wall_s_thermal"));
  out << b;
}

JsonValue Goals(const DemoResult& r) {
  JsonValue goals = JsonValue::Array();
  for (const Goal& g : r.goals) {
    JsonValue o = JsonValue::Object();
    o.Set("name", g.what)
        .Set("value", g.value)
        .Set("unit", !g.unit.empty() ? g.unit
                     : g.at_least    ? "%"
                                     : "um")
        .Set("limit", g.limit)
        .Set("at_least", g.at_least)
        .Set("holds", g.holds)
        .Set("asserted", g.asserted);
    goals.Push(std::move(o));
  }
  return goals;
}

JsonValue Budget(const DemoResult& r) {
  const ErrorBudget& e = r.budget;
  JsonValue b = JsonValue::Object();
  b.Set("sigma_um", Vec(e.sigma_um))
      .Set("three_sigma_um", e.three_sigma_um)
      .Set("drift_since_table_um", Vec(e.drift_since_table_um))
      .Set("drift_since_table_norm_um", model::Norm(e.drift_since_table_um))
      .Set("drift_since_table_s", e.drift_since_table_s)
      .Set("unmeasured_s", e.unmeasured_s)
      .Set("drift_during_points_um", Vec(e.drift_during_points_um))
      .Set("screw_period_mm", r.options.wear.screw_period_mm)
      .Set("axis_run_pitch_mm", r.options.axis_run_pitch_mm)
      .Set("lattice_spacing_mm", r.options.lattice_spacing_mm)
      .Set("short_period_um", Vec(e.short_period_um))
      .Set("tracker_three_sigma_um", e.tracker_three_sigma_um)
      .Set("laser_cosine_um", e.laser_cosine_um)
      .Set("step_um", e.step_um)
      .Set("limit_um", e.limit_um)
      .Set("max_residual_um", r.after.points.true_max_um)
      .Set("max_residual_within_limit", r.after.points.true_max_um <= e.limit_um)
      .Set("short_period_norm_um", e.short_period_norm_um)
      .Set("goal_limit_um", e.goal_limit_um);
  return b;
}

JsonValue Run(const DemoResult& r) {
  const DemoOptions& o = r.options;
  JsonValue run = JsonValue::Object();
  run.Set("machine", r.machine_name)
      .Set("profile", o.machine == MachineProfile::kWorn ? "worn" : "ideal")
      .Set("model", o.model_spec)
      .Set("seed", static_cast<unsigned long long>(o.seed))
      .Set("points", static_cast<unsigned long long>(r.after.points.targets_mm.size()))
      .Set("gost_targets", o.gost_targets)
      .Set("gost_runs", o.gost_runs)
      .Set("diagonal_targets", o.diagonal_targets)
      .Set("diagonal_runs", o.diagonal_runs);
  JsonValue tables = JsonValue::Array();
  auto table = [&](const std::string& label, const TableBuildResult& t, const UploadReport& u,
                   const ActivationReport& a) {
    JsonValue e = JsonValue::Object();
    e.Set("label", label)
        .Set("bytes", static_cast<unsigned long long>(t.image.size()))
        .Set("crc32", Hex32(t.crc32))
        .Set("staged_crc32", Hex32(u.staged_crc))
        .Set("active_crc32", Hex32(a.active_crc))
        .Set("upload_s", u.transfer_s);
    tables.Push(std::move(e));
  };
  for (const StagedTable& t : r.earlier_tables) table(t.label, t.table, t.upload, t.activation);
  table(r.table_label.empty() ? r.after_label : r.table_label, r.table, r.upload, r.activation);
  run.Set("tables", std::move(tables));
  if (!r.error_sources.is_null()) run.Set("error_sources", r.error_sources);
  return run;
}

JsonValue Steps(const DemoResult& r) {
  const double m_steps = static_cast<double>(r.audit.input_steps) / 1e6;
  JsonValue s = JsonValue::Object();
  s.Set("input_steps", static_cast<unsigned long long>(r.audit.input_steps))
      .Set("output_steps", static_cast<unsigned long long>(r.audit.output_steps))
      .Set("peak_input_rate_mhz", r.peak_input_rate_hz / 1e6)
      .Set("lost_steps", static_cast<unsigned long long>(r.audit.lost_steps))
      .Set("rest_checks", static_cast<unsigned long long>(r.audit.rest_checks))
      .Set("ticks", static_cast<unsigned long long>(r.audit.ticks))
      .Set("tick_mismatches", static_cast<unsigned long long>(r.audit.tick_mismatches))
      .Set("timing_violations", static_cast<unsigned long long>(r.audit.timing_violations))
      .Set("overruns", r.audit.overruns)
      .Set("max_backlog_steps", r.audit.max_backlog);
  JsonValue l = JsonValue::Object();
  l.Set("tick_us", r.tick_us)
      .Set("samples", static_cast<unsigned long long>(r.latency.samples))
      .Set("p50_ticks", r.latency.p50_ticks)
      .Set("p90_ticks", r.latency.p90_ticks)
      .Set("p99_ticks", r.latency.p99_ticks)
      .Set("p999_ticks", r.latency.p999_ticks)
      .Set("max_ticks", r.latency.max_ticks)
      .Set("limit_ticks", 2)
      .Set("over_limit", static_cast<unsigned long long>(r.latency.over_2_ticks))
      .Set("unmatched", static_cast<unsigned long long>(r.latency.unmatched));
  JsonValue v = JsonValue::Object();
  v.Set("benchmark_m_steps_per_s", r.benchmark.steps_per_s / 1e6)
      .Set("benchmark_axes", 3)
      .Set("benchmark_rate_mhz", 1)
      .Set("goal_m_steps_per_s", 10)
      .Set("machine_s", r.virtual_s)
      .Set("m_steps", m_steps)
      .Set("wall_s", r.wall_s)
      .Set("m_steps_per_s", m_steps / r.wall_s);
  JsonValue out = JsonValue::Object();
  out.Set("steps", std::move(s)).Set("latency", std::move(l)).Set("speed", std::move(v));
  return out;
}

unsigned long long Count(const JsonValue& v, const std::string& key) {
  const JsonValue& n = At(v, key);
  return n.is_unsigned ? n.uinteger : static_cast<unsigned long long>(n.integer);
}
const std::string& Str(const JsonValue& v, const std::string& key) { return At(v, key).string; }

void PrintFigures(const JsonValue& d, std::ostream& out) {
  char b[64];
  std::string h(44, ' ');
  const std::vector<JsonValue>& phases = At(d, "phases").array;
  for (size_t i = 0; i < phases.size(); ++i) {
    std::snprintf(b, sizeof b, i == 0 ? "%12s" : "%13s", phases[i].string.c_str());
    h += b;
  }
  out << h << "   reduction\n";
  for (const JsonValue& row : At(d, "figures").array) {
    std::snprintf(b, sizeof b, "%-44s", Str(row, "name").c_str());
    std::string line = b;
    for (const JsonValue& v : At(row, "values").array) {
      std::snprintf(b, sizeof b, " %9.3f %s", v.number, Str(row, "unit").c_str());
      line += b;
    }
    const JsonValue& reduction = At(row, "reduction_pct");
    if (reduction.is_number()) {
      std::snprintf(b, sizeof b, "   %6.2f %%", reduction.number);
      line += b;
    } else {
      line += "   (" + Str(row, "note") + ")";
    }
    out << line << "\n";
  }
}

void PrintGoals(const JsonValue& d, std::ostream& out) {
  out << "\n== goals of the worn profile =============================================\n";
  char b[300];
  bool reported = false;
  for (const JsonValue& g : At(d, "goals").array) {
    const bool asserted = At(g, "asserted").boolean;
    if (!asserted && !reported) {
      out << "reported, not asserted (not in the exit code):\n";
      reported = true;
    }
    const std::string& unit = Str(g, "unit");
    std::snprintf(b, sizeof b, "%-84s %8.2f %s %s %6.2f %s  %s\n", Str(g, "name").c_str(),
                  Num(g, "value"), unit.c_str(),
                  At(g, "at_least").boolean ? ">=" : "<=", Num(g, "limit"), unit.c_str(),
                  At(g, "holds").boolean ? "holds" : (asserted ? "FAILS" : "misses"));
    out << b;
  }
}

void PrintBudget(const JsonValue& d, std::ostream& out) {
  const JsonValue& e = At(d, "error_budget");
  out << "\n== error budget: what remains after the last compensation ================\n";
  char b[400];
  std::snprintf(b, sizeof b,
                "repeatability: GOST 27843 S (uncompensated, pooled over the targets) X %.2f, "
                "Y %.2f, Z %.2f um -> 3 sigma (3-D) %.2f um\n",
                Num(e, "sigma_um", 0), Num(e, "sigma_um", 1), Num(e, "sigma_um", 2),
                Num(e, "three_sigma_um"));
  out << b;
  std::snprintf(b, sizeof b,
                "thermal drift at the check point since the tracker lattice was measured "
                "(%.0f s; %.0f s of table changes not covered): (%.2f, %.2f, %.2f) um, |.| "
                "%.2f um\n",
                Num(e, "drift_since_table_s"), Num(e, "unmeasured_s"),
                Num(e, "drift_since_table_um", 0), Num(e, "drift_since_table_um", 1),
                Num(e, "drift_since_table_um", 2), Num(e, "drift_since_table_norm_um"));
  out << b;
  std::snprintf(b, sizeof b, "  of which during the final point test: (%.2f, %.2f, %.2f) um\n",
                Num(e, "drift_during_points_um", 0), Num(e, "drift_during_points_um", 1),
                Num(e, "drift_during_points_um", 2));
  out << b;
  std::snprintf(
      b, sizeof b,
      "short-period screw error (the machine's, period %.0f mm: not seen at the %.0f/%.0f "
      "mm measuring pitch): amplitude X %.2f, Y %.2f, Z %.2f um\n",
      Num(e, "screw_period_mm"), Num(e, "axis_run_pitch_mm"), Num(e, "lattice_spacing_mm"),
      Num(e, "short_period_um", 0), Num(e, "short_period_um", 1), Num(e, "short_period_um", 2));
  out << b;
  std::snprintf(b, sizeof b,
                "the instrument: tracker 3 sigma %.2f um per coordinate (in the tracker figures, "
                "and in every node of the lattice table); laser cosine error %.2f um over the "
                "longest line\n",
                Num(e, "tracker_three_sigma_um"), Num(e, "laser_cosine_um"));
  out << b;
  std::snprintf(b, sizeof b,
                "resolution: 1 step = %.2f um\n"
                "limit for the max residual: 3 sigma + |drift| + 1 step = %.2f um (the max "
                "residual, %.2f um, %s it); + the short-period error |A| %.2f um = %.2f um\n",
                Num(e, "step_um"), Num(e, "limit_um"), Num(e, "max_residual_um"),
                At(e, "max_residual_within_limit").boolean ? "is within" : "exceeds",
                Num(e, "short_period_norm_um"), Num(e, "goal_limit_um"));
  out << b;
}

void PrintSteps(const JsonValue& d, std::ostream& out) {
  const JsonValue& s = At(d, "steps");
  const JsonValue& l = At(d, "latency");
  const JsonValue& v = At(d, "speed");
  char b[256];
  out << "\n== steps, timing, latency, speed =========================================\n";
  std::snprintf(b, sizeof b,
                "input steps %llu, output steps %llu, peak input rate %.3f MHz per axis\n",
                Count(s, "input_steps"), Count(s, "output_steps"), Num(s, "peak_input_rate_mhz"));
  out << b;
  std::snprintf(b, sizeof b,
                "lost steps: %llu (drive == CNC steps + correction at %llu rest points; drive == "
                "board output at every one of %llu ticks: %llu mismatches)\n",
                Count(s, "lost_steps"), Count(s, "rest_checks"), Count(s, "ticks"),
                Count(s, "tick_mismatches"));
  out << b;
  std::snprintf(b, sizeof b,
                "pulse timing violations at the drives: %llu; backlog overruns: %llu, largest "
                "backlog %llu steps\n",
                Count(s, "timing_violations"), Count(s, "overruns"), Count(s, "max_backlog_steps"));
  out << b;
  std::snprintf(b, sizeof b,
                "latency input step -> output step (tick %.0f us, %llu steps): p50 %.2f, p90 "
                "%.2f, p99 %.2f, p99.9 %.2f, max %.3f ticks; > %.0f ticks: %llu; unmatched: "
                "%llu\n",
                Num(l, "tick_us"), Count(l, "samples"), Num(l, "p50_ticks"), Num(l, "p90_ticks"),
                Num(l, "p99_ticks"), Num(l, "p999_ticks"), Num(l, "max_ticks"),
                Num(l, "limit_ticks"), Count(l, "over_limit"), Count(l, "unmatched"));
  out << b;
  std::snprintf(b, sizeof b,
                "simulator speed: %.1f M steps/s (%.0f axes at %.0f MHz; goal >= %.0f M/s); whole "
                "demo: %.1f s of machine time, %.1f M steps in %.1f s wall (%.1f M steps/s)\n",
                Num(v, "benchmark_m_steps_per_s"), Num(v, "benchmark_axes"),
                Num(v, "benchmark_rate_mhz"), Num(v, "goal_m_steps_per_s"), Num(v, "machine_s"),
                Num(v, "m_steps"), Num(v, "wall_s"), Num(v, "m_steps_per_s"));
  out << b;
}

}  // namespace

tools::JsonValue SummaryData(const DemoResult& r) {
  const bool worn = r.options.machine == MachineProfile::kWorn;
  JsonValue d = JsonValue::Object();
  d.Set("run", Run(r));
  JsonValue phases = JsonValue::Array().Push("before");
  for (const NamedPhase& p : r.intermediate) phases.Push(p.label);
  phases.Push(r.after_label);
  d.Set("phases", std::move(phases));
  d.Set("figures", Figures(r));
  if (!r.before.circular.empty()) d.Set("circular", Circular(r));
  if (worn) {
    d.Set("goals", Goals(r));
    d.Set("error_budget", Budget(r));
    if (r.thermal.ran) d.Set("thermal", Thermal(r.thermal));
  }
  for (auto& [key, value] : Steps(r).object) d.Set(key, std::move(value));
  JsonValue failures = JsonValue::Array();
  for (const std::string& f : r.failures) failures.Push(f);
  d.Set("passed", r.failures.empty());
  d.Set("failures", std::move(failures));
  return d;
}

void PrintSummaryData(const tools::JsonValue& d, std::ostream& out) {
  const bool worn = Str(At(d, "run"), "profile") == "worn";
  out << "\n== before / after compensation ==========================================\n";
  PrintFigures(d, out);
  if (worn) {
    PrintGoals(d, out);
    PrintBudget(d, out);
    if (const JsonValue* t = d.get("thermal")) PrintThermal(*t, out);
  }
  PrintSteps(d, out);
  if (At(d, "passed").boolean) {
    out << (worn ? "\nall checks passed: every asserted goal of the worn profile holds, zero lost "
                   "steps, "
                   "zero timing violations, latency <= 2 ticks\n"
                 : "\nall checks passed: residual >= 95 % below uncompensated (E_d and random "
                   "points), zero lost steps, zero timing violations, latency <= 2 ticks\n");
  } else {
    out << "\nFAILED:";
    for (const JsonValue& f : At(d, "failures").array) out << " " << f.string << ";";
    out << "\n";
  }
}

void PrintSummary(const DemoResult& r, std::ostream& out) { PrintSummaryData(SummaryData(r), out); }

}  // namespace volcomp::sim
