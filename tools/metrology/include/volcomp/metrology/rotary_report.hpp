// Output of an ISO 230-7 evaluation: text, JSON (every value about every centre, centres,
// fundamentals, reversal), and HTML with polar plots (total cloud, synchronous plot, PC and
// LSC/MZ centres with the two-circle zone about the preferred centre).
#pragma once

#include <optional>
#include <ostream>

#include "volcomp/metrology/rotary_eval.hpp"
#include "volcomp/report/html_page.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::metrology {

void WriteRotaryText(std::ostream& out,
                     const RotaryEvaluation& ev,
                     const std::optional<ReversalResult>& reversal);
void WriteRotaryJson(tools::JsonWriter& json,
                     const RotaryEvaluation& ev,
                     const std::optional<ReversalResult>& reversal);
void AddRotarySections(report::HtmlPage* page,
                       const RotaryEvaluation& ev,
                       const std::optional<ReversalResult>& reversal);

}  // namespace volcomp::metrology
