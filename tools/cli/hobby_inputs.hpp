// What the hobby controller exports share (export klipper / marlin / reprap / grblhal): the
// squareness per plane from a 21-parameter model file (--model: config, Etalon or ISG-CSV; its
// C0Y, B0Z, A0Z) and/or --squareness-xy-urad / -xz- / -yz- (volcomp's convention,
// exporters/hobby_common.hpp; an option replaces the model's value of its plane, and the file and
// JSON name the source), and the backlash per axis from positioning tests (--x FILE ... read as
// every export reads them, export_axes.hpp). Their JSON figures and text lines.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "export_axes.hpp"
#include "option_groups.hpp"
#include "volcomp/exporters/hobby_common.hpp"

namespace volcomp::cli {

/// Beyond 0.1 rad (5.7 deg) a squareness is taken for a unit mistake (mrad, deg), not a machine:
/// refused.
inline constexpr double kMaxSquarenessUrad = 100000;

/// --model FILE and --squareness-xy-urad / -xz- / -yz-.
const Options& SquarenessOptions();
/// The positioning files (--x ... --w), --allow-few-runs, the file-format options and
/// --negate-tests.
Options BacklashOptions();

struct HobbyArgs {
  std::optional<std::string> model;  // --model FILE
  std::optional<double> xy_urad, xz_urad, yz_urad;
  std::vector<AxisInput> tests;  // may be empty
  datasets::PositioningReadOptions read;
  metrology::GroupingOptions grouping;
  bool negate_tests = false;
};

/// Reads the options of SquarenessOptions (when `squareness`) and BacklashOptions (when
/// `backlash`); a usage failure for a squareness that is not a number.
Expected<HobbyArgs> ReadHobbyArgs(Args& args, bool squareness, bool backlash);

/// The squareness per plane: the model's, replaced by an option where given. Refused
/// (kInputInvalid) beyond ±kMaxSquarenessUrad, naming the plane, value and limit; the model
/// reader's warnings go to ctx.err.
Expected<exporters::HobbySquareness> LoadSquareness(const HobbyArgs& a, Context& ctx);

/// The backlash of every axis test (kInputInvalid naming the file for a one-direction test).
Expected<std::vector<exporters::AxisBacklash>> LoadBacklash(const HobbyArgs& a, Context& ctx);

struct HobbyInputs {
  exporters::HobbySquareness squareness;
  std::vector<exporters::AxisBacklash> backlash;
};

/// LoadSquareness and LoadBacklash of a command that takes both; a usage failure when neither a
/// squareness nor a test was given.
Expected<HobbyInputs> LoadHobbyInputs(const HobbyArgs& a, Context& ctx);

/// The JSON of a command that takes both: firmware, output, negated, squareness (with the
/// firmware's `value_key` values), backlash.
JsonValue HobbyJson(const char* firmware,
                    const std::string& output,
                    bool negated,
                    const HobbyInputs& in,
                    const exporters::SkewValues& values,
                    const char* value_key);

/// {"xy": {"c0y_urad", "source", `value_key`}, ...} of the planes given; `values` the firmware's.
JsonValue SquarenessJson(const exporters::HobbySquareness& s,
                         const exporters::SkewValues& values,
                         const char* value_key);

/// [{"axis", "source", "rotary", "targets", "backlash_um", "reversal_mean_um",
/// "reversal_max_um", "spread_um", "test_negated", "value" (file unit), "unit"}].
JsonValue BacklashJson(const std::vector<exporters::AxisBacklash>& b);

/// Text lines of SquarenessJson and BacklashJson ("  XY: C0Y = ... urad -> factor ... (source)").
void HobbyInputsText(const JsonValue& d, const char* value_key, std::ostream& out);

}  // namespace volcomp::cli
