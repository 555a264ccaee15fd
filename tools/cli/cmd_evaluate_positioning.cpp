// `volcomp evaluate positioning FILE|-`: GOST 27843-88 / ISO 230-2:2014 positioning test
// evaluation (metrology/positioning_evaluation.hpp), as text or JSON, and an HTML report.
#include <ostream>
#include <vector>

#include "choice_option.hpp"
#include "commands.hpp"
#include "file_arguments.hpp"
#include "metrology_report.hpp"
#include "option_groups.hpp"
#include "positioning_input.hpp"
#include "uncertainty_options.hpp"
#include "volcomp/metrology/positioning_evaluation.hpp"
#include "volcomp/metrology/positioning_report.hpp"

namespace volcomp::cli {
namespace {

namespace m = volcomp::metrology;

void EvaluatePositioningText(const JsonValue& data, std::ostream& out) {
  m::WritePositioningEvaluationText(out, data);
}

Expected<Output> RunEvaluatePositioning(Args& args, Context& ctx) {
  args.Flag("--json");  // the command layer prints the data as JSON
  const auto report_dir = args.Value("--report");
  const std::string standard = args.Value("--standard").value_or("");
  const std::string sigma = args.Value("--sigma").value_or("");
  m::PositioningTestOptions o;
  o.axis_length_mm = args.Number("--axis-length-mm");
  o.grouping.allow_few_approaches = args.Flag("--allow-few-runs");
  VOLCOMP_TRY_ASSIGN(o.uncertainty, ReadPositioningUncertainty(args, ctx));
  VOLCOMP_TRY_ASSIGN(const datasets::PositioningReadOptions read,
                     ParsePositioningReadOptions(args));
  const auto files = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  if (files.size() != 1) return UsageFailure("give exactly one data file (or - for stdin)");
  using Standards = std::vector<m::Standard>;
  const Standards gost = {m::Standard::kGost27843}, iso = {m::Standard::kIso230_2};
  VOLCOMP_TRY_ASSIGN(o.standards, ParseChoice<Standards>("--standard", standard,
                                                         {{"gost27843", gost},
                                                          {"gost", gost, false},
                                                          {"iso230-2", iso},
                                                          {"iso", iso, false},
                                                          {"both", {gost[0], iso[0]}}}));
  VOLCOMP_TRY_ASSIGN(o.sigma, ParseChoice<m::SigmaMethod>("--sigma", sigma,
                                                          {{"formula", m::SigmaMethod::kFormula},
                                                           {"range", m::SigmaMethod::kRange}}));
  if (o.axis_length_mm && !(*o.axis_length_mm > 0.0)) {
    return UsageFailure("--axis-length-mm must be positive");
  }

  VOLCOMP_TRY_ASSIGN(const datasets::PositioningFile file,
                     ReadPositioningArgument(files[0], read, ctx));
  if (!file.readings) {
    return Fail(Error::kInputInvalid,
                file.source +
                    ": holds the mean deviations per target (position_mm, dev_forward_um ...); "
                    "evaluate positioning needs the readings of every run");
  }
  VOLCOMP_TRY_ASSIGN(m::PositioningEvaluation ev,
                     m::EvaluatePositioningReadings(*file.readings, file.conditions, o));
  // The reader's warnings (.rtl: directions, environment) belong to every evaluation.
  for (m::PositioningResult& r : ev.results) {
    r.warnings.insert(r.warnings.begin(), file.warnings.begin(), file.warnings.end());
  }
  ev.warnings.insert(ev.warnings.begin(), file.warnings.begin(), file.warnings.end());
  Output output{m::PositioningEvaluationJson(ev), EvaluatePositioningText, ev.warnings};
  output.data.Set("format", datasets::PositioningFormatName(file.format));
  if (file.format == datasets::PositioningFormat::kRtl) {
    output.data.Set("rtl_units", datasets::RtlUnitsName(file.rtl_units));
  }
  if (report_dir) {
    VOLCOMP_TRY(WriteMetrologyReport(m::PositioningEvaluationPage(ev), output.data, *report_dir,
                                     m::PositioningReportName(ev), ctx));
  }
  return output;
}

}  // namespace

const Command& EvaluatePositioningCommand() {
  static const Command kCommand{
      "evaluate positioning",
      "GOST 27843-88 / ISO 230-2 positioning test from CSV or a Renishaw .rtl",
      "FILE|-",
      Join({{{"--standard", nullptr, "gost27843|iso230-2|both", nullptr, "gost27843",
              "standard(s) to evaluate"},
             {"--sigma", nullptr, "formula|range", nullptr, "formula",
              "GOST 27843 S by formula (5) or by the range method (6)"},
             {"--axis-length-mm", nullptr, "L", "mm", nullptr,
              "axis travel for the target-count checks (default: the targets' span)"}},
            AllowFewRuns(),
            PositioningFormatOptions(),
            LengthUncertaintyOptions(),
            AngleUncertaintyOptions(),
            JsonReport()}),
      RunEvaluatePositioning,
      "Input: target_mm|target_in|target_deg, direction, run, deviation_um|deviation_mm|\n"
      "measured_mm|deviation_in|deviation_uin|measured_in|deviation_arcsec|...; inch columns\n"
      "are converted (results in mm and µm); ',' or ';' or TAB separated (decimal comma with\n"
      "';' or TAB);\n"
      "'# key: value' lines before the header are the test conditions of the report.\n"
      "Non-finite readings are refused; implausible magnitudes and Grubbs outliers (99 %)\n"
      "are warned about with their line. See docs/metrology.md.\n"
      "A Renishaw .rtl linear data file is read as it is (recognised by content); see\n"
      "docs/pc-tool.md \"Instrument files\"."};
  return kCommand;
}

}  // namespace volcomp::cli
