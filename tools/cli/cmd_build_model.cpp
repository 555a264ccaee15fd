// `volcomp build model`: a GRID3 image from the 21-parameter rigid-body model (or the
// dissertation's formulation of it), read from the built-in S500, a model config, an Etalon
// exchange file or ISG-CSV (datasets/model_file.hpp). Each node holds the correction that makes the
// command land the tool on the node (inverse of the model, iterated to ≤ 0.01 µm). See
// docs/table-builders.md.
#include "build_options.hpp"
#include "commands.hpp"
#include "grid_build.hpp"
#include "option_groups.hpp"

namespace volcomp::cli {
namespace {

Expected<Output> RunBuildModel(Args& args, Context&) {
  VOLCOMP_TRY_ASSIGN(const auto format, ParseModelFormat(args));
  ModelSource model_source;
  VOLCOMP_TRY_ASSIGN(const model::Model m, ParseModelOptions(args, format, &model_source));
  const builders::GridSource source = builders::ModelGridSource(m);
  VOLCOMP_TRY_ASSIGN(const GridCommand command, ParseGridCommand(args, source));
  VOLCOMP_TRY(args.Finish());
  VOLCOMP_TRY_ASSIGN(Output output, RunGridBuild(command, source, "volcomp build model"));
  for (const std::string& w : model_source.warnings) output.warnings.push_back(w);
  if (output.data.is_object()) output.data.Set("model", ModelSourceJson(model_source));
  return output;
}

}  // namespace

const Command& BuildModelCommand() {
  static const Command kCommand{"build model",
                                "GRID3 image from the 21-parameter error model (inverse map)",
                                "",
                                Join({ModelOptions(), ModelFormatOptions(), GridOptions()}),
                                RunBuildModel,
                                GridNotes()};
  return kCommand;
}

}  // namespace volcomp::cli
