// Output of an ISO 230-7 evaluation: JSON (every value about every centre, centres,
// fundamentals, reversal), the text laid out from that JSON, and HTML with polar plots (total
// cloud, synchronous plot, PC, LSC and the chosen MRS/MIC/MCC centres with the two-circle zone
// about the preferred centre).
#pragma once

#include <optional>
#include <ostream>

#include "volcomp/metrology/rotary_eval.hpp"
#include "volcomp/report/html_page.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::metrology {

tools::JsonValue RotaryJson(const RotaryEvaluation& ev,
                            const std::optional<ReversalResult>& reversal);
/// The values about each centre per measurement, fundamentals and reversal, from RotaryJson()'s
/// document.
void WriteRotaryText(std::ostream& out, const tools::JsonValue& ev);
void AddRotarySections(report::HtmlPage* page,
                       const RotaryEvaluation& ev,
                       const std::optional<ReversalResult>& reversal);
/// The report page: AddRotarySections() under the test's title.
report::HtmlPage RotaryPage(const RotaryEvaluation& ev,
                            const std::optional<ReversalResult>& reversal);

}  // namespace volcomp::metrology
