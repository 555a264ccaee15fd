// The report of a metrology command (`evaluate ... --report DIR`, `report compare -o DIR`): its
// HTML page and its data as JSON written into DIR (metrology/report_files.hpp), and a line on
// Context::err saying what was written.
#pragma once

#include <string>

#include "command.hpp"
#include "volcomp/report/html_page.hpp"

namespace volcomp::cli {

/// Writes DIR/NAME.html and, unless `data` is null, DIR/NAME.json (the command's --json output).
Outcome WriteMetrologyReport(const report::HtmlPage& page,
                             const JsonValue& data,
                             const std::string& dir,
                             const std::string& name,
                             Context& ctx);

}  // namespace volcomp::cli
