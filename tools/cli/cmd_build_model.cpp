// `volcomp build model`: a GRID3 image from the 21-parameter rigid-body model (or the
// dissertation's formulation of it). Each node holds the correction that makes the command land
// the tool on the node (inverse of the model, iterated to ≤ 0.01 µm). See docs/table-builders.md.
#include "build_options.hpp"
#include "commands.hpp"
#include "grid_build.hpp"
#include "option_groups.hpp"

namespace volcomp::cli {
namespace {

Expected<Output> RunBuildModel(Args& args, Context&) {
  VOLCOMP_TRY_ASSIGN(const model::Model m, ParseModelOptions(args));
  const builders::GridSource source = builders::ModelGridSource(m);
  VOLCOMP_TRY_ASSIGN(const GridCommand command, ParseGridCommand(args, source));
  VOLCOMP_TRY(args.Finish());
  return RunGridBuild(command, source, "volcomp build model");
}

}  // namespace

const Command& BuildModelCommand() {
  static const Command kCommand{"build model",
                                "GRID3 image from the 21-parameter error model (inverse map)",
                                "",
                                Join({ModelOptions(), GridOptions()}),
                                RunBuildModel,
                                GridNotes()};
  return kCommand;
}

}  // namespace volcomp::cli
