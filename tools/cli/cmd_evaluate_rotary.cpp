// `volcomp evaluate rotary FILE|-`: ISO 230-7 error motions of a spindle or rotary axis
// (metrology/rotary_eval.hpp), with an optional Donaldson reversal, as text or JSON, and an HTML
// report.
#include <algorithm>
#include <optional>
#include <ostream>
#include <string>
#include <utility>

#include "choice_option.hpp"
#include "commands.hpp"
#include "file_arguments.hpp"
#include "metrology_report.hpp"
#include "option_groups.hpp"
#include "uncertainty_options.hpp"
#include "volcomp/metrology/report_files.hpp"
#include "volcomp/metrology/rotary_data.hpp"
#include "volcomp/metrology/rotary_eval.hpp"
#include "volcomp/metrology/rotary_report.hpp"
#include "volcomp/metrology/test_conditions.hpp"

namespace volcomp::cli {
namespace {

namespace m = volcomp::metrology;

// --centres MRS,MIC,MCC (any of them, or "all"); PC and LSC are always evaluated.
Expected<m::CentreSelection> ParseCentres(const std::string& list) {
  m::CentreSelection c;
  std::size_t start = 0;
  while (start < list.size()) {
    const std::size_t end = std::min(list.find(',', start), list.size());
    const std::string name = list.substr(start, end - start);
    if (name == "MRS" || name == "mrs") {
      c.mrs = true;
    } else if (name == "MIC" || name == "mic") {
      c.mic = true;
    } else if (name == "MCC" || name == "mcc") {
      c.mcc = true;
    } else if (name == "all") {
      c = {true, true, true};
    } else if (name != "PC" && name != "LSC" && name != "pc" && name != "lsc") {
      return UsageFailure("--centres: unknown centre \"" + name +
                          "\" (give PC, LSC, MRS, MIC, MCC or all, comma-separated)");
    }
    start = end + 1;
  }
  return c;
}

void EvaluateRotaryText(const JsonValue& data, std::ostream& out) { m::WriteRotaryText(out, data); }

Expected<Output> RunEvaluateRotary(Args& args, Context& ctx) {
  args.Flag("--json");  // the command layer prints the data as JSON
  const auto report_dir = args.Value("--report");
  m::RotaryOptions o;
  const std::string sensitive = args.Value("--sensitive").value_or("");
  const auto fsd_angle = args.Number("--fsd-angle-deg");
  o.tilt_distance_mm = args.Number("--tilt-distance-mm");
  o.face_radius_mm = args.Number("--face-radius-mm");
  const bool min_zone = args.Flag("--min-zone");
  const std::string centres = args.Value("--centres").value_or("");
  const std::string axis = args.Value("--axis").value_or("");
  o.static_test = args.Flag("--static");
  o.uncertainty.device_calibration_um = args.Number("--instrument-u-um");
  o.uncertainty.device_range_um = args.Number("--instrument-range-um");
  const auto setup_u = args.Number("--setup-u-um");
  o.uncertainty.drift_range_um = args.Number("--drift-range-um");
  VOLCOMP_TRY(ReadDriftTest(args, ctx, &o.uncertainty.drift_range_um, &o.uncertainty.drift_source));
  o.uncertainty.literal_f6 = args.Flag("--f6-as-printed");
  const auto reversal_file = args.Value("--reversal");
  const std::string reversal_channel = args.Value("--reversal-channel").value_or("");
  const std::string procedure = args.Value("--reversal-procedure").value_or("");
  const auto files = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  VOLCOMP_TRY_ASSIGN(o.sensitive, ParseChoice<m::SensitiveDirection>(
                                      "--sensitive", sensitive,
                                      {{"rotating", m::SensitiveDirection::kRotating},
                                       {"fixed", m::SensitiveDirection::kFixed}}));
  if (fsd_angle) {
    if (o.sensitive != m::SensitiveDirection::kFixed) {
      return UsageFailure("--fsd-angle-deg needs --sensitive fixed");
    }
    o.fsd_angle_deg = *fsd_angle;
  }
  VOLCOMP_TRY_ASSIGN(o.centres, ParseCentres(centres));
  VOLCOMP_TRY_ASSIGN(o.axis,
                     ParseChoice<m::RotaryAxisKind>("--axis", axis,
                                                    {{"spindle", m::RotaryAxisKind::kSpindle},
                                                     {"table", m::RotaryAxisKind::kTable},
                                                     {"head", m::RotaryAxisKind::kHead}}));
  o.centres.mrs = o.centres.mrs || min_zone;
  if (files.size() != 1) return UsageFailure("give exactly one data file (or - for stdin)");
  if (procedure != "P" && procedure != "S") {
    return UsageFailure("--reversal-procedure must be P or S");
  }
  if (o.tilt_distance_mm && !(*o.tilt_distance_mm > 0.0)) {
    return UsageFailure("--tilt-distance-mm must be positive");
  }
  if (o.face_radius_mm && !(*o.face_radius_mm > 0.0)) {
    return UsageFailure("--face-radius-mm must be positive");
  }

  VOLCOMP_TRY_ASSIGN(const tools::CsvTable table, ReadCsvArgument(files[0], ctx));
  VOLCOMP_TRY_ASSIGN(const m::RotaryRecord rec, m::ReadRotaryCsv(table));
  const m::TestConditions conditions = m::ConditionsFromPreamble(table);
  // The uncertainty inputs an option does not give come from the file's preamble.
  for (auto [value, key] : {std::pair{&o.uncertainty.device_calibration_um, "instrument_u_um"},
                            std::pair{&o.uncertainty.device_range_um, "instrument_range_um"},
                            std::pair{&o.uncertainty.drift_range_um, "drift_range_um"}}) {
    if (*value) continue;
    VOLCOMP_TRY_ASSIGN(*value, conditions.Number(key));
  }
  if (setup_u) {
    o.uncertainty.setup_um = *setup_u;
  } else {
    VOLCOMP_TRY_ASSIGN(const auto v, conditions.Number("setup_u_um"));
    o.uncertainty.setup_um = v.value_or(0.0);
  }
  VOLCOMP_TRY_ASSIGN(m::RotaryEvaluation ev, m::EvaluateRotary(rec, o));
  ev.conditions = conditions;
  std::optional<m::ReversalResult> reversal;
  if (reversal_file) {
    VOLCOMP_TRY_ASSIGN(const tools::CsvTable table2, ReadCsvArgument(*reversal_file, ctx));
    VOLCOMP_TRY_ASSIGN(const m::RotaryRecord rec2, m::ReadRotaryCsv(table2));
    VOLCOMP_TRY_ASSIGN(reversal, m::DonaldsonReversal(rec, rec2, reversal_channel,
                                                      procedure == "P" ? m::ReversalProcedure::kP
                                                                       : m::ReversalProcedure::kS));
  }
  Output output{m::RotaryJson(ev, reversal), EvaluateRotaryText, ev.warnings};
  if (report_dir) {
    VOLCOMP_TRY(WriteMetrologyReport(m::RotaryPage(ev, reversal), output.data, *report_dir,
                                     "rotary_" + m::SourceStem(rec.source), ctx));
  }
  return output;
}

}  // namespace

const Command& EvaluateRotaryCommand() {
  static const Command kCommand{
      "evaluate rotary", "ISO 230-7 error motion (synchronous, asynchronous, tilt, reversal)",
      "FILE|-",
      Join({{{"--sensitive", nullptr, "rotating|fixed", nullptr, "rotating",
              "sensitive direction of the radial measurement"},
             {"--fsd-angle-deg", nullptr, "A", "deg", nullptr,
              "angle of the fixed sensitive direction (with --sensitive fixed; default 0)"},
             {"--tilt-distance-mm", nullptr, "L", "mm", nullptr,
              "distance of the second radial plane (x2_um, y2_um) for tilt"},
             {"--face-radius-mm", nullptr, "R", "mm", nullptr, "radius of the face sensor"},
             {"--centres", nullptr, "LIST", nullptr, "PC,LSC",
              "centres to evaluate about, comma-separated: MRS (minimum zone), MIC (maximum "
              "inscribed), MCC (minimum circumscribed) or all; PC and LSC always"},
             {"--min-zone", nullptr, nullptr, nullptr, nullptr, "the same as --centres MRS"},
             {"--axis", nullptr, "spindle|table|head", nullptr, "spindle",
              "what turns: the rule for the number of revolutions (spindle 20; table 4+4 or "
              "5+5 CW+CCW; head 2+2 or 5+5)"},
             {"--static", nullptr, nullptr, nullptr, nullptr,
              "a static test (annex E): stops turned by hand, >= 2 revolutions, >= 8 stops"},
             {"--instrument-u-um", nullptr, "U", "um", nullptr,
              "the instrument's calibration U at k = 2 (annex F.1; or preamble instrument_u_um)"},
             {"--instrument-range-um", nullptr, "R", "um", nullptr,
              "the maker's error range: U = 0.6 R (F.2; or preamble instrument_range_um)"},
             {"--setup-u-um", nullptr, "U", "um", "0",
              "setup contributors at k = 2: artefact roundness, alignment (or preamble "
              "setup_u_um)"},
             {"--drift-range-um", nullptr, "E", "um", nullptr,
              "range E_VE of a drift test: U_EVE = 0.6 E (F.3; or preamble drift_range_um)"},
             DriftTestOption(),
             {"--f6-as-printed", nullptr, nullptr, nullptr, nullptr,
              "single-plot value U by F.6 as printed instead of 1.4 U_single"},
             {"--reversal", nullptr, "FILE2", nullptr, nullptr,
              "Donaldson reversal: the second (reversed) setup"},
             {"--reversal-channel", nullptr, "COLUMN", nullptr, "x_um",
              "channel used for the reversal"},
             {"--reversal-procedure", nullptr, "P|S", nullptr, "P",
              "reversal procedure (same or reversed sign convention)"}},
            JsonReport()}),
      RunEvaluateRotary};
  return kCommand;
}

}  // namespace volcomp::cli
