// `volcomp evaluate diagonal`: ISO 230-6 diagonal displacement test evaluation.
#include <iostream>

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
  if (json) {
    JsonWriter j(std::cout);
    m::WriteDiagonalJson(j, ev);
    std::cout << "\n";
  } else {
    m::WriteDiagonalText(std::cout, ev);
  }
  if (report_dir) {
    report::HtmlPage page("ISO 230-6 diagonal displacement test");
    m::AddDiagonalSections(&page, ev);
    std::cerr << "report written to " << m::WriteReport(page, *report_dir, "diagonal.html") << "\n";
  }
  return 0;
}

}  // namespace volcomp::tools
