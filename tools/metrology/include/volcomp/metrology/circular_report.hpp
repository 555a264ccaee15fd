// Output of an ISO 230-4 circular test evaluation: JSON (every figure, the test conditions and
// the warnings), the text laid out from that JSON only, and the polar plot of a ballbar report
// (both directions about the common least-squares centre, deviation magnified, the G(b) zone)
// as SVG and in an HTML page.
#pragma once

#include <optional>
#include <ostream>
#include <string>

#include "volcomp/metrology/circular.hpp"
#include "volcomp/metrology/circular_uncertainty.hpp"
#include "volcomp/metrology/test_conditions.hpp"
#include "volcomp/report/html_page.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::metrology {

struct CircularEvaluation {
  CircularData data;
  CircularResult result;
  TestConditions conditions;
  std::optional<CircularUncertainty> uncertainty;  // with the reading's U stated
};

/// The figures of one test: points_cw, points_ccw, G_cw_um, G_ccw_um, G_b_um, H_um, H_angle_deg
/// (null for a missing direction), F_max_um, F_min_um, centre_offset_um {x, y},
/// mean_radius_deviation_um. The one writer of these keys (evaluate circular, volcomp-sim run
/// --ballbar, the demo's summary).
tools::JsonValue CircularFiguresJson(const CircularResult& r);
/// CircularFiguresJson()'s keys, the context (source, conditions, radius, warnings) and the
/// readings (paths {cw, ccw} {angle_deg, deviation_um}), and `uncertainty` (null, or k,
/// shape_U_um for G, G(b), H with shape_terms[] {name, U_um, basis}, F_U_um and the radial
/// budget `F` over the nominal radius, both null when the radius is not known).
tools::JsonValue CircularJson(const CircularEvaluation& ev);
/// The figures as text, from CircularJson()'s document.
void WriteCircularText(std::ostream& out, const tools::JsonValue& ev);
/// The polar plot as an SVG document.
std::string CircularPolarSvg(const CircularEvaluation& ev);
/// The report page: figures, conditions, polar plot and warnings.
report::HtmlPage CircularPage(const CircularEvaluation& ev);

}  // namespace volcomp::metrology
