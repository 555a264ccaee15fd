// `volcomp evaluate diagonal`: ISO 230-6 diagonal displacement test evaluation.
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "volcomp/metrology/cli_support.hpp"
#include "volcomp/metrology/diagonal.hpp"
#include "volcomp/metrology/diagonal_report.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::tools {

namespace m = volcomp::metrology;

int RunEvaluateDiagonal(Args& args) {
  const bool json = args.flag("--json");
  const auto report_dir = args.value("--report");
  const bool allow_few = args.flag("--allow-few-runs");
  const auto files = args.positionals();
  args.finish();
  if (files.size() != 1) throw UsageError("give exactly one data file (or - for stdin)");
  const CsvTable table = m::ReadCsvArgument(files[0]);
  m::GroupingOptions go;
  go.allow_few_approaches = allow_few;
  const m::DiagonalEvaluation ev = m::EvaluateDiagonals(table, go);
  m::PrintWarnings(std::cerr, ev.warnings);
  std::ostringstream json_text;
  {
    JsonWriter j(json_text);
    m::WriteDiagonalJson(j, ev);
  }
  json_text << "\n";
  if (json) {
    std::cout << json_text.str();
  } else {
    m::WriteDiagonalText(std::cout, ev);
  }
  if (report_dir) {
    report::HtmlPage page("ISO 230-6 diagonal displacement test");
    m::AddDiagonalSections(&page, ev);
    m::WriteReport(page, json_text.str(), *report_dir, m::DiagonalReportName(ev), std::cerr);
  }
  return kExitOk;
}

}  // namespace volcomp::tools
