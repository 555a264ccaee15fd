// The parsing of the option groups the table builders share (declared in option_groups.hpp): the
// error model (--model ...), the image options (--element ...) and the grid options (-o,
// --resolution-nm, --range, --spacing-mm, ...). Bad values are usage failures naming the option.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "board_fit.hpp"
#include "command.hpp"
#include "volcomp/builders/grid.hpp"
#include "volcomp/builders/grid_source.hpp"
#include "volcomp/datasets/model_file.hpp"
#include "volcomp/image/image_builder.hpp"
#include "volcomp/model/rigid_body.hpp"

namespace volcomp::cli {

/// Where the model came from: the file's format and what its reading warned about (the ISO 230-1
/// mapping names parameters taken as 0 or ignored; datasets/iso230_set.hpp).
struct ModelSource {
  std::string spec;      // --model's value
  std::string format;    // "builtin", "conf", "etalon" or "isg"
  bool detected = true;  // the format was recognised by content (false: --format)
  std::vector<std::string> warnings;
};

/// `--format conf|etalon|isg` of the commands that declare ModelFormatOptions() (`model export`:
/// `--model-format`); nullopt when absent (recognised by content).
Expected<std::optional<datasets::ModelFileFormat>> ParseModelFormat(
    Args& args, const std::string& option = "--format");

/// `--model s500|FILE` (a model config, an Etalon exchange file or ISG-CSV, recognised by content
/// unless `format` names it; datasets/model_file.hpp) plus the overrides --order first|exact,
/// --formulation physical|dissertation, --dissertation-case plus|minus, --angle-scale K,
/// --tool-offset-mm X,Y,Z, --no-squareness. A model file that cannot be read fails as its reader
/// does. `source` gets the format and the reader's warnings: the caller prints them.
Expected<model::Model> ParseModelOptions(Args& args,
                                         std::optional<datasets::ModelFileFormat> format,
                                         ModelSource* source);

/// The --json object of a ModelSource: spec, format, detected, warnings.
JsonValue ModelSourceJson(const ModelSource& source);

/// Parses "X=a,Y=b,Z=c" (any subset when `all_required` is false; missing = NaN), or one number
/// for all three axes.
Expected<std::array<double, 3>> ParseXyzNumbers(const std::string& text,
                                                const std::string& option,
                                                bool all_required);

/// The axes `names` with their step size from --resolution-nm or --steps-per-unit.
Expected<std::vector<image::AxisDef>> ParseAxisResolutions(Args& args,
                                                           const std::vector<char>& names);

/// --element, --frac-bits, --table-id and --info into `request` (shared with `build axis|grid`).
Outcome ParseImageOptions(Args& args, image::ImageRequest* request);

/// The options of a grid build.
struct GridCommand {
  std::string output;
  image::ImageRequest request;  // axes X, Y, Z, element, frac bits, table id, --info entries
  builders::GridBuildOptions grid;
  std::optional<BoardFileCheck> board;  // --board FILE: checked before the image is written
};

/// Reads -o, --resolution-nm/--steps-per-unit, --range, --spacing-mm, --max-interp-error-um,
/// --max-correction-um, the image options and --json (which the command layer acts on). The
/// source's extent and natural spacing are the defaults for --range and the spacing.
Expected<GridCommand> ParseGridCommand(Args& args, const builders::GridSource& source);

}  // namespace volcomp::cli
