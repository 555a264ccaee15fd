// `volcomp build model`: a GRID3 image from the 21-parameter rigid-body model (or the
// dissertation's formulation of it). Each node holds the correction that makes the command land
// the tool on the node (inverse of the model, iterated to ≤ 0.01 µm). See docs/table-builders.md.
#include <algorithm>
#include <array>
#include <iostream>
#include <map>
#include <string>

#include "commands.hpp"
#include "volcomp/model/build_cli.hpp"
#include "volcomp/model/rigid_body.hpp"

namespace volcomp::tools {

int RunBuildModel(Args& args) {
  const model::Model m = model::cli::ParseModelOptions(args);
  std::array<double, 3> lo, hi, natural;
  for (std::size_t a = 0; a < 3; ++a) {
    const model::AxisErrorTable& t = m.axes[a];
    lo[a] = t.min_mm();
    hi[a] = t.max_mm();
    double h = t.uniform_spacing_mm();
    if (!(h > 0)) {  // irregular table: its smallest row gap
      h = t.max_mm() - t.min_mm();
      for (std::size_t i = 1; i < t.size(); ++i) {
        h = std::min(h, t.position_mm(i) - t.position_mm(i - 1));
      }
    }
    natural[a] = h;
  }
  model::cli::GridCommand cmd = model::cli::ParseGridCommand(args, lo, hi, natural);
  args.finish();

  const model::InverseMap inverse = [&m](const model::Vec3& t) {
    return model::SolveCommand(m, t).command_mm;
  };
  const model::ForwardMap forward = [&m](const model::Vec3& q) {
    return q + 1e-3 * model::ToolPointError_um(m, q);
  };
  const std::map<std::string, std::string> info = {
      {"builder", "volcomp build model"},
      {"model", m.name},
      {"formulation", model::cli::DescribeModel(m)},
  };
  if (!cmd.json) std::cout << "volcomp build model\n";
  return model::cli::RunGridBuild(cmd, inverse, &forward, info, std::cout);
}

}  // namespace volcomp::tools
