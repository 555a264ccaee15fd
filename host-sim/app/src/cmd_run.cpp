// `volcomp-sim run`: a part program through the real firmware on the simulated machine.
#include <cstdio>
#include <sstream>

#include "commands.hpp"
#include "volcomp/metrology/circular_report.hpp"
#include "volcomp/sim/program_run.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/file_io.hpp"
#include "volcomp/tools/hex.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::sim {
namespace {

tools::JsonValue Vector(const Point3& v) {
  tools::JsonValue j = tools::JsonValue::Array();
  for (double x : v) j.Push(x);
  return j;
}

tools::JsonValue ResultJson(const ProgramRunResult& r) {
  tools::JsonValue j = tools::JsonValue::Object();
  j.Set("program", r.program);
  j.Set("machine", r.machine);
  j.Set("table_crc", r.table_crc == 0 ? tools::JsonValue() : tools::JsonValue(r.table_crc));
  j.Set("touch_off_mm", Vector(r.touch_off_mm));
  j.Set("work_offset_um", Vector(r.work_offset_um));
  j.Set("duration_s", r.duration_s);
  j.Set("cutting_max_error_um", r.cutting_max_error_um);
  j.Set("cutting_rms_error_um", r.cutting_rms_error_um);
  j.Set("rapid_max_error_um", r.rapid_max_error_um);
  j.Set("rest_max_error_um", r.rest_max_error_um);
  j.Set("lost_steps", static_cast<unsigned long long>(r.lost_steps));
  j.Set("timing_violations", static_cast<unsigned long long>(r.timing_violations));
  j.Set("rest_checks", static_cast<unsigned long long>(r.rest_checks));
  j.Set("samples", static_cast<unsigned long long>(r.samples.size()));
  tools::JsonValue segments = tools::JsonValue::Array();
  for (const LineFigures& l : r.lines) {
    tools::JsonValue s = tools::JsonValue::Object();
    s.Set("line", l.line);
    s.Set("kind", SampleKindName(l.kind));
    s.Set("samples", static_cast<unsigned long long>(l.samples));
    s.Set("max_error_um", l.max_error_um);
    segments.Push(s);
  }
  j.Set("segments", segments);
  if (r.circular) {
    tools::JsonValue b = metrology::CircularFiguresJson(*r.circular);
    j.Set("ballbar", b);
  }
  return j;
}

void PrintResult(const ProgramRunResult& r, std::ostream& out) {
  char b[200];
  std::snprintf(b, sizeof b, "%s on the %s machine, table %s: %.3f s of machine time\n",
                r.program.c_str(), r.machine.c_str(),
                r.table_crc == 0 ? "none" : tools::Hex32(r.table_crc).c_str(), r.duration_s);
  out << b;
  std::snprintf(b, sizeof b,
                "touched off at (%.3f, %.3f, %.3f) mm: work offset (%.3f, %.3f, %.3f) um\n",
                r.touch_off_mm[0], r.touch_off_mm[1], r.touch_off_mm[2], r.work_offset_um[0],
                r.work_offset_um[1], r.work_offset_um[2]);
  out << b;
  out << "line  kind      samples   max error\n";
  for (const LineFigures& l : r.lines) {
    std::snprintf(b, sizeof b, "%4d  %-8s %8llu  %8.3f um\n", l.line, SampleKindName(l.kind),
                  static_cast<unsigned long long>(l.samples), l.max_error_um);
    out << b;
  }
  std::snprintf(b, sizeof b,
                "tool point error against the programmed path: cutting max %.3f um, rms %.3f um; "
                "rapid max %.3f um; at rest max %.3f um\n",
                r.cutting_max_error_um, r.cutting_rms_error_um, r.rapid_max_error_um,
                r.rest_max_error_um);
  out << b;
  if (r.circular) {
    const metrology::CircularResult& c = *r.circular;
    std::snprintf(b, sizeof b,
                  "ballbar (ISO 230-4, %zu cw + %zu ccw readings): G cw %.2f um, G ccw %.2f um, "
                  "G(b) %.2f um, H %.2f um, F max %.2f um, F min %.2f um\n",
                  c.points_cw, c.points_ccw, c.G_cw_um, c.G_ccw_um, c.G_b_um, c.H_um, c.F_max_um,
                  c.F_min_um);
    out << b;
  }
  std::snprintf(b, sizeof b, "lost steps %llu (%llu rest checks), pulse timing violations %llu\n",
                static_cast<unsigned long long>(r.lost_steps),
                static_cast<unsigned long long>(r.rest_checks),
                static_cast<unsigned long long>(r.timing_violations));
  out << b;
}

Expected<int> RunProgramCommand(args::Args& args, Context& ctx) {
  const std::string machine = args.Value("--machine").value_or("ideal");
  const auto table = args.Value("--table");
  const auto seed = args.Integer("--seed");
  const auto report = args.Value("--report");
  const auto model = args.Value("--model");
  const bool json = args.Flag("--json");
  const auto ballbar = args.Value("--ballbar");
  const auto settings = args.Value("--settings");
  const std::vector<std::string> files = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  if (files.size() != 1) return UsageFailure("give one program file (PROGRAM.ngc)");
  ProgramRunOptions o;
  o.program_name = files[0];
  VOLCOMP_TRY_ASSIGN(o.program_text, tools::ReadTextFile(files[0]));
  if (machine != "ideal" && machine != "worn") {
    return UsageFailure("--machine must be ideal or worn");
  }
  o.worn = machine == "worn";
  if (seed) {
    if (*seed < 0) return UsageFailure("--seed must be >= 0");
    o.seed = static_cast<uint64_t>(*seed);
  }
  if (model) o.model_spec = *model;
  if (settings) {
    VOLCOMP_TRY_ASSIGN(o.settings_ini, tools::ReadTextFile(*settings));
    o.settings_source = *settings;
  }
  if (ballbar) {
    const auto p = tools::ParseTriple(*ballbar);
    if (!p) {
      return UsageFailure("--ballbar needs the pivot as X,Y,Z (mm), not \"" + *ballbar + "\"");
    }
    o.ballbar_pivot_mm = *p;
  }
  if (table) {
    VOLCOMP_TRY_ASSIGN(o.table_image, tools::ReadFileBytes(*table));
  }
  std::ostream& log = json ? ctx.err : ctx.out;
  VOLCOMP_TRY_ASSIGN(const ProgramRunResult r, RunProgramOnMachine(o, log));
  if (json) {
    tools::WriteJson(ResultJson(r), ctx.out);
  } else {
    PrintResult(r, ctx.out);
  }
  if (report) {
    VOLCOMP_TRY(WriteProgramRunReport(r, *report));
    std::ostringstream result_json;
    tools::WriteJson(ResultJson(r), result_json);
    VOLCOMP_TRY(tools::WriteTextFile(*report + "/result.json", result_json.str()));
    log << "report: " << *report << "/index.html, samples.csv, result.json"
        << (r.ballbar.empty() ? "" : ", ballbar.csv") << "\n";
  }
  if (r.lost_steps != 0 || r.timing_violations != 0) {
    ctx.err << "volcomp-sim run: " << r.lost_steps << " lost steps, " << r.timing_violations
            << " pulse timing violations\n";
    return 1;
  }
  return 0;
}

}  // namespace

const Command& RunCommand() {
  static const Command command{
      "run",
      "  run PROGRAM.ngc [--machine ideal|worn] [--table IMAGE] [--seed N] [--model s500|CONFIG]\n"
      "      [--settings BOARD.ini] [--ballbar X,Y,Z] [--report DIR] [--json]\n"
      "       a part program through the real firmware on the simulated machine: homing,\n"
      "       the table (if any) uploaded and activated, then the program; the tool point's\n"
      "       error against the programmed path along the whole program (G0-G4, G17-G19);\n"
      "       --settings: board settings over the simulator's (keys left out keep theirs);\n"
      "       --ballbar: a ballbar on a pivot at X,Y,Z reads every full circle about it\n"
      "       (ISO 230-4 G, G(b), H, F; with --report also ballbar.csv)\n",
      RunProgramCommand};
  return command;
}

}  // namespace volcomp::sim
