// Output of a positioning evaluation: JSON (every parameter, per position and overall, with the
// location of each extreme), the text laid out from that JSON (so the two cannot disagree), and an
// HTML section with the charts of GOST 27843-88 fig. 10 (X̄↑, X̄↓ with the X̄ ± kS bands per
// position, reversal B_j and repeatability R_j per position).
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "volcomp/metrology/positioning_eval.hpp"
#include "volcomp/metrology/positioning_evaluation.hpp"
#include "volcomp/report/html_page.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::metrology {

/// One JSON object with the standard, the per-position values and every overall parameter.
tools::JsonValue PositioningJson(const PositioningResult& result);
/// A budget as JSON: k, the span and its U, the local U (unless `with_local` is false: a budget
/// that stands for one length only, as the circular test's F) and terms[] (keys naming their
/// unit, UncertaintyKeys()); null for none.
tools::JsonValue UncertaintyJson(const std::optional<PositioningUncertainty>& u,
                                 bool with_local = true);
/// A budget's terms[] as text: "instrument 0.60, thermometer 1.38, ..." (U in key `u_key`).
std::string UncertaintyTermsText(const tools::JsonValue& terms, const char* u_key);

/// The parameter list of the standard with locations, then the per-position table, from
/// PositioningJson()'s object.
void WritePositioningText(std::ostream& out, const tools::JsonValue& evaluation);

/// Appends a section (heading, parameter table, charts, per-position table) to `page`.
void AddPositioningSection(report::HtmlPage* page, const PositioningResult& result);

/// The document `evaluate positioning` reports (--json, its report's .json, read back by
/// compare.hpp): command, name, source, conditions, the axis and its targets, and
/// PositioningJson() of every standard under "evaluations".
tools::JsonValue PositioningEvaluationJson(const PositioningEvaluation& ev);

/// The test, its conditions and axis, then WritePositioningText() of every standard, from
/// PositioningEvaluationJson()'s document.
void WritePositioningEvaluationText(std::ostream& out, const tools::JsonValue& ev);

/// The report page: the test conditions, then a section per standard.
report::HtmlPage PositioningEvaluationPage(const PositioningEvaluation& ev);

/// The fig. 10-style deviation chart alone (SVG), e.g. for reuse in other reports.
std::string PositioningDeviationChart(const PositioningResult& result, const std::string& title);

/// "j=2 ↓ (150.71 mm)": position number, direction if any, and target.
std::string DescribeLocation(const PositioningResult& result, const Extreme& e);

/// The same from a location object of the JSON ({"position", `target_key`, "direction"}), the
/// target in `unit`.
std::string DescribeLocation(const tools::JsonValue& location,
                             const std::string& target_key,
                             const std::string& unit);

}  // namespace volcomp::metrology
