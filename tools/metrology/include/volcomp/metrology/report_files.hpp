// The files of a metrology report: DIR/NAME.html and DIR/NAME.json, named after what they evaluate
// (axis, diagonals), so the reports of several axes share one directory. Failures name the path
// (kIoError).
#pragma once

#include <string>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/report/html_page.hpp"

namespace volcomp::metrology {

/// `text` reduced to a file-name-safe word: letters, digits and . _ + - are kept, anything else
/// becomes '_'.
std::string SafeName(const std::string& text);

/// The stem of an input's file name ("x_readings" for "data/x_readings.csv", "stdin" for "-" or
/// "<stdin>").
std::string SourceStem(const std::string& source);

/// What WriteReportFiles() wrote.
struct ReportFiles {
  std::string html;       // DIR/NAME.html
  std::string json;       // DIR/NAME.json; empty when no JSON was given
  bool replaced = false;  // an earlier report of that name was overwritten
};

/// Creates DIR and writes `page` to DIR/NAME.html and `json` (the command's --json document) to
/// DIR/NAME.json (skipped when `json` is empty).
Expected<ReportFiles> WriteReportFiles(const report::HtmlPage& page,
                                       const std::string& json,
                                       const std::string& dir,
                                       const std::string& name);

}  // namespace volcomp::metrology
