// What the export commands share: the positioning test files per axis (--x FILE ... --w FILE,
// read as `evaluate positioning` reads them), per-axis numbers (--spacing X=S,...), and for the
// controller tables (export siemens / heidenhain / fanuc) the error table of each axis
// (exporters/error_table.hpp) from --spacing, --reference and --negate, with its JSON figures.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "option_groups.hpp"
#include "volcomp/datasets/positioning_file.hpp"
#include "volcomp/exporters/error_table.hpp"
#include "volcomp/metrology/positioning_data.hpp"
#include "volcomp/model/positioning.hpp"

namespace volcomp::cli {

struct AxisInput {
  char axis = 'X';   // X Y Z A B C U V W
  std::string path;  // the test file
};

/// The files of --x ... --w, in XYZABCUVW order; kUsage when there is none.
Expected<std::vector<AxisInput>> PositioningInputs(Args& args);

/// `option`'s "X=N,..." (absent: nullopt text): each axis's whole number in [min, max]; an axis
/// not named keeps `first` + its place in XYZABCUVW. Usage failure "OPTION: WHAT of X must be
/// MIN..MAX" otherwise (e.g. --joints, --axis-numbers).
Expected<std::map<char, int>> ParseAxisNumberMap(const std::optional<std::string>& text,
                                                 const std::string& option,
                                                 const std::string& what,
                                                 int first,
                                                 int min,
                                                 int max);

/// "X=1.5,Y=2" of `option` as numbers per axis (absent text: none); kUsage naming the option
/// and axis for a value that is not a number, or not > 0 when `positive`.
Expected<std::map<char, double>> ParseAxisNumbers(const std::optional<std::string>& text,
                                                  const std::string& option,
                                                  bool positive);

/// The positioning test in `path` (a CSV or a Renishaw .rtl, positioning_input.hpp) as every
/// export reads it, as mean deviations; its warnings go to ctx.err; `format` (when given) says
/// what the file held.
Expected<model::PositioningData> LoadAxisTest(const std::string& path,
                                              const datasets::PositioningReadOptions& read,
                                              const metrology::GroupingOptions& grouping,
                                              Context& ctx,
                                              datasets::PositioningFormat* format = nullptr);

/// --units mm|in: the machine's length unit (the unit of --spacing, --reference and the table
/// written), as an option list's entry and as its value (usage failure for another word).
/// `metric_only` (the controller and why its tables are in mm whatever the machine's unit):
/// only mm is taken, and the failure for `in` says why.
args::OptionSpec MachineUnitsOption(const char* metric_only = nullptr);
Expected<exporters::LengthUnit> ParseMachineUnits(Args& args, const char* metric_only = nullptr);

/// --units, --spacing, --reference and --negate of the controller tables.
Options ControllerTableOptions(const char* spacing_help,
                               const char* reference_help,
                               const char* metric_only = nullptr);

struct ControllerTableArgs {
  exporters::LengthUnit unit = exporters::LengthUnit::kMm;  // --units
  std::map<char, double> spacing;    // machine units (deg); absent: the test's own positions
  std::map<char, double> reference;  // machine units (deg); absent: none (or the default)
  bool negate = false;
  metrology::GroupingOptions grouping;
  datasets::PositioningReadOptions read;  // --format, --rtl-*, --accept-units
};

/// Reads the options of ControllerTableOptions (with the same `metric_only`), AllowFewRuns and
/// PositioningFormatOptions.
Expected<ControllerTableArgs> ReadControllerTableArgs(Args& args,
                                                      const char* metric_only = nullptr);

struct AxisErrorTable {
  AxisInput input;
  exporters::ErrorTable table;
};

/// The error table of one axis; failures (kInputInvalid) are prefixed with the file. Where
/// --reference names no position for the axis, `reference_at_first` makes the first test
/// position the reference (otherwise the table is not zeroed).
Expected<AxisErrorTable> LoadAxisErrorTable(const AxisInput& input,
                                            const ControllerTableArgs& options,
                                            Context& ctx,
                                            bool reference_at_first = false);

/// The figures of an error table: points, from, to, spacing, bidirectional, reference, negated,
/// uncovered (the tested travel past the last point), the largest |error| in µm (arcsec).
JsonValue ErrorTableJson(const AxisErrorTable& axis);

/// One line per axis of ErrorTableJson for the text layouts ("  axis X: 11 points ...").
std::string ErrorTableText(const JsonValue& axis);

/// A warning for a table that stops short of the tested travel (resampling), or "" .
std::string UncoveredWarning(const AxisErrorTable& axis);

}  // namespace volcomp::cli
