// The positioning-test input of every command that reads one (`evaluate positioning`, `build
// axis`, the exports): the options that choose the file format (--format auto|csv|rtl) and how
// a Renishaw .rtl is read (--rtl-runs, --rtl-negate, --rtl-units, --rtl-expansion-per), the unit
// plausibility check's override (--accept-units), and the file read through the one loader
// (datasets/positioning_file.hpp).
#pragma once

#include <string>

#include "command.hpp"
#include "option_groups.hpp"
#include "volcomp/datasets/positioning_file.hpp"

namespace volcomp::cli {

/// --format, --rtl-runs, --rtl-negate, --rtl-units, --rtl-expansion-per and --accept-units.
const Options& PositioningFormatOptions();

/// Those options' values; a usage failure for a word outside their sets.
Expected<datasets::PositioningReadOptions> ParsePositioningReadOptions(Args& args);

/// The positioning test in the file `path`, or on standard input for "-" (named "<stdin>").
Expected<datasets::PositioningFile> ReadPositioningArgument(
    const std::string& path, const datasets::PositioningReadOptions& options, Context& ctx);

}  // namespace volcomp::cli
