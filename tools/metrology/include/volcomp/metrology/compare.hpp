// Before/after comparison of evaluation results (`volcomp report compare BEFORE AFTER -o DIR`): the
// JSON results `evaluate positioning|diagonal|circular --report DIR` wrote, paired by name, every
// parameter before and after with its reduction (docs/metrology.md "Before and after"); circular
// tests also as one polar plot of both (a ballbar report's overlay). Failures are
// returned (kInputInvalid; kIoError for a file that cannot be read), never thrown.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "volcomp/report/html_page.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::metrology {

struct LoadedResult {
  std::string name;  // file stem: the report's name
  std::string path;
  tools::JsonValue json;
};

/// The results in `path`: a directory (its *.json files of positioning, diagonal and circular
/// results, by name) or one .json file. A failure naming the path for anything else.
Expected<std::vector<LoadedResult>> LoadResults(const std::string& path);

struct ComparedValue {
  std::string symbol;   // "A", "E_d", "E_i"
  std::string meaning;  // "accuracy of bidirectional positioning ..." or the diagonal's name
  double before = 0.0;
  double after = 0.0;
  std::optional<double> reduction_pct;  // nullopt when before is 0
  std::optional<double> u_before;       // U (k = 2) where the evaluation states it
  std::optional<double> u_after;
};

struct ComparedTable {
  std::string title;  // "GOST 27843-88", "body diagonals", "diagonal -X-Y-Z"
  std::string unit;   // "µm" or "″"
  std::vector<ComparedValue> values;
};

struct ComparedSeries {  // mean deviation per target before and after, for a chart
  std::string title;
  std::string x_label;
  std::string unit;
  std::vector<double> x_before, up_before, down_before;
  std::vector<double> x_after, up_after, down_after;
};

struct ComparedPolar {  // circular test paths before and after, about each one's own centre
  std::string title;
  struct Path {
    std::string label;
    std::vector<double> angle_deg, value_um;
  };
  std::vector<Path> before, after;  // CW, CCW (those present)
};

struct ComparedResult {
  std::string name;  // positioning_X, diagonal_NNN_NPN_PNN_PPN, circular_xy
  std::string kind;  // "positioning", "diagonal" or "circular"
  std::string before_source, after_source;
  std::vector<std::pair<std::string, std::string>> conditions_before, conditions_after;
  std::vector<ComparedTable> tables;
  std::vector<ComparedSeries> series;
  std::vector<ComparedPolar> polars;
};

struct Comparison {
  std::vector<ComparedResult> results;
  std::vector<std::string> warnings;  // unpaired or mismatched results
};

/// Pairs and compares; a failure when nothing can be paired.
Expected<Comparison> CompareResults(const std::vector<LoadedResult>& before,
                                    const std::vector<LoadedResult>& after);

/// Every compared value (what `report compare` reports; the charts' series stay in the HTML).
tools::JsonValue ComparisonJson(const Comparison& comparison);
/// Per result and table: each value before -> after with its reduction, from ComparisonJson().
void WriteComparisonText(std::ostream& out, const tools::JsonValue& comparison);
void AddComparisonSections(report::HtmlPage* page, const Comparison& comparison);

}  // namespace volcomp::metrology
