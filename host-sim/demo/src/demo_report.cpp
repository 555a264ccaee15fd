// HTML report and data files of a demo run.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "volcomp/image/image_reader.hpp"
#include "volcomp/image/table_map.hpp"
#include "volcomp/metrology/circular_report.hpp"
#include "volcomp/metrology/diagonal_report.hpp"
#include "volcomp/metrology/positioning_report.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/report/html_page.hpp"
#include "volcomp/report/xy_chart.hpp"
#include "volcomp/sim/demo.hpp"
#include "volcomp/tools/file_io.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::sim {
namespace {

using report::FormatFixed;

std::string PointsCsv(const PointSetResult& p) {
  std::string csv = "x_mm,y_mm,z_mm,dx_um,dy_um,dz_um,norm_um,true_dx_um,true_dy_um,true_dz_um\n";
  for (size_t i = 0; i < p.targets_mm.size(); ++i) {
    const model::Vec3& m = p.measured_error_um[i];
    const model::Vec3& t = p.true_error_um[i];
    csv += FormatFixed(p.targets_mm[i][0], 3) + "," + FormatFixed(p.targets_mm[i][1], 3) + "," +
           FormatFixed(p.targets_mm[i][2], 3) + "," + FormatFixed(m.x, 3) + "," +
           FormatFixed(m.y, 3) + "," + FormatFixed(m.z, 3) + "," + FormatFixed(model::Norm(m), 3) +
           "," + FormatFixed(t.x, 4) + "," + FormatFixed(t.y, 4) + "," + FormatFixed(t.z, 4) + "\n";
  }
  return csv;
}

std::string Pct(double before, double after) {
  return before > 0 ? FormatFixed(100.0 * (1.0 - after / before), 2) + " %" : "n/a";
}

// |error| per point as markers (point number on x).
report::XySeries NormSeries(const char* label,
                            const char* color,
                            const std::vector<model::Vec3>& errors_um) {
  report::XySeries s;
  s.label = label;
  if (color != nullptr) s.color = color;
  s.line = false;
  for (size_t i = 0; i < errors_um.size(); ++i) {
    s.x.push_back(static_cast<double>(i + 1));
    s.y.push_back(model::Norm(errors_um[i]));
  }
  return s;
}

std::string PointsChart(const DemoResult& r) {
  report::XyChart c;
  c.title = "Volumetric error at the random points (laser tracker)";
  c.x_label = "point";
  c.y_label = "|error|, µm";
  c.series = {NormSeries("before", nullptr, r.before.points.measured_error_um),
              NormSeries("after", "#d62728", r.after.points.measured_error_um)};
  return c.Render();
}

std::string AfterPointsChart(const DemoResult& r) {
  report::XyChart c;
  c.title = "After compensation: tracker reading and machine model (no instrument error)";
  c.x_label = "point";
  c.y_label = "|error|, µm";
  c.series = {NormSeries("tracker", nullptr, r.after.points.measured_error_um),
              NormSeries("machine model", "#2ca02c", r.after.points.true_error_um)};
  return c.Render();
}

std::string ParametricChart(const ParametricResult& p, bool angular) {
  static const char* kColors[3] = {"#1f77b4", "#d62728", "#2ca02c"};
  report::XyChart c;
  const char axis = "XYZ"[p.axis];
  c.title = std::string(angular ? "Angular" : "Linear") + " error motions of " + axis +
            " (measured: markers, machine model: dashed)";
  c.x_label = std::string(1, axis) + ", mm";
  c.y_label = angular ? "µrad" : "µm";
  for (int k = 0; k < 3; ++k) {
    report::XySeries m, t;
    const char* names = angular ? "ABC" : "XYZ";
    m.label = std::string("E") + names[k] + axis;
    m.color = t.color = kColors[k];
    m.line = false;
    t.dash = "4 3";
    t.marker = report::Marker::kNone;
    for (size_t i = 0; i < p.position_mm.size(); ++i) {
      const SixDofReading& mm = p.measured[i];
      const SixDofReading& tt = p.truth[i];
      m.x.push_back(p.position_mm[i]);
      t.x.push_back(p.position_mm[i]);
      m.y.push_back(angular ? mm.angular_urad[k] : mm.linear_um[k]);
      t.y.push_back(angular ? tt.angular_urad[k] : tt.linear_um[k]);
    }
    c.series.push_back(m);
    c.series.push_back(t);
  }
  return c.Render();
}

std::string LatencyChart(const DemoResult& r) {
  report::XyChart c;
  c.title = "Latency from an input step to its output step";
  c.x_label = "ticks";
  c.y_label = "steps (log10)";
  report::XyBars bars;
  bars.bar_px = 2;
  const size_t n = r.latency_histogram.size();
  for (size_t i = 0; i + 1 < n && i < 3 * LatencyMeter::kBinsPerTick; ++i) {
    if (r.latency_histogram[i] == 0) continue;
    bars.x.push_back((static_cast<double>(i) + 0.5) / LatencyMeter::kBinsPerTick);
    bars.y.push_back(std::log10(static_cast<double>(r.latency_histogram[i]) + 1.0));
  }
  c.bars = {bars};
  return c.Render();
}

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// A ballbar's readings in the format `volcomp evaluate circular` reads.
std::string BallbarCsv(const metrology::CircularData& d) {
  std::string csv = "direction,angle_deg,deviation_um\n";
  for (const auto& [name, path] :
       {std::pair<const char*, const metrology::CircularPath*>{"ccw", &d.ccw}, {"cw", &d.cw}}) {
    for (size_t i = 0; i < path->angle_deg.size(); ++i) {
      csv += std::string(name) + "," + FormatFixed(path->angle_deg[i], 3) + "," +
             FormatFixed(path->deviation_um[i], 2) + "\n";
    }
  }
  return csv;
}

// The measured phases in order, with their column label and file tag.
struct Phase {
  std::string label, tag;
  const PhaseResults* results;
};

std::vector<Phase> Phases(const DemoResult& r) {
  std::vector<Phase> p = {{"before", "before", &r.before}};
  for (size_t i = 0; i < r.intermediate.size(); ++i) {
    p.push_back(
        {r.intermediate[i].label, "after" + std::to_string(i + 1), &r.intermediate[i].results});
  }
  p.push_back({r.after_label, "after", &r.after});
  return p;
}

// The worn run's inputs of its tables, in the PC tool's formats: the ISO 230-2 runs (`volcomp
// evaluate positioning`), their mean deviations (`volcomp build axis`), the tracker lattice
// (`volcomp build tracker --lattice`), and every image the board received.
Outcome WriteWornData(const DemoResult& r, const std::string& dir) {
  for (size_t a = 0; a < 3; ++a) {
    const std::string axis(1, "xyz"[a]);
    VOLCOMP_TRY(tools::WriteTextFile(dir + "/data/axis_run_" + axis + ".csv",
                                     PositioningCsv(r.axis_runs[a].data)));
    const model::PositioningData d = PairMeans(MeanDeviations(r.axis_runs[a].iso));
    std::string csv = "position_mm,dev_forward_um,dev_reverse_um\n";
    for (size_t i = 0; i < d.position.size(); ++i) {
      csv += FormatFixed(d.position[i], 4) + "," + FormatFixed(d.dev_forward[i], 4) + "," +
             FormatFixed(d.dev_reverse[i], 4) + "\n";
    }
    VOLCOMP_TRY(tools::WriteTextFile(dir + "/data/axis_" + axis + ".csv", csv));
  }
  const model::GridAxes& g = r.lattice.lattice;
  std::string csv = "x_cmd_mm,y_cmd_mm,z_cmd_mm,x_mm,y_mm,z_mm\n";
  size_t n = 0;
  for (uint32_t k = 0; k < g[2].nodes; ++k) {
    for (uint32_t j = 0; j < g[1].nodes; ++j) {
      for (uint32_t i = 0; i < g[0].nodes; ++i) {
        const model::Vec3& p = r.lattice.position_mm[n++];
        csv += FormatFixed(g[0].origin_mm + i * g[0].spacing_mm, 4) + "," +
               FormatFixed(g[1].origin_mm + j * g[1].spacing_mm, 4) + "," +
               FormatFixed(g[2].origin_mm + k * g[2].spacing_mm, 4) + "," + FormatFixed(p.x, 6) +
               "," + FormatFixed(p.y, 6) + "," + FormatFixed(p.z, 6) + "\n";
      }
    }
  }
  VOLCOMP_TRY(tools::WriteTextFile(dir + "/data/tracker_lattice.csv", csv));
  std::string drift = "after,time_s,table,dx_um,dy_um,dz_um\n";
  for (const DriftCheck& c : r.drift) {
    drift += "\"" + c.after + "\"," + FormatFixed(c.time_s, 2) + "," + std::to_string(c.epoch) +
             "," + FormatFixed(c.reading_um.x, 3) + "," + FormatFixed(c.reading_um.y, 3) + "," +
             FormatFixed(c.reading_um.z, 3) + "\n";
  }
  VOLCOMP_TRY(tools::WriteTextFile(dir + "/data/drift_checks.csv", drift));
  for (size_t i = 0; i < r.earlier_tables.size(); ++i) {
    VOLCOMP_TRY(tools::WriteFileBytes(dir + "/table" + std::to_string(i + 1) + ".vct",
                                      r.earlier_tables[i].table.image));
  }
  if (r.thermal.ran) {
    // `volcomp evaluate thermal data/drift_test.csv`, `volcomp build thermal data/drift_test.csv
    // --image table.vct -o table_thermal.vct`; the verification cycle's readings in the same form.
    const ThermalPhase& t = r.thermal;
    VOLCOMP_TRY(tools::WriteTextFile(dir + "/data/drift_test.csv", t.drift_csv));
    VOLCOMP_TRY(tools::WriteTextFile(dir + "/data/verification_table3.csv",
                                     DriftTestCsv(t.uncompensated.run, r.machine_name)));
    VOLCOMP_TRY(tools::WriteTextFile(dir + "/data/verification_thermal.csv",
                                     DriftTestCsv(t.compensated.run, r.machine_name)));
    VOLCOMP_TRY(tools::WriteFileBytes(dir + "/table_thermal.vct", t.image));
  }
  return Outcome::Ok();
}

void AddWornSections(report::HtmlPage* page, const DemoResult& r) {
  page->Heading(2, "Goals of the worn profile");
  std::vector<std::vector<std::string>> goals;
  for (const Goal& g : r.goals) {
    const char* unit = g.at_least ? " %" : " µm";
    goals.push_back(
        {g.what, FormatFixed(g.value, 2) + unit,
         std::string(g.at_least ? "≥ " : "≤ ") + FormatFixed(g.limit, 2) + unit,
         g.holds ? "holds" : (g.asserted ? "FAILS" : "misses (reported, not asserted)")});
  }
  page->Table({"goal", "measured", "limit", ""}, goals);
  const ErrorBudget& e = r.budget;
  page->Heading(2, "Error budget: what remains after the last compensation");
  page->Table(
      {"term", "value"},
      {{"repeatability: GOST 27843 S per axis (uncompensated, pooled), µm",
        FormatFixed(e.sigma_um[0], 2) + " / " + FormatFixed(e.sigma_um[1], 2) + " / " +
            FormatFixed(e.sigma_um[2], 2) + " → 3σ (3-D) " + FormatFixed(e.three_sigma_um, 2)},
       {"thermal drift at the check point since the lattice was measured, µm",
        FormatFixed(e.drift_since_table_um.x, 2) + ", " + FormatFixed(e.drift_since_table_um.y, 2) +
            ", " + FormatFixed(e.drift_since_table_um.z, 2) + " (|.| " +
            FormatFixed(model::Norm(e.drift_since_table_um), 2) + " over " +
            FormatFixed(e.drift_since_table_s, 0) + " s)"},
       {"  of which during the final point test, µm",
        FormatFixed(e.drift_during_points_um.x, 2) + ", " +
            FormatFixed(e.drift_during_points_um.y, 2) + ", " +
            FormatFixed(e.drift_during_points_um.z, 2)},
       {"short-period screw error (not seen at the measuring pitch), amplitude µm",
        FormatFixed(e.short_period_um[0], 2) + " / " + FormatFixed(e.short_period_um[1], 2) +
            " / " + FormatFixed(e.short_period_um[2], 2)},
       {"instrument: tracker 3σ per coordinate / laser cosine error, µm",
        FormatFixed(e.tracker_three_sigma_um, 2) + " / " + FormatFixed(e.laser_cosine_um, 2)},
       {"1 step, µm", FormatFixed(e.step_um, 2)},
       {"3σ + |drift| + 1 step, µm", FormatFixed(e.limit_um, 2)},
       {"+ short-period error |A| = limit for the max residual, µm",
        FormatFixed(e.goal_limit_um, 2)}});
}

// The circular tests: G(b) and H per plane and phase, and each plane's polar plot before and
// after (the plot of `volcomp evaluate circular --report`).
void AddCircularSection(report::HtmlPage* page,
                        const DemoResult& r,
                        const std::vector<Phase>& phases) {
  page->Heading(2, "ISO 230-4 circular tests (ballbar at the centre, r " +
                       FormatFixed(r.options.circle_radius_mm, 0) + " mm, " +
                       FormatFixed(r.options.circle_feed_mm_min, 0) + " mm/min)");
  std::vector<std::string> header = {"plane, figure"};
  for (const Phase& ph : phases) header.push_back(ph.label);
  header.push_back("reduction");
  std::vector<std::vector<std::string>> rows;
  for (size_t k = 0; k < r.before.circular.size(); ++k) {
    for (int h = 0; h < 2; ++h) {
      std::vector<std::string> cells = {r.before.circular[k].plane + (h ? " H, µm" : " G(b), µm")};
      for (const Phase& ph : phases) {
        const auto& c = ph.results->circular;
        cells.push_back(k < c.size() ? FormatFixed(h ? c[k].result.H_um : c[k].result.G_b_um, 2)
                                     : "-");
      }
      const auto& b = r.before.circular[k].result;
      const bool after = k < r.after.circular.size();
      cells.push_back(after ? Pct(h ? b.H_um : b.G_b_um, h ? r.after.circular[k].result.H_um
                                                           : r.after.circular[k].result.G_b_um)
                            : "-");
      rows.push_back(cells);
    }
  }
  page->Table(header, rows);
  for (size_t k = 0; k < r.before.circular.size() && k < r.after.circular.size(); ++k) {
    for (const PhaseResults* p : {&r.before, &r.after}) {
      const CircularTestResult& c = p->circular[k];
      metrology::CircularEvaluation ev;
      ev.data = c.data;
      ev.result = c.result;
      page->Figure(metrology::CircularPolarSvg(ev),
                   c.plane + ", " +
                       (p == &r.before ? "before compensation" : "after: " + r.after_label) +
                       ": G(b) " + FormatFixed(c.result.G_b_um, 2) + " µm, H " +
                       FormatFixed(c.result.H_um, 2) + " µm (data/circle_" + Lower(c.plane) + "_" +
                       (p == &r.before ? "before" : "after") + ".csv).");
    }
  }
}

}  // namespace

Outcome WriteDemoReport(const DemoResult& r, const std::string& dir) {
  for (const char* sub : {"", "/data", "/programs", "/model"})
    VOLCOMP_TRY(report::PrepareReportPath(dir + sub, "index.html"));

  // Data files, in the formats the PC tool reads.
  for (const Phase& ph : Phases(r)) {
    const std::string tag = ph.tag;
    for (size_t a = 0; a < 3; ++a) {
      VOLCOMP_TRY(
          tools::WriteTextFile(dir + "/data/gost_" + std::string(1, "xyz"[a]) + "_" + tag + ".csv",
                               PositioningCsv(ph.results->gost[a].data)));
    }
    VOLCOMP_TRY(
        tools::WriteTextFile(dir + "/data/diagonals_" + tag + ".csv", ph.results->diagonals.csv));
    VOLCOMP_TRY(
        tools::WriteTextFile(dir + "/data/points_" + tag + ".csv", PointsCsv(ph.results->points)));
    for (const CircularTestResult& c : ph.results->circular) {
      VOLCOMP_TRY(tools::WriteTextFile(dir + "/data/circle_" + Lower(c.plane) + "_" + tag + ".csv",
                                       BallbarCsv(c.data)));
    }
  }
  for (const CircularTestResult& c : r.before.circular) {
    VOLCOMP_TRY(tools::WriteTextFile(dir + "/programs/circle_" + Lower(c.plane) + ".ngc", c.gcode));
  }
  if (r.options.machine == MachineProfile::kWorn) VOLCOMP_TRY(WriteWornData(r, dir));
  for (size_t a = 0; a < 3; ++a) {
    VOLCOMP_TRY(tools::WriteTextFile(dir + "/programs/gost_" + std::string(1, "xyz"[a]) + ".ngc",
                                     r.before.gost[a].program.gcode));
  }
  for (const TestProgram& p : r.before.diagonals.programs) {
    std::string name = p.name;
    for (char& c : name) c = c == '+' ? 'P' : c == '-' ? 'N' : c;
    VOLCOMP_TRY(tools::WriteTextFile(dir + "/programs/diagonal_" + name + ".ngc", p.gcode));
  }
  VOLCOMP_TRY(tools::WriteTextFile(dir + "/programs/points.ngc", r.before.points.program.gcode));
  VOLCOMP_TRY(WriteModelFiles(r.measured_model, dir + "/model"));
  VOLCOMP_TRY(tools::WriteFileBytes(dir + "/table.vct", r.table.image));
  {
    std::ostringstream summary;
    tools::WriteJson(SummaryData(r), summary);
    summary << "\n";
    VOLCOMP_TRY(tools::WriteTextFile(dir + "/summary.json", summary.str()));
  }

  report::HtmlPage page("volcomp-sim demo report");
  page.Heading(1, "volcomp-sim demo: volumetric compensation of a simulated machine");
  page.Paragraph("Seed " + std::to_string(r.options.seed) + ". Machine: " + r.machine_name +
                 ". The real firmware (BoardApp on the mock HAL) ran between the simulated CNC "
                 "and the drive checkers; the table went over the simulated CAN bus with the PC "
                 "tool's SDO code. Run time " +
                 FormatFixed(r.wall_s, 1) + " s wall for " + FormatFixed(r.virtual_s, 1) +
                 " s of machine time.");
  page.Heading(2, "Before and after");
  const std::vector<Phase> phases = Phases(r);
  const bool worn = r.options.machine == MachineProfile::kWorn;
  std::vector<std::vector<std::string>> rows;
  auto row = [&](const std::string& what, double (*figure)(const PhaseResults&, size_t), size_t a,
                 bool reduce) {
    std::vector<std::string> cells = {what};
    for (const Phase& ph : phases) cells.push_back(FormatFixed(figure(*ph.results, a), 3));
    const double b = figure(r.before, a), f = figure(r.after, a);
    cells.push_back(reduce ? Pct(b, f) : worn ? "(scatter)" : "(noise)");
    rows.push_back(cells);
  };
  row(
      "ISO 230-6 E_d (body diagonals), µm", [](const PhaseResults& p, size_t) { return p.Ed(); }, 0,
      true);
  row(
      "ISO 230-6 B_d, µm", [](const PhaseResults& p, size_t) { return p.Bd(); }, 0, worn);
  row(
      "volumetric error, max over points (tracker), µm",
      [](const PhaseResults& p, size_t) { return p.points.max_um; }, 0, true);
  row(
      "volumetric error, rms (tracker), µm",
      [](const PhaseResults& p, size_t) { return p.points.rms_um; }, 0, true);
  row(
      worn ? "volumetric error, max, machine, µm" : "volumetric error, max, machine model, µm",
      [](const PhaseResults& p, size_t) { return p.points.true_max_um; }, 0, true);
  for (size_t a = 0; a < 3; ++a) {
    const std::string axis(1, "XYZ"[a]);
    row(
        "GOST 27843 " + axis + " A, µm",
        [](const PhaseResults& p, size_t i) { return p.Gost()[i].A; }, a, true);
    row(
        "GOST 27843 " + axis + " R, µm",
        [](const PhaseResults& p, size_t i) { return p.Gost()[i].R; }, a, false);
    row(
        "GOST 27843 " + axis + " B, µm",
        [](const PhaseResults& p, size_t i) { return p.Gost()[i].B; }, a, worn);
  }
  std::vector<std::string> header = {"figure"};
  for (const Phase& ph : phases) header.push_back(ph.label);
  header.push_back("reduction");
  page.Table(header, rows);
  if (worn) AddWornSections(&page, r);
  if (!r.before.circular.empty()) AddCircularSection(&page, r, phases);
  page.Heading(2, "Steps, timing and latency");
  page.Table(
      {"figure", "value"},
      {{"input steps / output steps",
        std::to_string(r.audit.input_steps) + " / " + std::to_string(r.audit.output_steps)},
       {"lost steps (rest checks)", std::to_string(r.audit.lost_steps) + " at " +
                                        std::to_string(r.audit.rest_checks) + " rest points"},
       {"ticks where a drive's count differed from the board's output",
        std::to_string(r.audit.tick_mismatches) + " of " + std::to_string(r.audit.ticks)},
       {"pulse timing violations at the drives", std::to_string(r.audit.timing_violations)},
       {"latency p50 / p90 / p99 / p99.9 / max, ticks of " + FormatFixed(r.tick_us, 0) + " µs",
        FormatFixed(r.latency.p50_ticks, 2) + " / " + FormatFixed(r.latency.p90_ticks, 2) + " / " +
            FormatFixed(r.latency.p99_ticks, 2) + " / " + FormatFixed(r.latency.p999_ticks, 2) +
            " / " + FormatFixed(r.latency.max_ticks, 3)},
       {"peak input step rate per axis", FormatFixed(r.peak_input_rate_hz / 1e6, 3) + " MHz"},
       {"simulator speed (3 axes at 1 MHz)",
        FormatFixed(r.benchmark.steps_per_s / 1e6, 1) + " M steps per wall-clock second"}});
  page.Figure(LatencyChart(r), "Latency distribution (1/100 tick bins, log scale).");
  page.Heading(2, "Volumetric error at random points");
  page.Figure(PointsChart(r), "Norm of the error vector at each point, before and after.");
  page.Figure(AfterPointsChart(r),
              "After compensation: what the tracker read and what the "
              "machine model says (the rest is tracker noise).");
  page.Heading(2, "The table");
  std::vector<std::string> items;
  for (const auto& [k, v] : r.table.info) items.push_back(k + ": " + v);
  items.push_back("image: " + std::to_string(r.table.image.size()) + " bytes (table.vct), " +
                  "largest correction " +
                  FormatFixed(r.table.grid ? r.table.grid->build.stats.max_correction_um : 0, 1) +
                  " µm");
  items.push_back("upload: " + FormatFixed(r.upload.transfer_s, 2) + " s of bus time, " +
                  FormatFixed(r.upload.rate_bytes_s / 1000, 1) + " kB/s");
  page.List(items);
  if (worn) {
    page.Paragraph(
        "Rebuild its sections with the PC tool: volcomp build tracker --lattice "
        "data/tracker_lattice.csv --through table2.vct --resolution-nm X=1000,Y=1000,Z=1000 "
        "--spacing-mm " +
        FormatFixed(r.options.grid_spacing_mm, 0) +
        " -o grid.vct; volcomp build axis --x data/axis_x.csv --y data/axis_y.csv --z "
        "data/axis_z.csv --resolution-nm X=1000,Y=1000,Z=1000 --spacing X=" +
        FormatFixed(r.options.axis_run_pitch_mm, 0) +
        ",Y=" + FormatFixed(r.options.axis_run_pitch_mm, 0) +
        ",Z=" + FormatFixed(r.options.axis_run_pitch_mm, 0) +
        " --reverse backlash -o axis.vct; volcomp build image --grid grid.vct --axis axis.vct -o "
        "table.vct (the demo's table.vct, joined the same way).");
  } else {
    page.Paragraph(
        "Rebuild it with the PC tool: volcomp build model --model model/measured.conf "
        "--resolution-nm X=1000,Y=1000,Z=1000 --spacing-mm " +
        FormatFixed(r.options.grid_spacing_mm, 0) + " -o table.vct");
  }
  {
    // The final table's map, drawn as `volcomp inspect table.vct --report DIR` draws it; its
    // figures in table_map.json.
    VOLCOMP_TRY_ASSIGN(const image::LoadedImage img,
                       image::LoadedImage::FromBytes(r.table.image, "table.vct"));
    VOLCOMP_TRY_ASSIGN(const image::TableMap map, image::MapTable(img, "table.vct"));
    image::AddTableMapSections(&page, map, 3);
    std::ostringstream json;
    tools::WriteJson(image::TableMapJson(map), json);
    json << "\n";
    VOLCOMP_TRY(tools::WriteTextFile(dir + "/table_map.json", json.str()));
  }
  for (const ParametricResult& p : r.parametric) {
    page.Figure(ParametricChart(p, false), "");
    page.Figure(ParametricChart(p, true), "");
  }
  for (const Phase& ph : phases) {
    const std::string when =
        ph.results == &r.before ? "before compensation" : "compensation: " + ph.label;
    page.Heading(2, "ISO 230-6 diagonals, " + when);
    metrology::AddDiagonalSections(&page, ph.results->diagonals.evaluation);
    for (size_t a = 0; a < 3; ++a) {
      page.Heading(2, std::string("GOST 27843 ") + "XYZ"[a] + ", " + when);
      metrology::AddPositioningSection(&page, ph.results->gost[a].gost);
    }
  }
  return tools::WriteTextFile(dir + "/index.html", page.Render());
}

}  // namespace volcomp::sim
