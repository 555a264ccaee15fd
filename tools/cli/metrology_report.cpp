// Writing a metrology command's report and saying so.
#include "metrology_report.hpp"

#include <ostream>
#include <sstream>

#include "volcomp/metrology/report_files.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::cli {

Outcome WriteMetrologyReport(const report::HtmlPage& page,
                             const JsonValue& data,
                             const std::string& dir,
                             const std::string& name,
                             Context& ctx) {
  std::ostringstream json;
  if (!data.is_null()) tools::WriteJson(data, json);
  VOLCOMP_TRY_ASSIGN(const metrology::ReportFiles files,
                     metrology::WriteReportFiles(page, json.str(), dir, name));
  ctx.err << "report written to " << files.html;
  if (!files.json.empty()) ctx.err << " and " << files.json;
  ctx.err << (files.replaced ? " (replacing the earlier report of that name)" : "") << "\n";
  return Outcome::Ok();
}

}  // namespace volcomp::cli
