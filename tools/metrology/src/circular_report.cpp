// Text, JSON, SVG and HTML output of ISO 230-4 circular test evaluations.
#include "volcomp/metrology/circular_report.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "json_fields.hpp"
#include "volcomp/metrology/polar_fit.hpp"
#include "volcomp/metrology/positioning_report.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/report/polar_chart.hpp"

namespace volcomp::metrology {
namespace {

using report::FormatFixed;
using tools::JsonValue;

JsonValue NumberOrNull(bool present, double v) { return present ? JsonValue(v) : JsonValue(); }

// A figure "12.34 µm", with " ± U" when the document carries the figure's U (key `u_key` of
// its uncertainty object).
std::string Um(const JsonValue& ev, const std::string& key, const char* u_key = nullptr) {
  const JsonValue& v = json::At(ev, key);
  if (v.is_null()) return "-";
  std::string text = FormatFixed(v.number, 2);
  const JsonValue* u = ev.get("uncertainty");
  if (u_key && u && !u->is_null() && !json::At(*u, u_key).is_null()) {
    text += " ± " + FormatFixed(json::Number(*u, u_key), 2);
  }
  return text + " µm";
}

report::PolarTrace Trace(const CircularPath& p,
                         const CentreFit& centre,
                         const char* label,
                         const char* color) {
  report::PolarTrace t;
  t.label = label;
  t.color = color;
  t.width_px = 1.6;
  std::vector<std::pair<double, double>> points;
  const auto r = ResidualsAbout(p.angle_deg, p.deviation_um, centre.a, centre.b);
  for (std::size_t i = 0; i < r.size(); ++i) points.emplace_back(p.angle_deg[i], r[i]);
  std::sort(points.begin(), points.end());
  for (const auto& [a, v] : points) {
    t.angle_deg.push_back(a);
    t.value.push_back(v - centre.mean);
  }
  return t;
}

report::PolarChart Chart(const CircularEvaluation& ev) {
  const CircularResult& r = ev.result;
  const CentreFit common{r.mean_radius_dev_um, r.centre_offset_x_um, r.centre_offset_y_um};
  report::PolarChart pc;
  pc.title = "Circular test (µm) about the least-squares centre";
  if (r.has_cw) pc.traces.push_back(Trace(ev.data.cw, common, "CW", "#1f5fbf"));
  if (r.has_ccw) pc.traces.push_back(Trace(ev.data.ccw, common, "CCW", "#d62728"));
  double lo = 0, hi = 0;
  bool first = true;
  for (const auto& t : pc.traces) {
    for (double v : t.value) {
      lo = first ? v : std::min(lo, v);
      hi = first ? v : std::max(hi, v);
      first = false;
    }
  }
  pc.zones.push_back({r.has_cw && r.has_ccw ? "G(b) zone" : "G zone", 0.0, 0.0, lo, hi, "#2ca02c"});
  pc.centres.push_back({"least-squares centre", 0.0, 0.0, "#000000"});
  return pc;
}

}  // namespace

JsonValue CircularFiguresJson(const CircularResult& r) {
  const bool both = r.has_cw && r.has_ccw;
  JsonValue j = JsonValue::Object();
  j.Set("points_cw", static_cast<uint64_t>(r.points_cw));
  j.Set("points_ccw", static_cast<uint64_t>(r.points_ccw));
  j.Set("G_cw_um", NumberOrNull(r.has_cw, r.G_cw_um));
  j.Set("G_ccw_um", NumberOrNull(r.has_ccw, r.G_ccw_um));
  j.Set("G_b_um", NumberOrNull(both, r.G_b_um));
  j.Set("H_um", NumberOrNull(both, r.H_um));
  j.Set("H_angle_deg", NumberOrNull(both, r.H_angle_deg));
  j.Set("F_max_um", r.F_max_um);
  j.Set("F_min_um", r.F_min_um);
  JsonValue offset = JsonValue::Object();
  offset.Set("x", r.centre_offset_x_um);
  offset.Set("y", r.centre_offset_y_um);
  j.Set("centre_offset_um", std::move(offset));
  j.Set("mean_radius_deviation_um", r.mean_radius_dev_um);
  return j;
}

JsonValue CircularJson(const CircularEvaluation& ev) {
  JsonValue j = JsonValue::Object();
  j.Set("command", "evaluate circular");
  j.Set("standard", "ISO 230-4:2005");
  j.Set("source", ev.data.source);
  j.Set("conditions", ConditionsJson(ev.conditions));
  j.Set("nominal_radius_mm",
        NumberOrNull(ev.data.nominal_radius_mm > 0, ev.data.nominal_radius_mm));
  for (auto& [key, value] : CircularFiguresJson(ev.result).object) j.Set(key, std::move(value));
  // The readings (for plots and `report compare`'s overlay), as read.
  JsonValue paths = JsonValue::Object();
  for (const auto& [name, path] :
       {std::pair<const char*, const CircularPath*>{"cw", &ev.data.cw}, {"ccw", &ev.data.ccw}}) {
    JsonValue o = JsonValue::Object();
    JsonValue angles = JsonValue::Array(), deviations = JsonValue::Array();
    for (double a : path->angle_deg) angles.Push(a);
    for (double d : path->deviation_um) deviations.Push(d);
    o.Set("angle_deg", std::move(angles));
    o.Set("deviation_um", std::move(deviations));
    paths.Set(name, std::move(o));
  }
  j.Set("paths", std::move(paths));
  JsonValue warnings = JsonValue::Array();
  for (const auto& w : ev.result.warnings) warnings.Push(w);
  j.Set("warnings", std::move(warnings));
  JsonValue u;
  if (const auto& cu = ev.uncertainty) {
    u = JsonValue::Object();
    u.Set("k", 2);
    u.Set("shape_U_um", cu->shape_u_um);
    JsonValue terms = JsonValue::Array();
    for (const auto& t : cu->shape_terms) {
      JsonValue o = JsonValue::Object();
      o.Set("name", t.name).Set("U_um", t.u).Set("basis", t.basis);
      terms.Push(std::move(o));
    }
    u.Set("shape_terms", std::move(terms));
    u.Set("F_U_um", cu->radial ? JsonValue(cu->radial->span_u) : JsonValue());
    u.Set("F", UncertaintyJson(cu->radial, /*with_local=*/false));  // F: one length, R
  }
  j.Set("uncertainty", std::move(u));
  return j;
}

void WriteCircularText(std::ostream& out, const JsonValue& ev) {
  out << "ISO 230-4 circular test: " << json::Text(ev, "source") << "\n";
  const JsonValue& conditions = json::At(ev, "conditions");
  if (!conditions.object.empty()) out << "conditions: " << ConditionsText(conditions) << "\n";
  out << json::Integer(ev, "points_cw") << " CW and " << json::Integer(ev, "points_ccw")
      << " CCW readings";
  const JsonValue& radius = json::At(ev, "nominal_radius_mm");
  if (!radius.is_null())
    out << " on a nominal radius of " << FormatFixed(radius.number, 3) << " mm";
  out << "\n";
  out << "  circular deviation G  CW " << Um(ev, "G_cw_um", "shape_U_um") << ", CCW "
      << Um(ev, "G_ccw_um", "shape_U_um") << " (each about its own least-squares centre)\n";
  out << "  bidirectional G(b)    " << Um(ev, "G_b_um", "shape_U_um")
      << " (one least-squares centre)\n";
  out << "  circular hysteresis H " << Um(ev, "H_um", "shape_U_um");
  const JsonValue& h_angle = json::At(ev, "H_angle_deg");
  if (!h_angle.is_null()) out << " at " << FormatFixed(h_angle.number, 1) << "°";
  out << "\n";
  out << "  radial deviation F    max " << Um(ev, "F_max_um", "F_U_um") << ", min "
      << Um(ev, "F_min_um", "F_U_um") << " (nominal centre and radius)\n";
  const JsonValue& offset = json::At(ev, "centre_offset_um");
  out << "  centre offset         (" << FormatFixed(json::Number(offset, "x"), 2) << ", "
      << FormatFixed(json::Number(offset, "y"), 2) << ") µm; mean radius deviation "
      << FormatFixed(json::Number(ev, "mean_radius_deviation_um"), 2) << " µm\n";
  const JsonValue* u = ev.get("uncertainty");
  if (u && !u->is_null()) {
    out << "  U (k = 2) of G, G(b), H " << FormatFixed(json::Number(*u, "shape_U_um"), 2) << " µm ("
        << UncertaintyTermsText(json::At(*u, "shape_terms"), "U_um") << "; simplified budget)";
    if (const JsonValue& f = json::At(*u, "F"); !f.is_null()) {
      out << "; of F " << FormatFixed(json::Number(f, "length_U_um"), 2)
          << " µm over R = " << FormatFixed(json::Number(f, "length_mm"), 1) << " mm ("
          << UncertaintyTermsText(json::At(f, "terms"), "U_um") << ")";
    }
    out << "\n";
  }
}

std::string CircularPolarSvg(const CircularEvaluation& ev) { return Chart(ev).Render(); }

report::HtmlPage CircularPage(const CircularEvaluation& ev) {
  const CircularResult& r = ev.result;
  const bool both = r.has_cw && r.has_ccw;
  report::HtmlPage page("ISO 230-4 circular test");
  page.Paragraph("Source: " + ev.data.source + "; " + std::to_string(r.points_cw) + " CW and " +
                 std::to_string(r.points_ccw) + " CCW readings.");
  AddConditionsSection(&page, ev.conditions);
  const auto& cu = ev.uncertainty;
  const std::optional<double> shape_u = cu ? std::optional<double>(cu->shape_u_um) : std::nullopt;
  const std::optional<double> f_u =
      cu && cu->radial ? std::optional<double>(cu->radial->span_u) : std::nullopt;
  auto um = [](bool present, double v, const std::optional<double>& u) {
    if (!present) return std::string("-");
    return FormatFixed(v, 2) + (u ? " ± " + FormatFixed(*u, 2) : std::string());
  };
  page.Table(
      {"figure", cu ? "value µm (± U, k = 2)" : "value µm", "about"},
      {{"G (CW)", um(r.has_cw, r.G_cw_um, shape_u), "least-squares centre of the CW path"},
       {"G (CCW)", um(r.has_ccw, r.G_ccw_um, shape_u), "least-squares centre of the CCW path"},
       {"G(b)", um(both, r.G_b_um, shape_u), "least-squares centre of both paths"},
       {"H", um(both, r.H_um, shape_u), "least-squares centre of both paths"},
       {"F max", um(true, r.F_max_um, f_u), "nominal centre and radius"},
       {"F min", um(true, r.F_min_um, f_u), "nominal centre and radius"},
       {"centre offset x", FormatFixed(r.centre_offset_x_um, 2), "from the nominal centre"},
       {"centre offset y", FormatFixed(r.centre_offset_y_um, 2), "from the nominal centre"}});
  if (cu) {
    std::vector<std::vector<std::string>> rows;
    for (const auto& t : cu->shape_terms) {
      rows.push_back({"G, G(b), H", t.name, FormatFixed(t.u, 2), t.basis});
    }
    rows.push_back({"G, G(b), H", "U", FormatFixed(cu->shape_u_um, 2), "root sum of squares"});
    if (cu->radial) {
      for (const auto& t : cu->radial->terms) {
        rows.push_back({"F", t.name, FormatFixed(t.u, 2), t.basis});
      }
      rows.push_back({"F", "U", FormatFixed(cu->radial->span_u, 2), "root sum of squares"});
    }
    page.Paragraph(
        "Measurement uncertainty (k = 2): a simplified budget after ISO/TR 230-9 (ISO 230-4's "
        "own annex was not available; docs/metrology.md). Errors common to every reading "
        "cancel in G, G(b) and H; F against the nominal radius carries them all.");
    page.Table({"figures", "term", "U, µm", "basis"}, rows);
  }
  page.Figure(
      CircularPolarSvg(ev),
      "Both paths about their common least-squares centre, the deviation magnified "
      "about a base circle; the two circles enclose both paths (their separation is G(b)).");
  if (!r.warnings.empty()) {
    page.Heading(3, "Warnings");
    page.List(r.warnings);
  }
  return page;
}

}  // namespace volcomp::metrology
