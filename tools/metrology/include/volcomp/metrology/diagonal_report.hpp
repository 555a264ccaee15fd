// Output of an ISO 230-6 diagonal evaluation: text, JSON, and an HTML page with one E plot
// (x̄↑ and x̄↓ against the distance along the diagonal, §8.1) per diagonal.
#pragma once

#include <ostream>

#include "volcomp/metrology/diagonal.hpp"
#include "volcomp/report/html_page.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::metrology {

void WriteDiagonalText(std::ostream& out, const DiagonalEvaluation& ev);
void WriteDiagonalJson(tools::JsonWriter& json, const DiagonalEvaluation& ev);
void AddDiagonalSections(report::HtmlPage* page, const DiagonalEvaluation& ev);

}  // namespace volcomp::metrology
