// Small helpers shared by the metrology commands of the `volcomp` tool.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "volcomp/report/html_page.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::metrology {

/// Parses the CSV file at `path`, or standard input for "-".
tools::CsvTable ReadCsvArgument(const std::string& path);

/// Writes `page` as DIR/file_name (creating DIR); returns the path written. Failures become
/// tools::InputError naming the path.
std::string WriteReport(const report::HtmlPage& page,
                        const std::string& dir,
                        const std::string& file_name);

/// "warning: ..." lines on `err`.
void PrintWarnings(std::ostream& err, const std::vector<std::string>& warnings);

/// Writes `text` to `path` ("-" = `out`); tools::InputError naming the path on failure.
void WriteTextOutput(const std::string& text, const std::string& path, std::ostream& out);

}  // namespace volcomp::metrology
