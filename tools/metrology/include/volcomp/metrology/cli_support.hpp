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

/// `text` reduced to a file-name-safe word: letters, digits and . _ + - are kept, anything else
/// becomes '_'.
std::string SafeName(const std::string& text);

/// The stem of an input's file name ("x_readings" for "data/x_readings.csv", "stdin" for "-").
std::string SourceStem(const std::string& source);

/// Writes DIR/NAME.html (`page`) and DIR/NAME.json (`json`, the command's --json output; skipped
/// when empty), creating DIR, and says on `err` what was written and when an earlier report of
/// that name was replaced. Returns the HTML path. Failures become tools::InputError naming the
/// path. Reports are named after what they evaluate (axis, diagonals), so the reports of several
/// axes share one directory.
std::string WriteReport(const report::HtmlPage& page,
                        const std::string& json,
                        const std::string& dir,
                        const std::string& name,
                        std::ostream& err);

/// "warning: ..." lines on `err`.
void PrintWarnings(std::ostream& err, const std::vector<std::string>& warnings);

/// Writes `text` to `path` ("-" = `out`); tools::InputError naming the path on failure.
void WriteTextOutput(const std::string& text, const std::string& path, std::ostream& out);

}  // namespace volcomp::metrology
