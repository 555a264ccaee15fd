// `volcomp program positioning`, `volcomp program diagonal` and `volcomp program circular`: test
// programs as G-code (metrology/test_program.hpp, metrology/circular_program.hpp) on standard
// output or in files, and the readings templates the evaluate commands read back
// (metrology/readings_template.hpp).
#include <algorithm>
#include <cstdint>
#include <optional>
#include <ostream>
#include <sstream>
#include <utility>
#include <vector>

#include "choice_option.hpp"
#include "commands.hpp"
#include "file_arguments.hpp"
#include "option_groups.hpp"
#include "volcomp/metrology/circular_program.hpp"
#include "volcomp/metrology/diagonal.hpp"
#include "volcomp/metrology/readings_template.hpp"
#include "volcomp/metrology/test_program.hpp"
#include "volcomp/report/format.hpp"

namespace volcomp::cli {
namespace {

namespace m = volcomp::metrology;

using report::FormatFixed;
using report::FormatNumber;

Expected<m::Vec3> PointOption(const std::string& option, const std::string& text) {
  const auto p = tools::ParseTriple(text);
  if (!p) return UsageFailure(option + ": \"" + text + "\" is not X,Y,Z in mm");
  return m::Vec3{(*p)[0], (*p)[1], (*p)[2]};
}

// An integer option within 1..max (each has a default, so it is never absent).
Outcome InRange(const std::string& name, const std::optional<long long>& value, long long max) {
  if (value && *value >= 1 && *value <= max) return Outcome::Ok();
  return UsageFailure(name + " must be between 1 and " + std::to_string(max));
}

// A plan the metrology library cannot make is a usage failure: the options asked for it.
template <typename T>
Expected<T> AsUsage(Expected<T> r) {
  if (!r.ok()) return UsageFailure(r.error().message);
  return r;
}

std::string PointText(const m::Vec3& p) {
  return "(" + FormatNumber(p.x) + ", " + FormatNumber(p.y) + ", " + FormatNumber(p.z) + ")";
}

// The diagonal's name as written in the template's `diagonal` column: the N/P form for body
// diagonals (a spreadsheet takes "-X-Y-Z" for a formula), the signed form for face diagonals.
std::string TemplateDiagonalName(const m::DiagonalName& name) {
  if (!name.body) return "\"" + name.text + "\"";
  return m::DiagonalFileToken(name);
}

struct DiagonalProgram {
  m::DiagonalName name;
  m::DiagonalPlan plan;
  std::vector<m::CycleMove> moves;
  std::string gcode;
};

Expected<DiagonalProgram> PlanOne(const m::DiagonalName& name,
                                  const m::Vec3& p1,
                                  const m::Vec3& p2,
                                  double increment,
                                  int runs,
                                  double overrun,
                                  m::GcodeOptions g) {
  DiagonalProgram d;
  d.name = name;
  VOLCOMP_TRY_ASSIGN(d.plan, AsUsage(m::PlanDiagonal(p1, p2, increment)));
  VOLCOMP_TRY_ASSIGN(d.moves,
                     AsUsage(m::BuildCycle(d.plan.distances, m::Cycle::kLinear, runs, overrun)));
  const m::DiagonalPlan& plan = d.plan;
  g.axes = {"X", "Y", "Z"};
  g.origin = {plan.p1.x, plan.p1.y, plan.p1.z};
  g.direction = {plan.travel_mm.x / plan.length_mm, plan.travel_mm.y / plan.length_mm,
                 plan.travel_mm.z / plan.length_mm};
  g.title = "ISO 230-6 diagonal test " + name.text + " from " + PointText(p1) + " to " +
            PointText(p2) + " mm, D = " + FormatFixed(plan.length_mm, 3) +
            " mm, I_d = " + FormatFixed(plan.increment_mm, 3) + " mm (I_x " +
            FormatFixed(plan.axis_increment_mm.x, 4) + ", I_y " +
            FormatFixed(plan.axis_increment_mm.y, 4) + ", I_z " +
            FormatFixed(plan.axis_increment_mm.z, 4) + "), " + std::to_string(runs) +
            " runs, standard cycle of ISO 230-2";
  VOLCOMP_TRY_ASSIGN(d.gcode, m::EmitGcode(d.moves, g));
  return d;
}

std::string DiagonalTestLine(const DiagonalProgram& d, int runs) {
  return "ISO 230-6 diagonal " + d.name.text + " from " + PointText(d.plan.p1) + " to " +
         PointText(d.plan.p2) + " mm, D = " + FormatFixed(d.plan.length_mm, 3) +
         " mm, I_d = " + FormatFixed(d.plan.increment_mm, 3) + " mm, " + std::to_string(runs) +
         " runs";
}

// "diag.ngc" + "NNN" -> "diag_NNN.ngc".
std::string WithToken(const std::string& path, const std::string& token) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.rfind('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) {
    return path + "_" + token + ".ngc";
  }
  return path.substr(0, dot) + "_" + token + path.substr(dot);
}

// The TemplateOutput() options but --runs: the program's file, its readings template, the feed and
// the dwell.
struct ProgramOutputOptions {
  std::optional<double> feed, dwell;
  std::string out;
  std::optional<std::string> targets_csv;
  bool force = false;
  std::string units;  // --units: of the program written; the options stay in mm
};

// --units mm|in: G21 or G20, the program's coordinates and feed in mm or inches.
Expected<bool> ProgramInInches(const std::string& units) {
  return ParseChoice<bool>("--units", units, {{"mm", false}, {"in", true}});
}

// The --units option of the program commands.
OptionSpec UnitsOption() {
  return {"--units",
          nullptr,
          "mm|in",
          nullptr,
          "mm",
          "program in mm (G21) or inches (G20: coordinates and feed /25.4); the options stay in "
          "mm and mm/min"};
}

ProgramOutputOptions ReadProgramOutput(Args& args) {
  ProgramOutputOptions o;
  o.feed = args.Number("--feed");
  o.dwell = args.Number("--dwell-s");
  o.out = args.Value("--output", "-o").value_or("-");
  o.targets_csv = args.Value("--targets-csv");
  o.force = args.Flag("--force");
  o.units = args.Value("--units").value_or("mm");
  return o;
}

// After the command's own checks: --feed and --dwell-s into `g`; before anything is written, the
// template must not be the program, nor hold readings.
Outcome CheckProgramOutput(const ProgramOutputOptions& o, m::GcodeOptions* g) {
  g->feed = o.feed.value_or(0.0);
  g->dwell_s = o.dwell.value_or(0.0);
  if (!(g->feed > 0.0) || g->dwell_s < 0.0) {
    return UsageFailure("--feed must be positive, --dwell-s ≥ 0");
  }
  VOLCOMP_TRY_ASSIGN(g->inch, ProgramInInches(o.units));
  if (!o.targets_csv) return Outcome::Ok();
  if (*o.targets_csv == o.out) return UsageFailure("--targets-csv and -o name the same file");
  return m::RefuseToOverwriteReadings(*o.targets_csv, o.force);
}

// The feed and dwell of the program, as test conditions of its readings template (they reach the
// reports and the certificate through the preamble).
std::vector<std::pair<std::string, std::string>> FeedAndDwell(const m::GcodeOptions& g,
                                                              bool rotary) {
  return {{rotary ? "feed deg per min" : "feed mm per min", FormatNumber(g.feed)},
          {"dwell s", FormatNumber(g.dwell_s)}};
}

// The readings template to `path` ("-": standard output), refused when it holds readings.
Outcome WriteTemplate(const std::string& text, const std::string& path, bool force, Context& ctx) {
  if (path == "-") return WriteTextArgument(text, path, ctx);
  return m::WriteTemplate(text, path, force);
}

Expected<Output> RunProgramPositioning(Args& args, Context& ctx) {
  m::TargetPlan plan;
  plan.rotary = args.Flag("--rotary");
  const auto start = args.Number("--start");
  const auto end = args.Number("--end");
  const auto pitch = args.Number("--pitch");
  const auto count = args.Integer("--count");
  const auto seed = args.Integer("--seed");
  const auto fraction_digits = args.Integer("--fraction-digits");
  const auto runs_option = args.Integer("--runs");
  const std::string cycle = args.Value("--cycle").value_or("");
  const auto overrun = args.Number("--overrun");
  m::GcodeOptions g;
  const std::string axis = args.Value("--axis").value_or(plan.rotary ? "C" : "X");
  g.axes = {axis};
  const ProgramOutputOptions files = ReadProgramOutput(args);
  VOLCOMP_TRY(args.Finish());
  VOLCOMP_TRY(InRange("--count", count, 10000));
  VOLCOMP_TRY(InRange("--seed", seed, 2147483647));
  VOLCOMP_TRY(InRange("--fraction-digits", fraction_digits, 4));
  VOLCOMP_TRY(InRange("--runs", runs_option, 100));
  plan.count = static_cast<int>(*count);
  plan.seed = static_cast<std::uint32_t>(*seed);
  plan.fraction_digits = static_cast<int>(*fraction_digits);
  const int runs = static_cast<int>(*runs_option);
  if (!pitch) return UsageFailure("missing required option --pitch (largest repeating step P)");
  plan.start = start.value_or(0.0);
  if (!plan.rotary) {
    if (!end) return UsageFailure("missing required option --end");
    plan.end = *end;
  }
  plan.pitch = *pitch;
  VOLCOMP_TRY_ASSIGN(const m::Cycle cycle_kind,
                     ParseChoice<m::Cycle>(
                         "--cycle", cycle,
                         {{"linear", m::Cycle::kLinear}, {"pilgrim", m::Cycle::kPseudoPilgrim}}));
  VOLCOMP_TRY(CheckProgramOutput(files, &g));
  if (g.inch && plan.rotary) {
    return UsageFailure("--units in is for a linear axis: a rotary axis program is in degrees");
  }
  VOLCOMP_TRY_ASSIGN(const std::vector<double> targets, AsUsage(m::PlanGostTargets(plan)));
  VOLCOMP_TRY_ASSIGN(const std::vector<m::CycleMove> moves,
                     AsUsage(m::BuildCycle(targets, cycle_kind, runs, overrun.value_or(0.0))));
  std::string targets_text;
  for (double t : targets) targets_text += (targets_text.empty() ? "" : " ") + FormatFixed(t, 3);
  const std::string test = std::string("GOST 27843-88 positioning test, ") +
                           (cycle_kind == m::Cycle::kLinear ? "linear cycle (fig. 1)"
                                                            : "pseudo-pilgrim cycle (fig. 2)") +
                           ", " + std::to_string(runs) + " runs, seed " + std::to_string(plan.seed);
  g.title = test + ", targets " + targets_text;
  VOLCOMP_TRY_ASSIGN(const std::string gcode, m::EmitGcode(moves, g));
  VOLCOMP_TRY(WriteTextArgument(gcode, files.out, ctx));
  if (files.targets_csv) {
    m::TemplateHeader h;
    h.description = std::string(
                        "Readings template of volcomp program positioning. Enter each "
                        "reading in the last column (deviation = actual - target, in ") +
                    (plan.rotary ? "arc-seconds" : "µm") +
                    ") and the test conditions below; rows follow the program's measured stops.";
    h.known = {{"axis", axis}, {"test", test}};
    for (auto& kv : FeedAndDwell(g, plan.rotary)) h.known.push_back(std::move(kv));
    if (files.out != "-") h.known.emplace_back("program", files.out);
    const std::string header = std::string(plan.rotary ? "target_deg" : "target_mm") +
                               ",direction,run," +
                               (plan.rotary ? "deviation_arcsec" : "deviation_um") + "\n";
    VOLCOMP_TRY(WriteTemplate(m::TemplatePreamble(h) + header + m::TemplateRows(moves, ""),
                              *files.targets_csv, files.force, ctx));
  }
  return Output{};
}

// The four body diagonals of the box X0,Y0,Z0:X1,Y1,Z1, each from its start corner -X-Y-Z,
// +X-Y-Z, -X+Y-Z, +X+Y-Z to the opposite corner.
Expected<std::vector<std::pair<m::Vec3, m::Vec3>>> BoxDiagonals(const std::string& box) {
  const std::size_t colon = box.find(':');
  if (colon == std::string::npos) return UsageFailure("--box: expected X0,Y0,Z0:X1,Y1,Z1 in mm");
  VOLCOMP_TRY_ASSIGN(const m::Vec3 a, PointOption("--box", box.substr(0, colon)));
  VOLCOMP_TRY_ASSIGN(const m::Vec3 b, PointOption("--box", box.substr(colon + 1)));
  const m::Vec3 lo{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
  const m::Vec3 hi{std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
  if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z)) {
    return UsageFailure("--box: the corners must differ in X, Y and Z");
  }
  std::vector<std::pair<m::Vec3, m::Vec3>> out;
  for (const auto& [sx, sy] : {std::pair{-1, -1}, {1, -1}, {-1, 1}, {1, 1}}) {
    out.emplace_back(m::Vec3{sx < 0 ? lo.x : hi.x, sy < 0 ? lo.y : hi.y, lo.z},
                     m::Vec3{sx < 0 ? hi.x : lo.x, sy < 0 ? hi.y : lo.y, hi.z});
  }
  return out;
}

// The diagonal from --p1 to --p2, named by --name when given (checked against P1 -> P2).
Expected<m::DiagonalName> NameOf(const m::Vec3& from,
                                 const m::Vec3& to,
                                 const std::optional<std::string>& name_option) {
  const auto derived = m::DiagonalNameFor(from, to);
  if (!derived) return UsageFailure("--p1 and --p2 differ in fewer than two axes: not a diagonal");
  if (!name_option) return *derived;
  const auto given = m::ParseDiagonalName(*name_option);
  if (!given) {
    return UsageFailure("--name \"" + *name_option +
                        "\" is not a diagonal name (e.g. +X+Y-Z, PPN, +X-Y)");
  }
  if (const auto why = m::DiagonalNameMismatch(*given, from, to)) {
    return UsageFailure("--name " + *why);
  }
  return *given;
}

Expected<Output> RunProgramDiagonal(Args& args, Context& ctx) {
  const auto p1 = args.Value("--p1");
  const auto p2 = args.Value("--p2");
  const auto box = args.Value("--box");
  const auto inc = args.Number("--increment-mm");
  const auto runs_option = args.Integer("--runs");
  const auto overrun = args.Number("--overrun-mm");
  m::GcodeOptions g;
  const ProgramOutputOptions files = ReadProgramOutput(args);
  const auto name_option = args.Value("--name");
  VOLCOMP_TRY(args.Finish());
  VOLCOMP_TRY(InRange("--runs", runs_option, 100));
  const int runs = static_cast<int>(*runs_option);
  if (!inc) return UsageFailure("missing required option --increment-mm");
  if (box && (p1 || p2 || name_option)) {
    return UsageFailure("--box plans the four body diagonals: give it without --p1, --p2, --name");
  }
  if (!box && (!p1 || !p2)) return UsageFailure("give --p1 and --p2 (one diagonal) or --box");
  if (box && files.out == "-") {
    return UsageFailure(
        "--box writes four programs: give -o FILE.ngc (FILE_NNN.ngc, ... are written)");
  }
  VOLCOMP_TRY(CheckProgramOutput(files, &g));

  std::vector<DiagonalProgram> programs;
  if (box) {
    VOLCOMP_TRY_ASSIGN(const auto diagonals, BoxDiagonals(*box));
    for (const auto& [from, to] : diagonals) {
      VOLCOMP_TRY_ASSIGN(DiagonalProgram d, PlanOne(*m::DiagonalNameFor(from, to), from, to, *inc,
                                                    runs, overrun.value_or(0.0), g));
      programs.push_back(std::move(d));
    }
  } else {
    VOLCOMP_TRY_ASSIGN(const m::Vec3 from, PointOption("--p1", *p1));
    VOLCOMP_TRY_ASSIGN(const m::Vec3 to, PointOption("--p2", *p2));
    VOLCOMP_TRY_ASSIGN(const m::DiagonalName name, NameOf(from, to, name_option));
    VOLCOMP_TRY_ASSIGN(DiagonalProgram d,
                       PlanOne(name, from, to, *inc, runs, overrun.value_or(0.0), g));
    programs.push_back(std::move(d));
  }

  Output output;  // the four diagonals of a box share their warnings: each once
  for (const auto& d : programs) {
    for (const auto& w : d.plan.warnings) {
      if (std::find(output.warnings.begin(), output.warnings.end(), w) == output.warnings.end()) {
        output.warnings.push_back(w);
      }
    }
  }
  for (const auto& d : programs) {
    const std::string path = box ? WithToken(files.out, m::DiagonalFileToken(d.name)) : files.out;
    VOLCOMP_TRY(WriteTextArgument(d.gcode, path, ctx));
    if (box) ctx.err << "wrote " << path << " (diagonal " << d.name.text << ")\n";
  }
  if (files.targets_csv) {
    m::TemplateHeader h;
    h.description =
        "Readings template of volcomp program diagonal. Enter each reading in the last column "
        "(deviation along the diagonal = actual - target, in µm) and the test conditions below; "
        "target_mm is the distance from the diagonal's start corner.";
    h.omit = {"axis"};
    h.known = FeedAndDwell(g, false);
    for (const auto& d : programs) {
      h.known.emplace_back("diagonal " + m::DiagonalFileToken(d.name), DiagonalTestLine(d, runs));
    }
    std::string rows;
    for (const auto& d : programs) rows += m::TemplateRows(d.moves, TemplateDiagonalName(d.name));
    VOLCOMP_TRY(WriteTemplate(
        m::TemplatePreamble(h) + "diagonal,target_mm,direction,run,deviation_um\n" + rows,
        *files.targets_csv, files.force, ctx));
  }
  return output;
}

Expected<Output> RunProgramCircular(Args& args, Context& ctx) {
  m::CircularProgramOptions o;
  const std::string plane = args.Value("--plane").value_or("XY");
  const auto centre = args.Value("--centre");
  const auto radius = args.Number("--radius");
  const auto feed = args.Number("--feed");
  const auto start = args.Number("--start-angle-deg");
  const auto run = args.Number("--run-in-deg");
  o.pause = args.Flag("--pause");
  const std::string out = args.Value("--output", "-o").value_or("-");
  const std::string units = args.Value("--units").value_or("mm");
  VOLCOMP_TRY(args.Finish());
  VOLCOMP_TRY_ASSIGN(o.inch, ProgramInInches(units));
  VOLCOMP_TRY_ASSIGN(o.plane, ParseChoice<m::CircularPlane>("--plane", plane,
                                                            {{"XY", m::CircularPlane::kXY},
                                                             {"XZ", m::CircularPlane::kZX},
                                                             {"ZX", m::CircularPlane::kZX, false},
                                                             {"YZ", m::CircularPlane::kYZ}}));
  if (centre) {
    VOLCOMP_TRY_ASSIGN(const m::Vec3 c, PointOption("--centre", *centre));
    o.centre_mm = {c.x, c.y, c.z};
  }
  if (!radius) return UsageFailure("missing required option --radius");
  if (!(*radius > 0.0)) return UsageFailure("--radius must be positive");
  o.radius_mm = *radius;
  o.feed_mm_min = feed.value_or(1000.0);
  if (!(o.feed_mm_min > 0.0)) return UsageFailure("--feed must be positive");
  o.start_angle_deg = start.value_or(0.0);
  o.run_deg = run.value_or(90.0);
  if (!(o.run_deg > 0.0 && o.run_deg <= 180.0)) {
    return UsageFailure("--run-in-deg must be within (0, 180]");
  }
  VOLCOMP_TRY_ASSIGN(const std::string gcode, AsUsage(m::EmitCircularProgram(o)));
  VOLCOMP_TRY(WriteTextArgument(gcode, out, ctx));
  return Output{};
}

}  // namespace

const Command& ProgramPositioningCommand() {
  static const Command kCommand{
      "program positioning",
      "GOST 27843 test program: targets P_j=(N+r)P and G-code cycle",
      "",
      Join({{{"--pitch", nullptr, "P", "mm (deg with --rotary)", nullptr,
              "largest repeating step of the axis: screw pitch, scale period (required)"},
             {"--start", nullptr, "S", "mm (deg with --rotary)", "0",
              "first end of the measured travel"},
             {"--end", nullptr, "E", "mm", nullptr,
              "other end of the measured travel (required for a linear axis)"},
             {"--count", nullptr, "M", nullptr, "11", "number of target positions"},
             {"--seed", nullptr, "N", nullptr, "1", "seed of the random fractions r_j"},
             {"--fraction-digits", nullptr, "D", nullptr, "2", "digits of r_j, 1..4"},
             {"--rotary", nullptr, nullptr, nullptr, nullptr,
              "full-turn rotary axis (0°, 90°, 180°, 270° included)"},
             {"--cycle", nullptr, "linear|pilgrim", nullptr, "linear",
              "GOST fig. 1 linear cycle or fig. 2 pseudo-pilgrim"},
             {"--overrun", nullptr, "O", "mm (deg with --rotary)", "5",
              "travel beyond the end targets for the reversal"},
             {"--axis", nullptr, "NAME", nullptr, nullptr,
              "axis word of the G-code and of the template (default: X, C with --rotary)"},
             UnitsOption()},
            TemplateOutput()}),
      RunProgramPositioning,
      "The readings template names the axis in its preamble; `evaluate positioning` names the\n"
      "report after it. A template that already holds readings is not overwritten."};
  return kCommand;
}

const Command& ProgramDiagonalCommand() {
  static const Command kCommand{
      "program diagonal",
      "ISO 230-6 diagonal targets and G-code cycle (one diagonal or all four)",
      "",
      Join({{{"--p1", nullptr, "X,Y,Z", "mm", nullptr, "start point of one diagonal"},
             {"--p2", nullptr, "X,Y,Z", "mm", nullptr, "end point of that diagonal"},
             {"--box", nullptr, "X0,Y0,Z0:X1,Y1,Z1", "mm", nullptr,
              "instead of --p1/--p2: the four body diagonals of this box"},
             {"--increment-mm", nullptr, "I", "mm", nullptr,
              "target spacing along the diagonal (required)"},
             {"--name", nullptr, "+X+Y-Z", nullptr, nullptr,
              "diagonal name; checked against P1→P2 (default: derived from P1→P2)"},
             {"--overrun-mm", nullptr, "O", "mm", "5", "travel beyond the end targets"},
             UnitsOption()},
            TemplateOutput()}),
      RunProgramDiagonal,
      "A diagonal is named by its start corner (ISO 230-6): P1 at the low end of X and Y and\n"
      "the high end of Z is -X-Y+Z. With --box, -o FILE.ngc writes FILE_NNN.ngc, FILE_PNN.ngc,\n"
      "FILE_NPN.ngc and FILE_PPN.ngc (start corners -X-Y-Z, +X-Y-Z, -X+Y-Z, +X+Y-Z) and\n"
      "--targets-csv one template for all four, which `evaluate diagonal` reads."};
  return kCommand;
}

const Command& ProgramCircularCommand() {
  static const Command kCommand{
      "program circular",
      "ISO 230-4 circular test program: CCW and CW with run-in/run-out arcs (G-code)",
      "",
      {{"--radius", nullptr, "R", "mm", nullptr, "radius of the nominal circle (required)"},
       {"--centre", nullptr, "X,Y,Z", "mm", "0,0,0", "centre of the circle"},
       {"--plane", nullptr, "XY|XZ|YZ", nullptr, "XY", "plane of the circle (G17, G18, G19)"},
       {"--feed", nullptr, "F", "mm/min", "1000", "contouring feed"},
       {"--start-angle-deg", nullptr, "A", "deg", "0",
        "where each measured 360° begins (angle convention below)"},
       {"--run-in-deg", nullptr, "D", "deg", "90",
        "run-in and run-out arc before and after each measured 360°, (0, 180]"},
       {"--pause", nullptr, nullptr, nullptr, nullptr,
        "M0 at the start point (fit the ballbar, then cycle start)"},
       UnitsOption(),
       {"--output", "-o", "FILE", nullptr, "-", "G-code program to write (- = stdout)"}},
      RunProgramCircular,
      "The circle is run counter-clockwise (G3), then clockwise (G2): run-in arc, measured 360°,\n"
      "run-out arc, blended (G64), so the feed is constant over the measured circle. Angles, as\n"
      "`evaluate circular` reads them, count counter-clockwise from the plane's first axis: XY\n"
      "from +X towards +Y, XZ (G18) from +Z towards +X, YZ from +Y towards +Z."};
  return kCommand;
}

}  // namespace volcomp::cli
