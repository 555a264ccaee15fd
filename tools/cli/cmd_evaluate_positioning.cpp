// `volcomp evaluate positioning`: GOST 27843-88 / ISO 230-2:2014 positioning test evaluation.
#include <iostream>
#include <optional>
#include <sstream>
#include <vector>

#include "commands.hpp"
#include "volcomp/metrology/cli_support.hpp"
#include "volcomp/metrology/positioning_checks.hpp"
#include "volcomp/metrology/positioning_csv.hpp"
#include "volcomp/metrology/positioning_eval.hpp"
#include "volcomp/metrology/positioning_report.hpp"
#include "volcomp/metrology/reading_checks.hpp"
#include "volcomp/metrology/test_conditions.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::tools {

namespace m = volcomp::metrology;

int RunEvaluatePositioning(Args& args) {
  const bool json = args.flag("--json");
  const auto report_dir = args.value("--report");
  const std::string standard = args.value("--standard").value();
  const std::string sigma = args.value("--sigma").value();
  const auto axis_length = args.number("--axis-length-mm");
  const bool allow_few = args.flag("--allow-few-runs");
  const auto files = args.positionals();
  args.finish();
  if (files.size() != 1) throw UsageError("give exactly one data file (or - for stdin)");
  std::vector<m::Standard> standards;
  if (standard == "gost27843" || standard == "gost") {
    standards = {m::Standard::kGost27843};
  } else if (standard == "iso230-2" || standard == "iso") {
    standards = {m::Standard::kIso230_2};
  } else if (standard == "both") {
    standards = {m::Standard::kGost27843, m::Standard::kIso230_2};
  } else {
    throw UsageError("--standard must be gost27843, iso230-2 or both");
  }
  m::EvaluationOptions eo;
  if (sigma == "formula") {
    eo.sigma = m::SigmaMethod::kFormula;
  } else if (sigma == "range") {
    eo.sigma = m::SigmaMethod::kRange;
  } else {
    throw UsageError("--sigma must be formula or range");
  }
  if (axis_length && !(*axis_length > 0.0)) throw UsageError("--axis-length-mm must be positive");

  const CsvTable table = m::ReadCsvArgument(files[0]);
  const m::TestConditions conditions = m::ConditionsFromPreamble(table);
  const m::PositioningData data = m::ReadPositioningCsv(table);
  m::GroupingOptions go;
  go.allow_few_approaches = allow_few;
  const m::PositioningSet set = m::GroupReadings(data, go);
  m::ReadingCheckOptions checks;
  checks.travel = axis_length;
  const std::vector<std::string> reading_warnings = m::CheckReadings(data, set, checks);

  std::vector<m::PositioningResult> results;
  for (const m::Standard s : standards) {
    eo.standard = s;
    m::PositioningResult r = m::EvaluatePositioning(set, eo);
    for (const auto& w : reading_warnings) r.warnings.push_back(w);
    for (const auto& w : m::CheckPositionCount(set, s, axis_length)) r.warnings.push_back(w);
    for (const auto& w : m::CheckCardinalAngles(set)) r.warnings.push_back(w);
    results.push_back(std::move(r));
  }

  std::vector<std::string> all_warnings;
  for (const auto& r : results) {
    for (const auto& w : r.warnings) {
      bool dup = false;
      for (const auto& a : all_warnings) dup = dup || a == w;
      if (!dup) all_warnings.push_back(w);
    }
  }
  m::PrintWarnings(std::cerr, all_warnings);

  const auto axis = conditions.Find("axis");
  const std::string name =
      "positioning_" + (axis ? m::SafeName(*axis) : m::SourceStem(table.source()));
  std::ostringstream json_text;
  {
    JsonWriter j(json_text);
    j.begin_object();
    j.key("command").value("evaluate positioning");
    j.key("name").value(name);
    j.key("source").value(table.source());
    m::WriteConditionsJson(j, conditions);
    j.key("positions").value(static_cast<int64_t>(set.positions.size()));
    j.key("evaluations").begin_array();
    for (const auto& r : results) m::WritePositioningJson(j, r);
    j.end_array();
    j.end_object();
  }
  json_text << "\n";
  if (json) {
    std::cout << json_text.str();
  } else {
    std::cout << "positioning test: " << table.source() << "\n";
    if (!conditions.empty()) std::cout << "conditions: " << m::ConditionsText(conditions) << "\n";
    std::cout << (set.kind == m::AxisKind::kLinear ? "linear" : "rotary") << " axis, "
              << set.positions.size()
              << " target positions, directions: " << (set.has_up ? "↑" : "")
              << (set.has_down ? "↓" : "") << "\n\n";
    for (const auto& r : results) {
      m::WritePositioningText(std::cout, r);
      std::cout << "\n";
    }
  }
  if (report_dir) {
    report::HtmlPage page("Positioning test" + (axis ? " of axis " + *axis : std::string()) + ": " +
                          table.source());
    page.Paragraph(std::string(set.kind == m::AxisKind::kLinear ? "Linear" : "Rotary") + " axis, " +
                   std::to_string(set.positions.size()) + " target positions.");
    m::AddConditionsSection(&page, conditions);
    for (const auto& r : results) m::AddPositioningSection(&page, r);
    m::WriteReport(page, json_text.str(), *report_dir, name, std::cerr);
  }
  return kExitOk;
}

}  // namespace volcomp::tools
