// `volcomp evaluate thermal FILE|-`: a thermal drift test in the manner of ISO 230-3
// (metrology/drift_test.hpp): per point the drift, its largest value, range and rate, per axis the
// offset and slope components, per channel the temperature rise; as text or JSON, a chart (SVG)
// and an HTML report.
#include <ostream>

#include "commands.hpp"
#include "file_arguments.hpp"
#include "metrology_report.hpp"
#include "option_groups.hpp"
#include "volcomp/metrology/drift_report.hpp"
#include "volcomp/metrology/drift_test.hpp"

namespace volcomp::cli {
namespace {

namespace m = volcomp::metrology;

void EvaluateThermalText(const JsonValue& data, std::ostream& out) { m::WriteDriftText(out, data); }

Expected<Output> RunEvaluateThermal(Args& args, Context& ctx) {
  args.Flag("--json");  // the command layer prints the data as JSON
  const auto report_dir = args.Value("--report");
  const auto svg = args.Value("--svg");
  const auto files = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  if (files.size() != 1) return UsageFailure("give exactly one data file (or - for stdin)");
  VOLCOMP_TRY_ASSIGN(const tools::CsvTable table, ReadCsvArgument(files[0], ctx));
  VOLCOMP_TRY_ASSIGN(const m::DriftRecord record, m::ReadDriftCsv(table));
  const m::DriftEvaluation ev = m::EvaluateDrift(record);
  Output output{m::DriftJson(ev), EvaluateThermalText, ev.warnings};
  if (svg) VOLCOMP_TRY(WriteTextArgument(m::DriftSvg(ev), *svg, ctx));
  if (report_dir) {
    VOLCOMP_TRY(WriteMetrologyReport(m::DriftPage(ev), output.data, *report_dir,
                                     m::DriftReportName(ev), ctx));
  }
  return output;
}

}  // namespace

const Command& EvaluateThermalCommand() {
  static const Command kCommand{
      "evaluate thermal",
      "ISO 230-3 thermal drift test (drift, rate, offset and slope, temperature rise) from CSV",
      "FILE|-",
      Join({{{"--svg", nullptr, "FILE", nullptr, nullptr,
              "write the chart (drift of every point, temperatures, against time) as SVG"}},
            JsonReport()}),
      RunEvaluateThermal,
      "Input: columns time_s, axis (X Y Z U V W), position_mm, deviation_um and one\n"
      "T_<name>_C column per temperature channel (up to 8; the channel number is the column's\n"
      "order among them). Every point (axis, position) is read 2 or more times, in increasing\n"
      "time; 2 or more points per axis. '# key: value' lines before the header are the test\n"
      "conditions. See docs/pc-tool.md and docs/thermal.md."};
  return kCommand;
}

}  // namespace volcomp::cli
