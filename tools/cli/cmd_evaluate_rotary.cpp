// `volcomp evaluate rotary`: ISO 230-7 error motions of a spindle or rotary axis.
#include <iostream>
#include <optional>
#include <sstream>

#include "commands.hpp"
#include "volcomp/metrology/cli_support.hpp"
#include "volcomp/metrology/rotary_data.hpp"
#include "volcomp/metrology/rotary_eval.hpp"
#include "volcomp/metrology/rotary_report.hpp"
#include "volcomp/metrology/test_conditions.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::tools {

namespace m = volcomp::metrology;

namespace {

// The synchronous (revolution-averaged) profile of one channel.
std::vector<double> SynchronousChannel(const m::RotaryRecord& rec, const std::string& channel) {
  const auto it = rec.channels.find(channel);
  if (it == rec.channels.end()) {
    throw InputError(rec.source + ": no column \"" + channel + "\" for the reversal");
  }
  std::vector<double> s(rec.angle_deg.size(), 0.0);
  for (const auto& rev : it->second) {
    for (std::size_t j = 0; j < s.size(); ++j) s[j] += rev[j];
  }
  for (double& v : s) v /= static_cast<double>(it->second.size());
  return s;
}

}  // namespace

int RunEvaluateRotary(Args& args) {
  const bool json = args.flag("--json");
  const auto report_dir = args.value("--report");
  m::RotaryOptions o;
  const std::string sensitive = args.value("--sensitive").value();
  if (sensitive == "rotating") {
    o.sensitive = m::SensitiveDirection::kRotating;
  } else if (sensitive == "fixed") {
    o.sensitive = m::SensitiveDirection::kFixed;
  } else {
    throw UsageError("--sensitive must be rotating or fixed");
  }
  if (const auto a = args.number("--fsd-angle-deg")) {
    if (o.sensitive != m::SensitiveDirection::kFixed) {
      throw UsageError("--fsd-angle-deg needs --sensitive fixed");
    }
    o.fsd_angle_deg = *a;
  }
  o.tilt_distance_mm = args.number("--tilt-distance-mm");
  o.face_radius_mm = args.number("--face-radius-mm");
  o.min_zone = args.flag("--min-zone");
  const auto reversal_file = args.value("--reversal");
  const std::string reversal_channel = args.value("--reversal-channel").value();
  const std::string procedure = args.value("--reversal-procedure").value();
  const auto files = args.positionals();
  args.finish();
  if (files.size() != 1) throw UsageError("give exactly one data file (or - for stdin)");
  if (procedure != "P" && procedure != "S") throw UsageError("--reversal-procedure must be P or S");
  if (o.tilt_distance_mm && !(*o.tilt_distance_mm > 0.0)) {
    throw UsageError("--tilt-distance-mm must be positive");
  }
  if (o.face_radius_mm && !(*o.face_radius_mm > 0.0)) {
    throw UsageError("--face-radius-mm must be positive");
  }

  const CsvTable table = m::ReadCsvArgument(files[0]);
  const m::RotaryRecord rec = m::ReadRotaryCsv(table);
  m::RotaryEvaluation ev = m::EvaluateRotary(rec, o);
  ev.conditions = m::ConditionsFromPreamble(table);
  std::optional<m::ReversalResult> rev;
  if (reversal_file) {
    const m::RotaryRecord rec2 = m::ReadRotaryCsv(m::ReadCsvArgument(*reversal_file));
    if (rec2.angle_deg.size() != rec.angle_deg.size()) {
      throw InputError(rec2.source + ": the reversal record has " +
                       std::to_string(rec2.angle_deg.size()) + " angles per revolution, " +
                       rec.source + " has " + std::to_string(rec.angle_deg.size()));
    }
    for (std::size_t j = 0; j < rec.angle_deg.size(); ++j) {
      if (std::abs(rec.angle_deg[j] - rec2.angle_deg[j]) > 1e-6) {
        throw InputError(rec2.source + ": the reversal record must use the angles of " +
                         rec.source);
      }
    }
    rev = m::DonaldsonReversal(
        rec.angle_deg, SynchronousChannel(rec, reversal_channel),
        SynchronousChannel(rec2, reversal_channel),
        procedure == "P" ? m::ReversalProcedure::kP : m::ReversalProcedure::kS);
  }
  m::PrintWarnings(std::cerr, ev.warnings);
  std::ostringstream json_text;
  {
    JsonWriter j(json_text);
    m::WriteRotaryJson(j, ev, rev);
  }
  json_text << "\n";
  if (json) {
    std::cout << json_text.str();
  } else {
    m::WriteRotaryText(std::cout, ev, rev);
  }
  if (report_dir) {
    report::HtmlPage page("ISO 230-7 error motion");
    m::AddRotarySections(&page, ev, rev);
    m::WriteReport(page, json_text.str(), *report_dir, "rotary_" + m::SourceStem(rec.source),
                   std::cerr);
  }
  return kExitOk;
}

}  // namespace volcomp::tools
