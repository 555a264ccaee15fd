// What the export commands share: the positioning test files per axis (--x FILE ... --w FILE,
// read as `evaluate positioning` reads them), per-axis numbers (--spacing X=S,...), and for the
// controller tables (export siemens / heidenhain / fanuc) the error table of each axis
// (exporters/error_table.hpp) from --spacing, --reference and --negate, with its JSON figures.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "option_groups.hpp"
#include "volcomp/datasets/positioning_file.hpp"
#include "volcomp/exporters/error_table.hpp"
#include "volcomp/metrology/positioning_data.hpp"
#include "volcomp/model/positioning.hpp"
#include "volcomp/model/rigid_body.hpp"

namespace volcomp::cli {

struct AxisInput {
  char axis = 'X';          // X Y Z A B C U V W
  std::string path;         // the test file, or with from_model the model (a file or "s500")
  bool from_model = false;  // the model's error of this linear axis (X, Y or Z), in direction
  char direction = 0;       // `direction` (0: the axis's own, the positioning error E_XX ...;
                            // another axis: the straightness, 'Y' for E_YX)
  std::shared_ptr<const model::Model> model;  // from_model: the model read (LoadModels)
};

/// --model s500|FILE: a 21-parameter model (model config, Etalon, ISG-CSV) as the source of the
/// X, Y, Z tables no --x/--y/--z file gives (its positioning errors E_XX, E_YY, E_ZZ, one
/// direction).
args::OptionSpec ModelAxesOption();

/// The files of --x ... --w, in XYZABCUVW order, and with `model_axes` the --model's X, Y, Z
/// for the linear axes no file gives; kUsage when there is none.
Expected<std::vector<AxisInput>> PositioningInputs(Args& args, bool model_axes = false);

/// The model `name` names: "s500" (the built-in one) or a model file of any format; the
/// reader's warnings go to ctx.err.
Expected<model::Model> LoadModelArgument(const std::string& name, Context& ctx);

/// Reads the model of every from_model input once (its warnings said once) into its `model`.
Expected<void> LoadModels(std::vector<AxisInput>* inputs, Context& ctx);

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

/// The positioning test of `input` as every export reads it, as mean deviations: the file (a CSV
/// or a Renishaw .rtl, positioning_input.hpp; `format`, when given, says which), or the model's
/// error function (input.from_model: one direction, at the model's positions); warnings go to
/// ctx.err.
Expected<model::PositioningData> LoadAxisTest(const AxisInput& input,
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
