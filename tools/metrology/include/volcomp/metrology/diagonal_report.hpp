// Output of an ISO 230-6 diagonal evaluation: JSON (what `evaluate diagonal` reports and its
// report's .json), the text laid out from that JSON, and HTML sections with one E plot (x̄↑ and
// x̄↓ against the distance along the diagonal, §8.1) per diagonal.
#pragma once

#include <ostream>

#include "volcomp/metrology/diagonal.hpp"
#include "volcomp/report/html_page.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::metrology {

tools::JsonValue DiagonalJson(const DiagonalEvaluation& ev);
/// The result table and E_d, B_d per group, from DiagonalJson()'s document.
void WriteDiagonalText(std::ostream& out, const tools::JsonValue& ev);
void AddDiagonalSections(report::HtmlPage* page, const DiagonalEvaluation& ev);
/// The report page: AddDiagonalSections() under the test's title.
report::HtmlPage DiagonalPage(const DiagonalEvaluation& ev);

}  // namespace volcomp::metrology
