// Output of a positioning evaluation: human-readable text, JSON (every parameter, per position
// and overall, with the location of each extreme) and an HTML section with the charts of
// GOST 27843-88 fig. 10 (X̄↑, X̄↓ with the X̄ ± kS bands per position, reversal B_j and
// repeatability R_j per position).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "volcomp/metrology/positioning_eval.hpp"
#include "volcomp/report/html_page.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::metrology {

/// The parameter list of the result's standard with locations, then the per-position table.
void WritePositioningText(std::ostream& out, const PositioningResult& result);

/// One JSON object with the standard, the per-position values and every overall parameter.
void WritePositioningJson(tools::JsonWriter& json, const PositioningResult& result);

/// Appends a section (heading, parameter table, charts, per-position table) to `page`.
void AddPositioningSection(report::HtmlPage* page, const PositioningResult& result);

/// The fig. 10-style deviation chart alone (SVG), e.g. for reuse in other reports.
std::string PositioningDeviationChart(const PositioningResult& result, const std::string& title);

/// "j=2 ↓ (150.71 mm)": position number, direction if any, and target.
std::string DescribeLocation(const PositioningResult& result, const Extreme& e);

}  // namespace volcomp::metrology
