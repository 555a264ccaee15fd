// `volcomp model eval`: the forward error of a model at given points (or, with --inverse, the
// command that lands on each point), CSV in, CSV out, so models can be checked against one's own
// measurements. The rows are written as they are computed, to stdout or -o FILE.
//
// Input CSV (FILE or - for stdin): x_mm, y_mm, z_mm (extra columns ignored).
// Output CSV:
//   default:    x_mm,y_mm,z_mm,ex_um,ey_um,ez_um,e_um   (error = actual − nominal at the command)
//   --inverse:  x_mm,y_mm,z_mm,cmd_x_mm,cmd_y_mm,cmd_z_mm,dx_um,dy_um,dz_um,residual_um
#include <cstdio>
#include <fstream>
#include <ostream>
#include <string>

#include "build_options.hpp"
#include "commands.hpp"
#include "option_groups.hpp"
#include "volcomp/model/rigid_body.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::cli {
namespace {

// One output line for the point of `row`.
Expected<std::string> EvalLine(const model::Model& m,
                               bool inverse,
                               const tools::CsvTable& csv,
                               const tools::CsvRow& row) {
  tools::CsvFields f(row);
  const model::Vec3 p = {f.Number("x_mm"), f.Number("y_mm"), f.Number("z_mm")};
  VOLCOMP_TRY(f.status());
  char line[320];
  if (inverse) {
    const model::CommandSolution s = model::SolveCommand(m, p);
    if (!s.converged) {
      return Fail(csv.LineFailure(row.line(), "the model's inverse did not converge here"));
    }
    const model::Vec3 d = 1e3 * (s.command_mm - p);
    std::snprintf(line, sizeof(line), "%.6f,%.6f,%.6f,%.9f,%.9f,%.9f,%.6f,%.6f,%.6f,%.2e\n", p.x,
                  p.y, p.z, s.command_mm.x, s.command_mm.y, s.command_mm.z, d.x, d.y, d.z,
                  s.residual_um);
  } else {
    const model::Vec3 e = model::ToolPointError_um(m, p);
    std::snprintf(line, sizeof(line), "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n", p.x, p.y, p.z, e.x,
                  e.y, e.z, model::Norm(e));
  }
  return std::string(line);
}

Expected<Output> RunModelEval(Args& args, Context& ctx) {
  VOLCOMP_TRY_ASSIGN(const auto format, ParseModelFormat(args));
  ModelSource source;
  VOLCOMP_TRY_ASSIGN(const model::Model m, ParseModelOptions(args, format, &source));
  const bool inverse = args.Flag("--inverse");
  const auto out_path = args.Value("-o", "--output");
  const auto pos = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  if (pos.size() > 1) return UsageFailure("expected one points file (or - for stdin)");
  VOLCOMP_TRY_ASSIGN(const tools::CsvTable csv, pos.empty() || pos[0] == "-"
                                                    ? tools::CsvTable::Read(ctx.in, "<stdin>")
                                                    : tools::CsvTable::ReadFile(pos[0]));
  for (const char* c : {"x_mm", "y_mm", "z_mm"}) VOLCOMP_TRY(csv.Require(c));

  for (const std::string& w : source.warnings) ctx.err << "warning: " << w << "\n";
  std::ofstream file;
  if (out_path) {
    file.open(*out_path);
    if (!file) return Fail(Error::kIoError, *out_path + ": cannot write");
  }
  std::ostream& out = out_path ? file : ctx.out;
  out << (inverse ? "x_mm,y_mm,z_mm,cmd_x_mm,cmd_y_mm,cmd_z_mm,dx_um,dy_um,dz_um,residual_um\n"
                  : "x_mm,y_mm,z_mm,ex_um,ey_um,ez_um,e_um\n");
  for (const tools::CsvRow& row : csv.rows()) {
    VOLCOMP_TRY_ASSIGN(const std::string line, EvalLine(m, inverse, csv, row));
    out << line;
  }
  if (out_path) {
    file.close();
    if (!file) return Fail(Error::kIoError, *out_path + ": write failed");
  }
  return Output{};
}

}  // namespace

const Command& ModelEvalCommand() {
  static const Command kCommand{
      "model eval", "forward error (or --inverse command) of a model at points, CSV in/out",
      "[POINTS.csv|-]",
      Join({ModelOptions(),
            ModelFormatOptions(),
            {{"--inverse", nullptr, nullptr, nullptr, nullptr,
              "the command that lands on each point instead of the error"},
             {"--output", "-o", "FILE", nullptr, nullptr, "CSV to write (default: stdout)"}}}),
      RunModelEval};
  return kCommand;
}

}  // namespace volcomp::cli
