// File arguments of the commands: "-" names the command's standard input or output (Context::in,
// Context::out), any other word a file. Failures name the file (kIoError, or kInputInvalid for
// CSV that cannot be read).
#pragma once

#include <string>

#include "command.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::cli {

/// The CSV table in the file `path`, or on standard input for "-" (named "<stdin>").
Expected<tools::CsvTable> ReadCsvArgument(const std::string& path, Context& ctx);

/// Writes `text` to the file `path`, or to standard output for "-".
Outcome WriteTextArgument(const std::string& text, const std::string& path, Context& ctx);

}  // namespace volcomp::cli
