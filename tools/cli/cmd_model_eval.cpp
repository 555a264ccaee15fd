// `volcomp model eval`: the forward error of a model at given points (or, with --inverse, the
// command that lands on each point), CSV in, CSV out, so models can be checked against one's own
// measurements.
//
// Input CSV (FILE or - for stdin): x_mm, y_mm, z_mm (extra columns ignored).
// Output CSV (stdout or -o FILE):
//   default:    x_mm,y_mm,z_mm,ex_um,ey_um,ez_um,e_um   (error = actual − nominal at the command)
//   --inverse:  x_mm,y_mm,z_mm,cmd_x_mm,cmd_y_mm,cmd_z_mm,dx_um,dy_um,dz_um,residual_um
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "commands.hpp"
#include "volcomp/model/build_cli.hpp"
#include "volcomp/model/rigid_body.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::tools {

int RunModelEval(Args& args) {
  const model::Model m = model::cli::ParseModelOptions(args);
  const bool inverse = args.flag("--inverse");
  const auto out_path = args.value("-o", "--output");
  const auto pos = args.positionals();
  args.finish();
  if (pos.size() > 1) throw UsageError("expected one points file (or - for stdin)");
  const CsvTable csv = pos.empty() || pos[0] == "-" ? CsvTable::Parse(std::cin, "<stdin>")
                                                    : CsvTable::ParseFile(pos[0]);
  for (const char* c : {"x_mm", "y_mm", "z_mm"}) csv.require(c);

  std::ofstream file;
  if (out_path) {
    file.open(*out_path);
    if (!file) throw InputError(*out_path + ": cannot write");
  }
  std::ostream& out = out_path ? file : std::cout;
  out << (inverse ? "x_mm,y_mm,z_mm,cmd_x_mm,cmd_y_mm,cmd_z_mm,dx_um,dy_um,dz_um,residual_um\n"
                  : "x_mm,y_mm,z_mm,ex_um,ey_um,ez_um,e_um\n");
  char line[320];
  for (const CsvRow& row : csv.rows()) {
    const model::Vec3 p = {row.number("x_mm"), row.number("y_mm"), row.number("z_mm")};
    if (inverse) {
      const model::CommandSolution s = model::SolveCommand(m, p);
      if (!s.converged) throw csv.error(row.line(), "the model's inverse did not converge here");
      const model::Vec3 d = 1e3 * (s.command_mm - p);
      std::snprintf(line, sizeof(line), "%.6f,%.6f,%.6f,%.9f,%.9f,%.9f,%.6f,%.6f,%.6f,%.2e\n", p.x,
                    p.y, p.z, s.command_mm.x, s.command_mm.y, s.command_mm.z, d.x, d.y, d.z,
                    s.residual_um);
    } else {
      const model::Vec3 e = model::ToolPointError_um(m, p);
      std::snprintf(line, sizeof(line), "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n", p.x, p.y, p.z, e.x,
                    e.y, e.z, model::Norm(e));
    }
    out << line;
  }
  if (out_path && !file) throw InputError(*out_path + ": write failed");
  return 0;
}

}  // namespace volcomp::tools
