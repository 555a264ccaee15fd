// A positioning CSV for the input tests (reading and grouping positioning readings): a good file,
// one line of it replaced, and the readings of a text grouped and checked.
#pragma once

#include <cstddef>
#include <string>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/positioning_csv.hpp"
#include "volcomp/metrology/positioning_data.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::metrology::testing {

/// Five full runs over targets 0, 100, 200 in both directions (rows: header + 30).
inline std::string GoodPositioningCsv() {
  std::string csv = "target_mm,direction,run,deviation_um\n";
  for (int run = 1; run <= 5; ++run) {
    for (int t : {0, 100, 200}) csv += std::to_string(t) + ",up," + std::to_string(run) + ",1.5\n";
    for (int t : {200, 100, 0}) csv += std::to_string(t) + ",down," + std::to_string(run) + ",-1\n";
  }
  return csv;
}

/// `csv` with line `line` (1-based) replaced by `text`.
inline std::string WithLine(const std::string& csv, int line, const std::string& text) {
  std::string out;
  int n = 0;
  std::size_t pos = 0;
  while (pos < csv.size()) {
    const std::size_t end = csv.find('\n', pos);
    ++n;
    out += (n == line ? text : csv.substr(pos, end - pos)) + "\n";
    pos = end + 1;
  }
  return out;
}

/// Reads `csv` (named p.csv) and its positioning readings, grouped and checked.
inline Expected<PositioningSet> LoadPositioning(const std::string& csv, GroupingOptions o = {}) {
  VOLCOMP_TRY_ASSIGN(const tools::CsvTable table, tools::CsvTable::ReadString(csv, "p.csv"));
  VOLCOMP_TRY_ASSIGN(const PositioningData data, ReadPositioningCsv(table));
  return GroupReadings(data, o);
}

}  // namespace volcomp::metrology::testing
