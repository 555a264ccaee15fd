// `volcomp report compare BEFORE AFTER -o DIR`: the before/after page of a compensation
// (metrology/compare.hpp), its values as text or JSON.
#include <ostream>

#include "commands.hpp"
#include "metrology_report.hpp"
#include "volcomp/metrology/compare.hpp"

namespace volcomp::cli {
namespace {

namespace m = volcomp::metrology;

void ReportCompareText(const JsonValue& data, std::ostream& out) {
  m::WriteComparisonText(out, data);
}

Expected<Output> RunReportCompare(Args& args, Context& ctx) {
  args.Flag("--json");  // the command layer prints the data as JSON
  const std::string out_dir = args.Required("--output", "-o");
  const auto pos = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  if (pos.size() != 2) return UsageFailure("give BEFORE and AFTER (report directories or .json)");
  VOLCOMP_TRY_ASSIGN(const auto before, m::LoadResults(pos[0]));
  VOLCOMP_TRY_ASSIGN(const auto after, m::LoadResults(pos[1]));
  VOLCOMP_TRY_ASSIGN(const m::Comparison c, m::CompareResults(before, after));
  report::HtmlPage page("Before and after: " + pos[0] + " → " + pos[1]);
  m::AddComparisonSections(&page, c);
  VOLCOMP_TRY(WriteMetrologyReport(page, JsonValue(), out_dir, "compare", ctx));
  return Output{m::ComparisonJson(c), ReportCompareText, c.warnings};
}

}  // namespace

const Command& ReportCompareCommand() {
  static const Command kCommand{
      "report compare",
      "before/after page: positioning, diagonal and circular results with reductions",
      "BEFORE AFTER",
      {{"--output", "-o", "DIR", nullptr, nullptr, "directory for compare.html (required)"},
       {"--json", nullptr, nullptr, nullptr, nullptr, "every compared value as JSON on stdout"}},
      RunReportCompare,
      "BEFORE and AFTER are report directories written by `evaluate ... --report DIR` (or\n"
      "single .json results of it); results are paired by name (axis, diagonals, circular test "
      "file)."};
  return kCommand;
}

}  // namespace volcomp::cli
