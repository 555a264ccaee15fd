// Command-line plumbing shared by `volcomp build model|tracker|kmtpp|axis` and `volcomp model
// eval`: the model source options, the grid/image options, building, writing and the report.
#pragma once

#include <array>
#include <map>
#include <ostream>
#include <string>

#include "volcomp/image/image_builder.hpp"
#include "volcomp/model/grid.hpp"
#include "volcomp/model/rigid_body.hpp"
#include "volcomp/tools/args.hpp"

namespace volcomp::model::cli {

/// `--model s500|FILE.conf` plus overrides --order first|exact, --formulation
/// physical|dissertation, --dissertation-case plus|minus, --angle-scale K, --tool-offset-mm X,Y,Z,
/// --no-squareness. Throws UsageError / InputError.
Model ParseModelOptions(tools::Args& args);

/// Parses "X=a,Y=b,Z=c" (any subset when `all_required` is false; missing = NaN), or one number
/// for all three axes.
std::array<double, 3> ParseXyzNumbers(const std::string& text,
                                      const std::string& option,
                                      bool all_required);

/// The common options of a grid build.
struct GridCommand {
  std::string output;
  image::ImageRequest request;  // axes X, Y, Z, element, frac bits, table id, --info entries
  GridBuildOptions grid;
  bool json = false;
};

/// Reads -o, --resolution-nm/--steps-per-unit, --range, --spacing-mm, --max-interp-error-um,
/// --max-correction-um, --element, --frac-bits, --table-id, --info, --json. The data's extent and
/// natural spacing are the defaults for --range and the spacing.
GridCommand ParseGridCommand(tools::Args& args,
                             const std::array<double, 3>& data_min_mm,
                             const std::array<double, 3>& data_max_mm,
                             const std::array<double, 3>& natural_spacing_mm);

/// Builds the grid (checks: bound, inverse residual, interpolation target), writes the image and
/// prints the report (text, or JSON with --json) to `out`. `info` describes the source and goes
/// into the image's INFO section and the report. Returns the process exit code.
int RunGridBuild(GridCommand& command,
                 const InverseMap& inverse,
                 const ForwardMap* forward,
                 const std::map<std::string, std::string>& info,
                 std::ostream& out);

/// Element type, frac bits, table id and --info entries (shared with `build axis`).
void ParseImageOptions(tools::Args& args, image::ImageRequest* request);

/// Human-readable name of a model's formulation/order/chain for reports.
std::string DescribeModel(const Model& model);

}  // namespace volcomp::model::cli
