// `volcomp program positioning` and `volcomp program diagonal`: test programs as G-code.
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "commands.hpp"
#include "volcomp/metrology/cli_support.hpp"
#include "volcomp/metrology/diagonal.hpp"
#include "volcomp/metrology/test_program.hpp"
#include "volcomp/report/format.hpp"

namespace volcomp::tools {

namespace m = volcomp::metrology;

namespace {

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

int PositiveInt(Args& args, const std::string& name, long long fallback, long long max) {
  const long long v = args.integer(name).value_or(fallback);
  if (v < 1 || v > max) {
    throw UsageError(name + " must be between 1 and " + std::to_string(max));
  }
  return static_cast<int>(v);
}

// A blank long-layout CSV listing the measured stops in program order, for the operator.
std::string TargetsTemplate(const std::vector<m::CycleMove>& moves,
                            const std::string& diagonal,
                            const char* target_col,
                            const char* value_col) {
  std::ostringstream s;
  s << "# fill in the last column; rows follow the order of the measured stops of the program\n";
  if (!diagonal.empty()) s << "diagonal,";
  s << target_col << ",direction,run," << value_col << "\n";
  for (const auto& mv : moves) {
    if (!mv.measure) continue;
    if (!diagonal.empty()) s << "\"" << diagonal << "\",";
    s << report::FormatFixed(mv.position, 3) << "," << m::DirectionName(mv.approach) << ","
      << mv.run << ",\n";
  }
  return s.str();
}

}  // namespace

int RunProgramPositioning(Args& args) {
  m::TargetPlan plan;
  plan.rotary = args.flag("--rotary");
  const auto start = args.number("--start");
  const auto end = args.number("--end");
  const auto pitch = args.number("--pitch");
  plan.count = PositiveInt(args, "--count", 11, 10000);
  plan.seed = static_cast<std::uint32_t>(PositiveInt(args, "--seed", 1, 2147483647));
  plan.fraction_digits = PositiveInt(args, "--fraction-digits", 2, 4);
  const int runs = PositiveInt(args, "--runs", 5, 100);
  const std::string cycle = args.value("--cycle").value_or("linear");
  const double overrun = args.number("--overrun").value_or(plan.rotary ? 5.0 : 5.0);
  m::GcodeOptions g;
  g.axes = {args.value("--axis").value_or(plan.rotary ? "C" : "X")};
  g.feed = args.number("--feed").value_or(1000.0);
  g.dwell_s = args.number("--dwell-s").value_or(2.0);
  const std::string out = args.value("-o", "--output").value_or("-");
  const auto targets_csv = args.value("--targets-csv");
  args.finish();
  if (!pitch) throw UsageError("missing required option --pitch (largest repeating step P)");
  plan.start = start.value_or(0.0);
  if (!plan.rotary) {
    if (!end) throw UsageError("missing required option --end");
    plan.end = *end;
  }
  plan.pitch = *pitch;
  if (cycle != "linear" && cycle != "pilgrim")
    throw UsageError("--cycle must be linear or pilgrim");
  if (!(g.feed > 0.0) || g.dwell_s < 0.0)
    throw UsageError("--feed must be positive, --dwell-s ≥ 0");
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
  for (double t : targets)
    targets_text += (targets_text.empty() ? "" : " ") + report::FormatFixed(t, 3);
  g.title = std::string("GOST 27843-88 positioning test, ") +
            (cycle == "linear" ? "linear cycle (fig. 1)" : "pseudo-pilgrim cycle (fig. 2)") + ", " +
            std::to_string(runs) + " runs, seed " + std::to_string(plan.seed) + ", targets " +
            targets_text;
  m::WriteTextOutput(m::EmitGcode(moves, g), out, std::cout);
  if (targets_csv) {
    m::WriteTextOutput(TargetsTemplate(moves, "", plan.rotary ? "target_deg" : "target_mm",
                                       plan.rotary ? "deviation_arcsec" : "deviation_um"),
                       *targets_csv, std::cout);
  }
  return 0;
}

int RunProgramDiagonal(Args& args) {
  const auto p1 = args.value("--p1");
  const auto p2 = args.value("--p2");
  const auto inc = args.number("--increment-mm");
  const int runs = PositiveInt(args, "--runs", 5, 100);
  const double overrun = args.number("--overrun-mm").value_or(5.0);
  m::GcodeOptions g;
  g.feed = args.number("--feed").value_or(1000.0);
  g.dwell_s = args.number("--dwell-s").value_or(2.0);
  const std::string name = args.value("--name").value_or("");
  const std::string out = args.value("-o", "--output").value_or("-");
  const auto targets_csv = args.value("--targets-csv");
  args.finish();
  if (!p1 || !p2 || !inc) throw UsageError("--p1, --p2 and --increment-mm are required");
  if (!name.empty() && !m::ParseDiagonalName(name)) {
    throw UsageError("--name \"" + name + "\" is not a diagonal name (e.g. +X+Y-Z, PPN, +X-Y)");
  }
  if (!(g.feed > 0.0) || g.dwell_s < 0.0)
    throw UsageError("--feed must be positive, --dwell-s ≥ 0");
  m::DiagonalPlan plan;
  std::vector<m::CycleMove> moves;
  try {
    plan = m::PlanDiagonal(ParsePoint("--p1", *p1), ParsePoint("--p2", *p2), *inc);
    moves = m::BuildCycle(plan.distances, m::Cycle::kLinear, runs, overrun);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  m::PrintWarnings(std::cerr, plan.warnings);
  g.axes = {"X", "Y", "Z"};
  g.origin = {plan.p1.x, plan.p1.y, plan.p1.z};
  g.direction = {plan.travel_mm.x / plan.length_mm, plan.travel_mm.y / plan.length_mm,
                 plan.travel_mm.z / plan.length_mm};
  g.title = "ISO 230-6 diagonal test " + (name.empty() ? std::string() : name + " ") +
            "D = " + report::FormatFixed(plan.length_mm, 3) +
            " mm, I_d = " + report::FormatFixed(plan.increment_mm, 3) + " mm (I_x " +
            report::FormatFixed(plan.axis_increment_mm.x, 4) + ", I_y " +
            report::FormatFixed(plan.axis_increment_mm.y, 4) + ", I_z " +
            report::FormatFixed(plan.axis_increment_mm.z, 4) + "), " + std::to_string(runs) +
            " runs, standard cycle of ISO 230-2";
  m::WriteTextOutput(m::EmitGcode(moves, g), out, std::cout);
  if (targets_csv) {
    m::WriteTextOutput(
        TargetsTemplate(moves, name.empty() ? "?" : name, "target_mm", "deviation_um"),
        *targets_csv, std::cout);
  }
  return 0;
}

}  // namespace volcomp::tools
