// `volcomp program positioning` and `volcomp program diagonal`: test programs as G-code, and the
// readings templates the evaluate commands read back.
#include <algorithm>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "commands.hpp"
#include "volcomp/metrology/cli_support.hpp"
#include "volcomp/metrology/diagonal.hpp"
#include "volcomp/metrology/readings_template.hpp"
#include "volcomp/metrology/test_program.hpp"
#include "volcomp/report/format.hpp"

namespace volcomp::tools {

namespace m = volcomp::metrology;

namespace {

using report::FormatFixed;
using report::FormatNumber;

m::Vec3 ParsePoint(const std::string& option, const std::string& text) {
  std::vector<double> v;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, ',')) {
    const auto d = ParseDouble(part);
    if (!d) throw UsageError(option + ": \"" + text + "\" is not X,Y,Z in mm");
    v.push_back(*d);
  }
  if (v.size() != 3) throw UsageError(option + ": \"" + text + "\" is not X,Y,Z in mm");
  return {v[0], v[1], v[2]};
}

int PositiveInt(Args& args, const std::string& name, long long max) {
  const long long v = args.integer(name).value();
  if (v < 1 || v > max) {
    throw UsageError(name + " must be between 1 and " + std::to_string(max));
  }
  return static_cast<int>(v);
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

DiagonalProgram PlanOne(const m::DiagonalName& name,
                        const m::Vec3& p1,
                        const m::Vec3& p2,
                        double increment,
                        int runs,
                        double overrun,
                        m::GcodeOptions g) {
  DiagonalProgram d;
  d.name = name;
  try {
    d.plan = m::PlanDiagonal(p1, p2, increment);
    d.moves = m::BuildCycle(d.plan.distances, m::Cycle::kLinear, runs, overrun);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
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
  d.gcode = m::EmitGcode(d.moves, g);
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

// Before anything is written: the template must not be the program, nor hold readings.
void CheckTemplatePath(const std::optional<std::string>& targets_csv,
                       const std::string& out,
                       bool force) {
  if (!targets_csv) return;
  if (*targets_csv == out) throw UsageError("--targets-csv and -o name the same file");
  m::RefuseToOverwriteReadings(*targets_csv, force);
}

}  // namespace

int RunProgramPositioning(Args& args) {
  m::TargetPlan plan;
  plan.rotary = args.flag("--rotary");
  const double start = args.number("--start").value();
  const auto end = args.number("--end");
  const auto pitch = args.number("--pitch");
  plan.count = PositiveInt(args, "--count", 10000);
  plan.seed = static_cast<std::uint32_t>(PositiveInt(args, "--seed", 2147483647));
  plan.fraction_digits = PositiveInt(args, "--fraction-digits", 4);
  const int runs = PositiveInt(args, "--runs", 100);
  const std::string cycle = args.value("--cycle").value();
  const double overrun = args.number("--overrun").value();
  m::GcodeOptions g;
  const std::string axis = args.value("--axis").value_or(plan.rotary ? "C" : "X");
  g.axes = {axis};
  g.feed = args.number("--feed").value();
  g.dwell_s = args.number("--dwell-s").value();
  const std::string out = args.value("-o", "--output").value();
  const auto targets_csv = args.value("--targets-csv");
  const bool force = args.flag("--force");
  args.finish();
  if (!pitch) throw UsageError("missing required option --pitch (largest repeating step P)");
  plan.start = start;
  if (!plan.rotary) {
    if (!end) throw UsageError("missing required option --end");
    plan.end = *end;
  }
  plan.pitch = *pitch;
  if (cycle != "linear" && cycle != "pilgrim")
    throw UsageError("--cycle must be linear or pilgrim");
  if (!(g.feed > 0.0) || g.dwell_s < 0.0)
    throw UsageError("--feed must be positive, --dwell-s ≥ 0");
  CheckTemplatePath(targets_csv, out, force);
  std::vector<double> targets;
  std::vector<m::CycleMove> moves;
  try {
    targets = m::PlanGostTargets(plan);
    moves = m::BuildCycle(targets, cycle == "linear" ? m::Cycle::kLinear : m::Cycle::kPseudoPilgrim,
                          runs, overrun);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  std::string targets_text;
  for (double t : targets) targets_text += (targets_text.empty() ? "" : " ") + FormatFixed(t, 3);
  const std::string test =
      std::string("GOST 27843-88 positioning test, ") +
      (cycle == "linear" ? "linear cycle (fig. 1)" : "pseudo-pilgrim cycle (fig. 2)") + ", " +
      std::to_string(runs) + " runs, seed " + std::to_string(plan.seed);
  g.title = test + ", targets " + targets_text;
  m::WriteTextOutput(m::EmitGcode(moves, g), out, std::cout);
  if (targets_csv) {
    m::TemplateHeader h;
    h.description = std::string(
                        "Readings template of volcomp program positioning. Enter each "
                        "reading in the last column (deviation = actual - target, in ") +
                    (plan.rotary ? "arc-seconds" : "µm") +
                    ") and the test conditions below; rows follow the program's measured stops.";
    h.known = {{"axis", axis}, {"test", test}};
    if (out != "-") h.known.emplace_back("program", out);
    const std::string header = std::string(plan.rotary ? "target_deg" : "target_mm") +
                               ",direction,run," +
                               (plan.rotary ? "deviation_arcsec" : "deviation_um") + "\n";
    m::WriteTemplate(m::TemplatePreamble(h) + header + m::TemplateRows(moves, ""), *targets_csv,
                     force, std::cout);
  }
  return kExitOk;
}

int RunProgramDiagonal(Args& args) {
  const auto p1 = args.value("--p1");
  const auto p2 = args.value("--p2");
  const auto box = args.value("--box");
  const auto inc = args.number("--increment-mm");
  const int runs = PositiveInt(args, "--runs", 100);
  const double overrun = args.number("--overrun-mm").value();
  m::GcodeOptions g;
  g.feed = args.number("--feed").value();
  g.dwell_s = args.number("--dwell-s").value();
  const auto name_option = args.value("--name");
  const std::string out = args.value("-o", "--output").value();
  const auto targets_csv = args.value("--targets-csv");
  const bool force = args.flag("--force");
  args.finish();
  if (!inc) throw UsageError("missing required option --increment-mm");
  if (box && (p1 || p2 || name_option)) {
    throw UsageError("--box plans the four body diagonals: give it without --p1, --p2, --name");
  }
  if (!box && (!p1 || !p2)) throw UsageError("give --p1 and --p2 (one diagonal) or --box");
  if (box && out == "-") {
    throw UsageError(
        "--box writes four programs: give -o FILE.ngc (FILE_NNN.ngc, ... are written)");
  }
  if (!(g.feed > 0.0) || g.dwell_s < 0.0)
    throw UsageError("--feed must be positive, --dwell-s ≥ 0");
  CheckTemplatePath(targets_csv, out, force);

  std::vector<DiagonalProgram> programs;
  if (box) {
    const std::size_t colon = box->find(':');
    if (colon == std::string::npos) throw UsageError("--box: expected X0,Y0,Z0:X1,Y1,Z1 in mm");
    const m::Vec3 a = ParsePoint("--box", box->substr(0, colon));
    const m::Vec3 b = ParsePoint("--box", box->substr(colon + 1));
    const m::Vec3 lo{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
    const m::Vec3 hi{std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
    if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z)) {
      throw UsageError("--box: the corners must differ in X, Y and Z");
    }
    // Start corners -X-Y-Z, +X-Y-Z, -X+Y-Z, +X+Y-Z, each to the opposite corner.
    for (const auto& [sx, sy] : {std::pair{-1, -1}, {1, -1}, {-1, 1}, {1, 1}}) {
      const m::Vec3 from{sx < 0 ? lo.x : hi.x, sy < 0 ? lo.y : hi.y, lo.z};
      const m::Vec3 to{sx < 0 ? hi.x : lo.x, sy < 0 ? hi.y : lo.y, hi.z};
      programs.push_back(PlanOne(*m::DiagonalNameFor(from, to), from, to, *inc, runs, overrun, g));
    }
  } else {
    const m::Vec3 from = ParsePoint("--p1", *p1);
    const m::Vec3 to = ParsePoint("--p2", *p2);
    const auto derived = m::DiagonalNameFor(from, to);
    if (!derived) {
      throw UsageError("--p1 and --p2 differ in fewer than two axes: not a diagonal");
    }
    m::DiagonalName name = *derived;
    if (name_option) {
      const auto given = m::ParseDiagonalName(*name_option);
      if (!given) {
        throw UsageError("--name \"" + *name_option +
                         "\" is not a diagonal name (e.g. +X+Y-Z, PPN, +X-Y)");
      }
      if (const auto why = m::DiagonalNameMismatch(*given, from, to)) {
        throw UsageError("--name " + *why);
      }
      name = *given;
    }
    programs.push_back(PlanOne(name, from, to, *inc, runs, overrun, g));
  }

  std::vector<std::string> warnings;  // the four diagonals of a box share their warnings
  for (const auto& d : programs) {
    for (const auto& w : d.plan.warnings) {
      if (std::find(warnings.begin(), warnings.end(), w) == warnings.end()) warnings.push_back(w);
    }
  }
  m::PrintWarnings(std::cerr, warnings);
  for (const auto& d : programs) {
    const std::string path = box ? WithToken(out, m::DiagonalFileToken(d.name)) : out;
    m::WriteTextOutput(d.gcode, path, std::cout);
    if (box) std::cerr << "wrote " << path << " (diagonal " << d.name.text << ")\n";
  }
  if (targets_csv) {
    m::TemplateHeader h;
    h.description =
        "Readings template of volcomp program diagonal. Enter each reading in the last column "
        "(deviation along the diagonal = actual - target, in µm) and the test conditions below; "
        "target_mm is the distance from the diagonal's start corner.";
    h.omit = {"axis"};
    for (const auto& d : programs) {
      h.known.emplace_back("diagonal " + m::DiagonalFileToken(d.name), DiagonalTestLine(d, runs));
    }
    std::string rows;
    for (const auto& d : programs) rows += m::TemplateRows(d.moves, TemplateDiagonalName(d.name));
    m::WriteTemplate(
        m::TemplatePreamble(h) + "diagonal,target_mm,direction,run,deviation_um\n" + rows,
        *targets_csv, force, std::cout);
  }
  return kExitOk;
}

}  // namespace volcomp::tools
