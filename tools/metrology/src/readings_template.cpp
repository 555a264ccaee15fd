// Readings templates and their protection.
#include "volcomp/metrology/readings_template.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "volcomp/metrology/test_conditions.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::metrology {

std::string TemplatePreamble(const TemplateHeader& header) {
  std::ostringstream s;
  s << "# " << header.description << "\n";
  std::vector<bool> used(header.known.size(), false);
  for (const std::string& key : ConditionKeys()) {
    if (std::find(header.omit.begin(), header.omit.end(), key) != header.omit.end()) continue;
    std::string value;
    for (std::size_t i = 0; i < header.known.size(); ++i) {
      if (header.known[i].first == key) {
        value = header.known[i].second;
        used[i] = true;
      }
    }
    s << "# " << key << ":" << (value.empty() ? "" : " " + value) << "\n";
  }
  for (std::size_t i = 0; i < header.known.size(); ++i) {
    if (!used[i]) s << "# " << header.known[i].first << ": " << header.known[i].second << "\n";
  }
  return s.str();
}

std::string TemplateRows(const std::vector<CycleMove>& moves, const std::string& diagonal) {
  std::ostringstream s;
  for (const auto& mv : moves) {
    if (!mv.measure) continue;
    if (!diagonal.empty()) s << diagonal << ",";
    s << report::FormatFixed(mv.position, 3) << "," << DirectionName(mv.approach) << "," << mv.run
      << ",\n";
  }
  return s.str();
}

std::optional<std::string> ReadingsAtRisk(const std::string& path) {
  std::error_code ec;
  if (path == "-" || !std::filesystem::exists(path, ec)) return std::nullopt;
  const Expected<tools::CsvTable> read = tools::CsvTable::ReadFile(path);
  if (!read.ok()) return path + " exists and is not a readings template";
  const tools::CsvTable& t = *read;
  std::vector<std::size_t> columns;
  for (std::size_t c = 0; c < t.header().size(); ++c) {
    const std::string& h = t.header()[c];
    if (h.rfind("deviation_", 0) == 0 || h.rfind("measured_", 0) == 0) columns.push_back(c);
  }
  if (columns.empty()) return path + " exists and is not a readings template";
  for (const tools::CsvRow& row : t.rows()) {
    for (std::size_t c : columns) {
      if (!row.fields()[c].empty()) {
        return path + " already holds readings (line " + std::to_string(row.line()) + ")";
      }
    }
  }
  return std::nullopt;
}

Outcome RefuseToOverwriteReadings(const std::string& path, bool force) {
  if (force) return Outcome::Ok();
  if (const auto risk = ReadingsAtRisk(path)) {
    return Fail(Error::kInputInvalid, *risk +
                                          "; not overwritten (give --force to replace it, or "
                                          "another --targets-csv name)");
  }
  return Outcome::Ok();
}

Outcome WriteTemplate(const std::string& text, const std::string& path, bool force) {
  VOLCOMP_TRY(RefuseToOverwriteReadings(path, force));
  return tools::WriteTextFile(path, text);
}

}  // namespace volcomp::metrology
