// Text, JSON and HTML output of ISO 230-6 evaluations.
#include "volcomp/metrology/diagonal_report.hpp"

#include <cstdio>

#include "json_fields.hpp"
#include "volcomp/metrology/positioning_report.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/report/xy_chart.hpp"

namespace volcomp::metrology {
namespace {

using report::FormatFixed;
using tools::JsonValue;

JsonValue ExtremeJson(const PositioningResult& r, const Extreme& e) {
  JsonValue j = JsonValue::Object();
  j.Set("value", e.value);
  j.Set("position", static_cast<int64_t>(e.position + 1));
  j.Set("distance_mm", r.positions[e.position].target);
  if (e.direction) j.Set("direction", DirectionName(*e.direction));
  return j;
}

JsonValue GroupJson(const DiagonalGroupValue& g) {
  JsonValue j = JsonValue::Object();
  j.Set("E_d", g.E_d);
  j.Set("E_d_from", g.E_from);
  j.Set("B_d", g.B_d);
  j.Set("B_d_from", g.B_from);
  j.Set("diagonals", g.diagonals);
  j.Set("E_d_U", g.E_d_U ? JsonValue(*g.E_d_U) : JsonValue());
  j.Set("B_d_U", g.B_d_U ? JsonValue(*g.B_d_U) : JsonValue());
  return j;
}

// "12.34" or "12.34 ± 1.20" from a group's value and its U (null when not stated).
std::string WithU(const JsonValue& g, const char* value, const char* u) {
  const JsonValue& uv = json::At(g, u);
  return FormatFixed(json::Number(g, value), 2) +
         (uv.is_null() ? std::string() : " ± " + FormatFixed(uv.number, 2));
}

std::string WithU(double value, const std::optional<double>& u) {
  return FormatFixed(value, 2) + (u ? " ± " + FormatFixed(*u, 2) : std::string());
}

std::string Where(const JsonValue& location) {
  return DescribeLocation(location, "distance_mm", "mm");
}

}  // namespace

JsonValue DiagonalJson(const DiagonalEvaluation& ev) {
  JsonValue j = JsonValue::Object();
  j.Set("command", "evaluate diagonal");
  j.Set("standard", "ISO 230-6:2002");
  j.Set("source", ev.source);
  j.Set("conditions", ConditionsJson(ev.conditions));
  j.Set("unit", "um");
  JsonValue diagonals = JsonValue::Array();
  for (const auto& d : ev.diagonals) {
    const auto& r = d.evaluation;
    JsonValue o = JsonValue::Object();
    o.Set("name", d.name.text);
    o.Set("kind", d.name.body ? "body" : "face");
    if (!d.name.body) o.Set("plane", d.name.plane);
    if (!d.name.offset.empty()) o.Set("offset", d.name.offset);
    o.Set("length_mm", d.length_mm);
    JsonValue e = JsonValue::Object();
    e.Set("value", d.E.value);
    e.Set("max", ExtremeJson(r, d.E.max));
    e.Set("min", ExtremeJson(r, d.E.min));
    const auto& u = r.uncertainty;
    e.Set("U", u ? JsonValue(u->span_u) : JsonValue());
    o.Set("E", std::move(e));
    JsonValue b = ExtremeJson(r, d.B);
    b.Set("U", u ? JsonValue(u->local_u) : JsonValue());
    o.Set("B", std::move(b));
    JsonValue positions = JsonValue::Array();
    for (const auto& p : r.positions) {
      JsonValue q = JsonValue::Object();
      q.Set("j", static_cast<int64_t>(p.index + 1));
      q.Set("distance_mm", p.target);
      q.Set("mean_up", p.up->mean);
      q.Set("mean_down", p.down->mean);
      q.Set("s_up", p.up->s);
      q.Set("s_down", p.down->s);
      q.Set("reversal_B", *p.reversal);
      positions.Push(std::move(q));
    }
    o.Set("positions", std::move(positions));
    diagonals.Push(std::move(o));
  }
  j.Set("diagonals", std::move(diagonals));
  j.Set("body", ev.body ? GroupJson(*ev.body) : JsonValue());
  JsonValue faces = JsonValue::Object();
  for (const auto& f : ev.faces) faces.Set(f.name, GroupJson(f));
  j.Set("faces", std::move(faces));
  JsonValue warnings = JsonValue::Array();
  for (const auto& w : ev.warnings) warnings.Push(w);
  j.Set("warnings", std::move(warnings));
  return j;
}

void WriteDiagonalText(std::ostream& out, const JsonValue& ev) {
  out << "ISO 230-6 diagonal displacement test: " << json::Text(ev, "source") << "\n";
  const JsonValue& conditions = json::At(ev, "conditions");
  if (!conditions.object.empty()) out << "conditions: " << ConditionsText(conditions) << "\n";
  out << "values in µm; E = bidirectional systematic positioning error, B = reversal value "
         "(ISO 230-2)\n\n";
  out << "  diagonal          kind   length mm  targets      E_i     B_i   E from max/min, B at\n";
  for (const JsonValue& d : json::At(ev, "diagonals").array) {
    const JsonValue& e = json::At(d, "E");
    const JsonValue& b = json::At(d, "B");
    char line[200];
    std::snprintf(
        line, sizeof line, "  %-16s  %-5s %10s %8zu %8s %7s   ", json::Text(d, "name").c_str(),
        json::Text(d, "kind").c_str(), FormatFixed(json::Number(d, "length_mm"), 1).c_str(),
        json::At(d, "positions").array.size(), FormatFixed(json::Number(e, "value"), 2).c_str(),
        FormatFixed(json::Number(b, "value"), 2).c_str());
    out << line << Where(json::At(e, "max")) << " / " << Where(json::At(e, "min")) << ", "
        << Where(b) << "\n";
  }
  out << "\n";
  const JsonValue& body = json::At(ev, "body");
  if (!body.is_null()) {
    out << "  body diagonals (" << json::Integer(body, "diagonals")
        << "):  E_d = " << WithU(body, "E_d", "E_d_U") << " µm (" << json::Text(body, "E_d_from")
        << "),  B_d = " << WithU(body, "B_d", "B_d_U") << " µm (" << json::Text(body, "B_d_from")
        << ")\n";
  }
  for (const auto& [name, f] : json::At(ev, "faces").object) {
    out << "  face " << name << " (" << json::Integer(f, "diagonals") << "):  E_d(" << name
        << ") = " << WithU(f, "E_d", "E_d_U") << " µm (" << json::Text(f, "E_d_from") << "),  B_d("
        << name << ") = " << WithU(f, "B_d", "B_d_U") << " µm (" << json::Text(f, "B_d_from")
        << ")\n";
  }
}

void AddDiagonalSections(report::HtmlPage* page, const DiagonalEvaluation& ev) {
  page->Paragraph("Source: " + ev.source +
                  ". Values in µm. E is the bidirectional systematic "
                  "positioning error and B the reversal value of ISO 230-2, evaluated along "
                  "each diagonal (ISO 230-6 §6).");
  AddConditionsSection(page, ev.conditions);
  page->Heading(2, "Results");
  std::vector<std::vector<std::string>> rows;
  if (ev.body) {
    rows.push_back({"E_d (body)", WithU(ev.body->E_d, ev.body->E_d_U), ev.body->E_from});
    rows.push_back({"B_d (body)", WithU(ev.body->B_d, ev.body->B_d_U), ev.body->B_from});
  }
  for (const auto& f : ev.faces) {
    rows.push_back({"E_d(" + f.name + ")", WithU(f.E_d, f.E_d_U), f.E_from});
    rows.push_back({"B_d(" + f.name + ")", WithU(f.B_d, f.B_d_U), f.B_from});
  }
  const bool with_u =
      ev.body ? ev.body->E_d_U.has_value() : !ev.faces.empty() && ev.faces[0].E_d_U.has_value();
  page->Table({"parameter", with_u ? "µm (± U, k = 2)" : "µm", "from diagonal"}, rows);
  rows.clear();
  for (const auto& d : ev.diagonals) {
    rows.push_back({d.name.text, d.name.body ? "body" : "face " + d.name.plane,
                    FormatFixed(d.length_mm, 1), std::to_string(d.evaluation.positions.size()),
                    FormatFixed(d.E.value, 2), FormatFixed(d.B.value, 2),
                    DescribeLocation(d.evaluation, d.B)});
  }
  page->Table({"diagonal", "kind", "length mm", "targets", "E_i", "B_i", "B_i at"}, rows);
  for (const auto& d : ev.diagonals) {
    const auto& r = d.evaluation;
    report::XyChart c;
    c.title = "Diagonal " + d.name.text + ": E_i = " + FormatFixed(d.E.value, 2) +
              " µm, B_i = " + FormatFixed(d.B.value, 2) + " µm";
    c.x_label = "distance along the diagonal from its start, mm";
    c.y_label = "mean deviation, µm";
    report::XySeries up, down;
    up.label = "x̄↑";
    up.color = "#1f5fbf";
    up.marker = report::Marker::kTriangleUp;
    down.label = "x̄↓";
    down.color = "#c0392b";
    down.dash = "6 3";
    down.marker = report::Marker::kTriangleDown;
    for (const auto& p : r.positions) {
      up.x.push_back(p.target);
      up.y.push_back(p.up->mean);
      down.x.push_back(p.target);
      down.y.push_back(p.down->mean);
    }
    c.series = {up, down};
    c.hlines.push_back({"max = " + FormatFixed(d.E.max.value, 2), d.E.max.value});
    c.hlines.push_back({"min = " + FormatFixed(d.E.min.value, 2), d.E.min.value});
    page->Figure(c.Render(760, 320), "Diagonal " + d.name.text +
                                         ": mean deviations per direction; E_i is the distance "
                                         "between the two horizontal lines.");
  }
  if (!ev.warnings.empty()) {
    page->Heading(3, "Warnings");
    page->List(ev.warnings);
  }
}

report::HtmlPage DiagonalPage(const DiagonalEvaluation& ev) {
  report::HtmlPage page("ISO 230-6 diagonal displacement test");
  AddDiagonalSections(&page, ev);
  return page;
}

}  // namespace volcomp::metrology
