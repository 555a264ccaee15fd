// Text, JSON and HTML output of ISO 230-6 evaluations.
#include "volcomp/metrology/diagonal_report.hpp"

#include <cstdio>

#include "volcomp/metrology/positioning_report.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/report/xy_chart.hpp"

namespace volcomp::metrology {
namespace {

using report::FormatFixed;

void JsonExtreme(tools::JsonWriter& j, const PositioningResult& r, const Extreme& e) {
  j.begin_object();
  j.key("value").value(e.value);
  j.key("position").value(static_cast<int64_t>(e.position + 1));
  j.key("distance_mm").value(r.positions[e.position].target);
  if (e.direction) j.key("direction").value(DirectionName(*e.direction));
  j.end_object();
}

void JsonGroup(tools::JsonWriter& j, const DiagonalGroupValue& g) {
  j.begin_object();
  j.key("E_d").value(g.E_d);
  j.key("E_d_from").value(g.E_from);
  j.key("B_d").value(g.B_d);
  j.key("B_d_from").value(g.B_from);
  j.key("diagonals").value(g.diagonals);
  j.end_object();
}

}  // namespace

void WriteDiagonalText(std::ostream& out, const DiagonalEvaluation& ev) {
  out << "ISO 230-6 diagonal displacement test: " << ev.source << "\n";
  if (!ev.conditions.empty()) out << "conditions: " << ConditionsText(ev.conditions) << "\n";
  out << "values in µm; E = bidirectional systematic positioning error, B = reversal value "
         "(ISO 230-2)\n\n";
  out << "  diagonal          kind   length mm  targets      E_i     B_i   E from max/min, B at\n";
  for (const auto& d : ev.diagonals) {
    char line[200];
    std::snprintf(line, sizeof line, "  %-16s  %-5s %10s %8zu %8s %7s   ", d.name.text.c_str(),
                  d.name.body ? "body" : "face", FormatFixed(d.length_mm, 1).c_str(),
                  d.evaluation.positions.size(), FormatFixed(d.E.value, 2).c_str(),
                  FormatFixed(d.B.value, 2).c_str());
    out << line << DescribeLocation(d.evaluation, d.E.max) << " / "
        << DescribeLocation(d.evaluation, d.E.min) << ", " << DescribeLocation(d.evaluation, d.B)
        << "\n";
  }
  out << "\n";
  if (ev.body) {
    out << "  body diagonals (" << ev.body->diagonals
        << "):  E_d = " << FormatFixed(ev.body->E_d, 2) << " µm (" << ev.body->E_from
        << "),  B_d = " << FormatFixed(ev.body->B_d, 2) << " µm (" << ev.body->B_from << ")\n";
  }
  for (const auto& f : ev.faces) {
    out << "  face " << f.name << " (" << f.diagonals << "):  E_d(" << f.name
        << ") = " << FormatFixed(f.E_d, 2) << " µm (" << f.E_from << "),  B_d(" << f.name
        << ") = " << FormatFixed(f.B_d, 2) << " µm (" << f.B_from << ")\n";
  }
}

void WriteDiagonalJson(tools::JsonWriter& j, const DiagonalEvaluation& ev) {
  j.begin_object();
  j.key("command").value("evaluate diagonal");
  j.key("standard").value("ISO 230-6:2002");
  j.key("source").value(ev.source);
  WriteConditionsJson(j, ev.conditions);
  j.key("unit").value("um");
  j.key("diagonals").begin_array();
  for (const auto& d : ev.diagonals) {
    const auto& r = d.evaluation;
    j.begin_object();
    j.key("name").value(d.name.text);
    j.key("kind").value(d.name.body ? "body" : "face");
    if (!d.name.body) j.key("plane").value(d.name.plane);
    if (!d.name.offset.empty()) j.key("offset").value(d.name.offset);
    j.key("length_mm").value(d.length_mm);
    j.key("E").begin_object();
    j.key("value").value(d.E.value);
    j.key("max");
    JsonExtreme(j, r, d.E.max);
    j.key("min");
    JsonExtreme(j, r, d.E.min);
    j.end_object();
    j.key("B");
    JsonExtreme(j, r, d.B);
    j.key("positions").begin_array();
    for (const auto& p : r.positions) {
      j.begin_object();
      j.key("j").value(static_cast<int64_t>(p.index + 1));
      j.key("distance_mm").value(p.target);
      j.key("mean_up").value(p.up->mean);
      j.key("mean_down").value(p.down->mean);
      j.key("s_up").value(p.up->s);
      j.key("s_down").value(p.down->s);
      j.key("reversal_B").value(*p.reversal);
      j.end_object();
    }
    j.end_array();
    j.end_object();
  }
  j.end_array();
  j.key("body");
  if (ev.body)
    JsonGroup(j, *ev.body);
  else
    j.null();
  j.key("faces").begin_object();
  for (const auto& f : ev.faces) {
    j.key(f.name);
    JsonGroup(j, f);
  }
  j.end_object();
  j.key("warnings").begin_array();
  for (const auto& w : ev.warnings) j.value(w);
  j.end_array();
  j.end_object();
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
    rows.push_back({"E_d (body)", FormatFixed(ev.body->E_d, 2), ev.body->E_from});
    rows.push_back({"B_d (body)", FormatFixed(ev.body->B_d, 2), ev.body->B_from});
  }
  for (const auto& f : ev.faces) {
    rows.push_back({"E_d(" + f.name + ")", FormatFixed(f.E_d, 2), f.E_from});
    rows.push_back({"B_d(" + f.name + ")", FormatFixed(f.B_d, 2), f.B_from});
  }
  page->Table({"parameter", "µm", "from diagonal"}, rows);
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

}  // namespace volcomp::metrology
