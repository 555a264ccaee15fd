// `volcomp evaluate positioning`: GOST 27843-88 / ISO 230-2:2014 positioning test evaluation.
#include <iostream>
#include <optional>
#include <vector>

#include "commands.hpp"
#include "volcomp/metrology/cli_support.hpp"
#include "volcomp/metrology/positioning_checks.hpp"
#include "volcomp/metrology/positioning_csv.hpp"
#include "volcomp/metrology/positioning_eval.hpp"
#include "volcomp/metrology/positioning_report.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::tools {

namespace m = volcomp::metrology;

int RunEvaluatePositioning(Args& args) {
  const bool json = args.flag("--json");
  const auto report_dir = args.value("--report");
  const std::string standard = args.value("--standard").value_or("gost27843");
  const std::string sigma = args.value("--sigma").value_or("formula");
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
  const m::PositioningData data = m::ReadPositioningCsv(table);
  m::GroupingOptions go;
  go.allow_few_approaches = allow_few;
  const m::PositioningSet set = m::GroupReadings(data, go);

  std::vector<m::PositioningResult> results;
  for (const m::Standard s : standards) {
    eo.standard = s;
    m::PositioningResult r = m::EvaluatePositioning(set, eo);
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

  if (json) {
    JsonWriter j(std::cout);
    j.begin_object();
    j.key("command").value("evaluate positioning");
    j.key("source").value(table.source());
    j.key("positions").value(static_cast<int64_t>(set.positions.size()));
    j.key("evaluations").begin_array();
    for (const auto& r : results) m::WritePositioningJson(j, r);
    j.end_array();
    j.end_object();
    std::cout << "\n";
  } else {
    std::cout << "positioning test: " << table.source() << "\n"
              << (set.kind == m::AxisKind::kLinear ? "linear" : "rotary") << " axis, "
              << set.positions.size()
              << " target positions, directions: " << (set.has_up ? "↑" : "")
              << (set.has_down ? "↓" : "") << "\n\n";
    for (const auto& r : results) {
      m::WritePositioningText(std::cout, r);
      std::cout << "\n";
    }
  }
  if (report_dir) {
    report::HtmlPage page("Positioning test: " + table.source());
    page.Paragraph(std::string(set.kind == m::AxisKind::kLinear ? "Linear" : "Rotary") + " axis, " +
                   std::to_string(set.positions.size()) + " target positions.");
    for (const auto& r : results) m::AddPositioningSection(&page, r);
    const std::string path = m::WriteReport(page, *report_dir, "positioning.html");
    std::cerr << "report written to " << path << "\n";
  }
  return 0;
}

}  // namespace volcomp::tools
