// `volcomp report compare BEFORE AFTER -o DIR`: the before/after page of a compensation.
#include <iostream>

#include "commands.hpp"
#include "volcomp/metrology/cli_support.hpp"
#include "volcomp/metrology/compare.hpp"

namespace volcomp::tools {

namespace m = volcomp::metrology;

int RunReportCompare(Args& args) {
  const std::string out_dir = args.required("-o", "--output");
  const auto pos = args.positionals();
  args.finish();
  if (pos.size() != 2) throw UsageError("give BEFORE and AFTER (report directories or .json)");
  const m::Comparison c = m::CompareResults(m::LoadResults(pos[0]), m::LoadResults(pos[1]));
  m::PrintWarnings(std::cerr, c.warnings);
  m::WriteComparisonText(std::cout, c);
  report::HtmlPage page("Before and after: " + pos[0] + " → " + pos[1]);
  m::AddComparisonSections(&page, c);
  m::WriteReport(page, "", out_dir, "compare", std::cerr);
  return kExitOk;
}

}  // namespace volcomp::tools
