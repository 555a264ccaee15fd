// `volcomp evaluate diagonal FILE|-`: ISO 230-6 diagonal displacement test evaluation
// (metrology/diagonal.hpp), as text or JSON, and an HTML report.
#include <ostream>

#include "commands.hpp"
#include "file_arguments.hpp"
#include "metrology_report.hpp"
#include "option_groups.hpp"
#include "uncertainty_options.hpp"
#include "volcomp/metrology/diagonal.hpp"
#include "volcomp/metrology/diagonal_report.hpp"

namespace volcomp::cli {
namespace {

namespace m = volcomp::metrology;

void EvaluateDiagonalText(const JsonValue& data, std::ostream& out) {
  m::WriteDiagonalText(out, data);
}

Expected<Output> RunEvaluateDiagonal(Args& args, Context& ctx) {
  args.Flag("--json");  // the command layer prints the data as JSON
  const auto report_dir = args.Value("--report");
  m::GroupingOptions grouping;
  grouping.allow_few_approaches = args.Flag("--allow-few-runs");
  VOLCOMP_TRY_ASSIGN(const m::PositioningUncertaintyInputs uncertainty,
                     ReadLengthUncertainty(args, ctx));
  const auto files = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  if (files.size() != 1) return UsageFailure("give exactly one data file (or - for stdin)");
  VOLCOMP_TRY_ASSIGN(const tools::CsvTable table, ReadCsvArgument(files[0], ctx));
  VOLCOMP_TRY_ASSIGN(const m::DiagonalEvaluation ev,
                     m::EvaluateDiagonals(table, grouping, uncertainty));
  Output output{m::DiagonalJson(ev), EvaluateDiagonalText, ev.warnings};
  if (report_dir) {
    VOLCOMP_TRY(WriteMetrologyReport(m::DiagonalPage(ev), output.data, *report_dir,
                                     m::DiagonalReportName(ev), ctx));
  }
  return output;
}

}  // namespace

const Command& EvaluateDiagonalCommand() {
  static const Command kCommand{
      "evaluate diagonal",
      "ISO 230-6 body/face diagonal test (E, B, E_d, B_d) from CSV",
      "FILE|-",
      Join({AllowFewRuns(), LengthUncertaintyOptions(), JsonReport()}),
      RunEvaluateDiagonal,
      "Input: the positioning long layout with a `diagonal` column naming each row's diagonal."};
  return kCommand;
}

}  // namespace volcomp::cli
