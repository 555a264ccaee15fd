// `volcomp build model`: a GRID3 image from the 21-parameter rigid-body model (or the
// dissertation's formulation of it). Each node holds the correction that makes the command land
// the tool on the node (inverse of the model, iterated to ≤ 0.01 µm). See docs/table-builders.md.
#include <iostream>
#include <map>
#include <string>

#include "commands.hpp"
#include "volcomp/model/build_cli.hpp"
#include "volcomp/model/grid_source.hpp"

namespace volcomp::tools {

int RunBuildModel(Args& args) {
  const model::Model m = model::cli::ParseModelOptions(args);
  const model::GridSource source = model::ModelGridSource(m);
  model::cli::GridCommand cmd =
      model::cli::ParseGridCommand(args, source.min_mm, source.max_mm, source.natural_spacing_mm);
  args.finish();

  std::map<std::string, std::string> info = source.info;
  info.emplace("builder", "volcomp build model");
  if (!cmd.json) std::cout << "volcomp build model\n";
  return model::cli::RunGridBuild(cmd, source.inverse, source.forward_or_null(), info, std::cout);
}

}  // namespace volcomp::tools
