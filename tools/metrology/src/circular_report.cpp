// Text, JSON, SVG and HTML output of ISO 230-4 circular test evaluations.
#include "volcomp/metrology/circular_report.hpp"

#include <algorithm>
#include <utility>

#include "json_fields.hpp"
#include "volcomp/metrology/polar_fit.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/report/polar_chart.hpp"

namespace volcomp::metrology {
namespace {

using report::FormatFixed;
using tools::JsonValue;

JsonValue NumberOrNull(bool present, double v) { return present ? JsonValue(v) : JsonValue(); }

std::string Um(const JsonValue& ev, const std::string& key) {
  const JsonValue& v = json::At(ev, key);
  return v.is_null() ? "-" : FormatFixed(v.number, 2) + " µm";
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
  out << "  circular deviation G  CW " << Um(ev, "G_cw_um") << ", CCW " << Um(ev, "G_ccw_um")
      << " (each about its own least-squares centre)\n";
  out << "  bidirectional G(b)    " << Um(ev, "G_b_um") << " (one least-squares centre)\n";
  out << "  circular hysteresis H " << Um(ev, "H_um");
  const JsonValue& h_angle = json::At(ev, "H_angle_deg");
  if (!h_angle.is_null()) out << " at " << FormatFixed(h_angle.number, 1) << "°";
  out << "\n";
  out << "  radial deviation F    max " << Um(ev, "F_max_um") << ", min " << Um(ev, "F_min_um")
      << " (nominal centre and radius)\n";
  const JsonValue& offset = json::At(ev, "centre_offset_um");
  out << "  centre offset         (" << FormatFixed(json::Number(offset, "x"), 2) << ", "
      << FormatFixed(json::Number(offset, "y"), 2) << ") µm; mean radius deviation "
      << FormatFixed(json::Number(ev, "mean_radius_deviation_um"), 2) << " µm\n";
}

std::string CircularPolarSvg(const CircularEvaluation& ev) { return Chart(ev).Render(); }

report::HtmlPage CircularPage(const CircularEvaluation& ev) {
  const CircularResult& r = ev.result;
  const bool both = r.has_cw && r.has_ccw;
  report::HtmlPage page("ISO 230-4 circular test");
  page.Paragraph("Source: " + ev.data.source + "; " + std::to_string(r.points_cw) + " CW and " +
                 std::to_string(r.points_ccw) + " CCW readings.");
  AddConditionsSection(&page, ev.conditions);
  auto um = [](bool present, double v) { return present ? FormatFixed(v, 2) : std::string("-"); };
  page.Table(
      {"figure", "value µm", "about"},
      {{"G (CW)", um(r.has_cw, r.G_cw_um), "least-squares centre of the CW path"},
       {"G (CCW)", um(r.has_ccw, r.G_ccw_um), "least-squares centre of the CCW path"},
       {"G(b)", um(both, r.G_b_um), "least-squares centre of both paths"},
       {"H", um(both, r.H_um), "least-squares centre of both paths"},
       {"F max", FormatFixed(r.F_max_um, 2), "nominal centre and radius"},
       {"F min", FormatFixed(r.F_min_um, 2), "nominal centre and radius"},
       {"centre offset x", FormatFixed(r.centre_offset_x_um, 2), "from the nominal centre"},
       {"centre offset y", FormatFixed(r.centre_offset_y_um, 2), "from the nominal centre"}});
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
