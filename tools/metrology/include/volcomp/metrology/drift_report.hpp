// Output of a thermal drift test evaluation (drift_test.hpp): the JSON that `evaluate thermal`
// reports (and its report's .json), the text laid out from that JSON only, the chart (drift
// against time per point above the temperatures against time, one SVG) and the HTML report.
#pragma once

#include <ostream>
#include <string>

#include "volcomp/metrology/drift_test.hpp"
#include "volcomp/report/html_page.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::metrology {

tools::JsonValue DriftJson(const DriftEvaluation& ev);
/// Per axis the points' figures and the components, per channel the rise, from DriftJson().
void WriteDriftText(std::ostream& out, const tools::JsonValue& ev);
/// Two charts stacked in one <svg>: the drift of every point (µm) and the temperature of every
/// channel (°C) against time (h).
std::string DriftSvg(const DriftEvaluation& ev);
/// The report page: conditions, the figures' tables and the two charts.
report::HtmlPage DriftPage(const DriftEvaluation& ev);
/// "thermal_<file stem>".
std::string DriftReportName(const DriftEvaluation& ev);

}  // namespace volcomp::metrology
