// The measurement-uncertainty inputs of the positioning tests (`evaluate positioning`, `evaluate
// diagonal`, `build axis`; angles for a rotary axis): declared once, read into the budget's inputs
// (positioning_uncertainty.hpp); what an option leaves unset comes from the readings file's
// preamble or the budget's stated default.
#pragma once

#include <optional>
#include <string>

#include "command.hpp"
#include "option_groups.hpp"
#include "volcomp/args/args.hpp"
#include "volcomp/metrology/circular_uncertainty.hpp"
#include "volcomp/metrology/positioning_uncertainty.hpp"

namespace volcomp::cli {

const Options& LengthUncertaintyOptions();

/// The options of LengthUncertaintyOptions() that were given (negative values are left to the
/// budget, which refuses them naming the rule).
Expected<metrology::PositioningUncertaintyInputs> ReadLengthUncertainty(args::Args& args,
                                                                        Context& ctx);

/// `--drift-test FILE` (declared in LengthUncertaintyOptions(); other commands add it):
/// E_VE = the drift test's largest point range (metrology LargestDriftRange) into `range_um`,
/// and where it comes from into `source`. Given with a value already in `range_um` (from
/// --drift-range-um): a usage failure; a bad file: its failure naming file and line.
args::OptionSpec DriftTestOption();
Expected<void> ReadDriftTest(args::Args& args,
                             Context& ctx,
                             std::optional<double>* range_um,
                             std::string* source);

/// A rotary axis's angle reference and drift (`evaluate positioning`, `build axis`).
const Options& AngleUncertaintyOptions();

/// A circular test's reading, calibrator, temperature and drift (`evaluate circular`): the length
/// options (the budget refuses --instrument-ppm and --misalignment-mm) and --calibrator-u-um.
const Options& CircularUncertaintyOptions();
Expected<metrology::CircularUncertaintyInputs> ReadCircularUncertainty(args::Args& args,
                                                                       Context& ctx);

/// ReadLengthUncertainty and the options of AngleUncertaintyOptions() that were given.
Expected<metrology::PositioningUncertaintyInputs> ReadPositioningUncertainty(args::Args& args,
                                                                             Context& ctx);

}  // namespace volcomp::cli
