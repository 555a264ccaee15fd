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
#include "volcomp/image/image_builder.hpp"
#include "volcomp/model/rigid_body.hpp"

namespace volcomp::cli {

/// `--model s500|FILE.conf` plus the overrides --order first|exact, --formulation
/// physical|dissertation, --dissertation-case plus|minus, --angle-scale K, --tool-offset-mm X,Y,Z,
/// --no-squareness. A model file that cannot be read fails as datasets::LoadModelConfig does.
Expected<model::Model> ParseModelOptions(Args& args);

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
