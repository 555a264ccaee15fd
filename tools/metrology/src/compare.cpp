// Before/after comparison of evaluation results.
#include "volcomp/metrology/compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <utility>

#include "json_fields.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/report/polar_chart.hpp"
#include "volcomp/report/xy_chart.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::metrology {
namespace {

using tools::JsonValue;

Unexpected<Failure> Refuse(std::string message) {
  return Fail(Error::kInputInvalid, std::move(message));
}

std::string Command(const JsonValue& j) {
  const JsonValue* c = j.get("command");
  return c != nullptr && c->is_string() ? c->string : std::string();
}

std::string Text(const JsonValue* v) {
  return v != nullptr && v->is_string() ? v->string : std::string();
}

std::optional<double> Number(const JsonValue* v) {
  if (v == nullptr || !v->is_number()) return std::nullopt;
  return v->number;
}

ComparedValue Value(const std::string& symbol, const std::string& meaning, double b, double a) {
  ComparedValue v{symbol, meaning, b, a, std::nullopt, std::nullopt, std::nullopt};
  if (std::fabs(b) > 0.0) v.reduction_pct = 100.0 * (std::fabs(b) - std::fabs(a)) / std::fabs(b);
  return v;
}

std::vector<std::pair<std::string, std::string>> Conditions(const JsonValue& j) {
  std::vector<std::pair<std::string, std::string>> out;
  if (const JsonValue* c = j.get("conditions")) {
    for (const auto& [k, v] : c->object) out.emplace_back(k, Text(&v));
  }
  return out;
}

const JsonValue* FindByKey(const JsonValue* array,
                           const std::string& key,
                           const std::string& text) {
  if (array == nullptr) return nullptr;
  for (const JsonValue& e : array->array) {
    if (Text(e.get(key)) == text) return &e;
  }
  return nullptr;
}

// Mean deviations per target of one evaluation (or one diagonal): x, ↑, ↓.
void MeanCurves(const JsonValue* positions,
                const std::string& x_key,
                bool diagonal,
                std::vector<double>* x,
                std::vector<double>* up,
                std::vector<double>* down) {
  if (positions == nullptr) return;
  for (const JsonValue& p : positions->array) {
    const auto t = Number(p.get(x_key));
    if (!t) continue;
    x->push_back(*t);
    std::optional<double> u, d;
    if (diagonal) {
      u = Number(p.get("mean_up"));
      d = Number(p.get("mean_down"));
    } else {
      if (const JsonValue* s = p.get("up")) u = Number(s->get("mean"));
      if (const JsonValue* s = p.get("down")) d = Number(s->get("mean"));
    }
    up->push_back(u.value_or(NAN));
    down->push_back(d.value_or(NAN));
  }
}

void ComparePositioning(const JsonValue& b,
                        const JsonValue& a,
                        ComparedResult* r,
                        std::vector<std::string>* warnings) {
  const JsonValue* eb = b.get("evaluations");
  const JsonValue* ea = a.get("evaluations");
  if (eb == nullptr || ea == nullptr) return;
  for (const JsonValue& before : eb->array) {
    const std::string standard = Text(before.get("standard"));
    const JsonValue* after = FindByKey(ea, "standard", standard);
    if (after == nullptr) {
      warnings->push_back(r->name + ": " + standard + " only in the before results");
      continue;
    }
    const bool linear = Text(before.get("deviation_unit")) != "arcsec";
    ComparedTable t{standard, linear ? "µm" : "″", {}};
    const JsonValue* pb = before.get("parameters");
    const JsonValue* pa = after->get("parameters");
    if (pb == nullptr || pa == nullptr) continue;
    for (const auto& [key, param] : pb->object) {
      const JsonValue* other = pa->get(key);
      const auto vb = Number(param.get("value"));
      const auto va = other != nullptr ? Number(other->get("value")) : std::nullopt;
      if (!vb || !va) continue;
      ComparedValue v = Value(Text(param.get("symbol")), Text(param.get("meaning")), *vb, *va);
      v.u_before = Number(param.get("U"));
      v.u_after = Number(other->get("U"));
      t.values.push_back(v);
    }
    r->tables.push_back(t);
    if (r->series.empty()) {
      ComparedSeries s;
      const std::string tu = Text(before.get("target_unit"));
      s.title = r->name + ": mean deviations before and after";
      s.x_label = "target position, " + tu;
      s.unit = t.unit;
      MeanCurves(before.get("positions"), "target_" + tu, false, &s.x_before, &s.up_before,
                 &s.down_before);
      MeanCurves(after->get("positions"), "target_" + tu, false, &s.x_after, &s.up_after,
                 &s.down_after);
      r->series.push_back(s);
    }
  }
}

void AddGroup(const std::string& title,
              const JsonValue* gb,
              const JsonValue* ga,
              ComparedResult* r) {
  if (gb == nullptr || ga == nullptr || !gb->is_object() || !ga->is_object()) return;
  ComparedTable t{title, "µm", {}};
  for (const char* key : {"E_d", "B_d"}) {
    const auto vb = Number(gb->get(key));
    const auto va = Number(ga->get(key));
    if (vb && va) {
      ComparedValue v = Value(key,
                              Text(gb->get(std::string(key) + "_from")) + " → " +
                                  Text(ga->get(std::string(key) + "_from")),
                              *vb, *va);
      v.u_before = Number(gb->get(std::string(key) + "_U"));
      v.u_after = Number(ga->get(std::string(key) + "_U"));
      t.values.push_back(v);
    }
  }
  if (!t.values.empty()) r->tables.push_back(t);
}

void CompareDiagonals(const JsonValue& b,
                      const JsonValue& a,
                      ComparedResult* r,
                      std::vector<std::string>* warnings) {
  AddGroup("body diagonals", b.get("body"), a.get("body"), r);
  if (const JsonValue* fb = b.get("faces")) {
    const JsonValue* fa = a.get("faces");
    for (const auto& [plane, g] : fb->object) {
      AddGroup("face " + plane, &g, fa != nullptr ? fa->get(plane) : nullptr, r);
    }
  }
  ComparedTable each{"each diagonal", "µm", {}};
  const JsonValue* db = b.get("diagonals");
  const JsonValue* da = a.get("diagonals");
  if (db == nullptr) return;
  for (const JsonValue& d : db->array) {
    const std::string name = Text(d.get("name"));
    const JsonValue* other = FindByKey(da, "name", name);
    if (other == nullptr) {
      warnings->push_back(r->name + ": diagonal " + name + " only in the before results");
      continue;
    }
    for (const char* key : {"E", "B"}) {
      const JsonValue* vb = d.get(key);
      const JsonValue* va = other->get(key);
      const auto nb = vb != nullptr ? Number(vb->get("value")) : std::nullopt;
      const auto na = va != nullptr ? Number(va->get("value")) : std::nullopt;
      if (nb && na) each.values.push_back(Value(std::string(key) + "_i", name, *nb, *na));
    }
    ComparedSeries s;
    s.title = "diagonal " + name + ": mean deviations before and after";
    s.x_label = "distance along the diagonal, mm";
    s.unit = "µm";
    MeanCurves(d.get("positions"), "distance_mm", true, &s.x_before, &s.up_before, &s.down_before);
    MeanCurves(other->get("positions"), "distance_mm", true, &s.x_after, &s.up_after,
               &s.down_after);
    r->series.push_back(s);
  }
  if (!each.values.empty()) r->tables.push_back(each);
}

// The readings of one direction about the result's own least-squares centre, mean removed (as
// `evaluate circular` plots them).
ComparedPolar::Path CircularResiduals(const JsonValue& result,
                                      const char* direction,
                                      const char* who) {
  ComparedPolar::Path p;
  p.label = std::string(who) + " " + (std::string(direction) == "cw" ? "CW" : "CCW");
  const JsonValue* paths = result.get("paths");
  const JsonValue* path = paths != nullptr ? paths->get(direction) : nullptr;
  const JsonValue* offset = result.get("centre_offset_um");
  if (path == nullptr || offset == nullptr) return p;
  const double x = Number(offset->get("x")).value_or(0.0);
  const double y = Number(offset->get("y")).value_or(0.0);
  const double mean = Number(result.get("mean_radius_deviation_um")).value_or(0.0);
  const JsonValue* angles = path->get("angle_deg");
  const JsonValue* deviations = path->get("deviation_um");
  if (angles == nullptr || deviations == nullptr) return p;
  std::vector<std::pair<double, double>> points;
  for (std::size_t i = 0; i < angles->array.size() && i < deviations->array.size(); ++i) {
    const double a = angles->array[i].number;
    const double t = a * 3.14159265358979323846 / 180.0;
    points.emplace_back(a, deviations->array[i].number - x * std::cos(t) - y * std::sin(t) - mean);
  }
  std::sort(points.begin(), points.end());
  for (const auto& [a, v] : points) {
    p.angle_deg.push_back(a);
    p.value_um.push_back(v);
  }
  return p;
}

void CompareCircular(const JsonValue& b, const JsonValue& a, ComparedResult* r) {
  ComparedTable t{"ISO 230-4 circular test", "µm", {}};
  const std::pair<const char*, const char*> figures[] = {
      {"G_cw_um", "G_cw"}, {"G_ccw_um", "G_ccw"}, {"G_b_um", "G(b)"},
      {"H_um", "H"},       {"F_max_um", "F_max"}, {"F_min_um", "F_min"}};
  const std::map<std::string, const char*> meaning = {
      {"G_cw", "circular deviation, CW"},
      {"G_ccw", "circular deviation, CCW"},
      {"G(b)", "bidirectional circular deviation"},
      {"H", "circular hysteresis"},
      {"F_max", "largest radial deviation from the nominal circle"},
      {"F_min", "smallest radial deviation from the nominal circle"}};
  // Each figure's U (evaluate circular's `uncertainty`: shape_U_um for G and H, F_U_um for F).
  auto u_of = [](const JsonValue& result, const std::string& key) -> std::optional<double> {
    const JsonValue* u = result.get("uncertainty");
    if (u == nullptr || u->is_null()) return std::nullopt;
    return Number(u->get(key.rfind("F_", 0) == 0 ? "F_U_um" : "shape_U_um"));
  };
  for (const auto& [key, symbol] : figures) {
    const auto vb = Number(b.get(key));
    const auto va = Number(a.get(key));
    if (!vb || !va) continue;
    ComparedValue v = Value(symbol, meaning.at(symbol), *vb, *va);
    v.u_before = u_of(b, key);
    v.u_after = u_of(a, key);
    t.values.push_back(v);
  }
  r->tables.push_back(t);
  ComparedPolar polar;
  polar.title = r->name + ": both directions before and after";
  for (const char* direction : {"cw", "ccw"}) {
    ComparedPolar::Path pb = CircularResiduals(b, direction, "before");
    ComparedPolar::Path pa = CircularResiduals(a, direction, "after");
    if (!pb.angle_deg.empty()) polar.before.push_back(std::move(pb));
    if (!pa.angle_deg.empty()) polar.after.push_back(std::move(pa));
  }
  if (!polar.before.empty() || !polar.after.empty()) r->polars.push_back(std::move(polar));
}

std::string Reduction(const std::optional<double>& pct) {
  return pct ? report::FormatFixed(*pct, 1) + " %" : std::string("-");
}

std::string Reduction(const ComparedValue& v) { return Reduction(v.reduction_pct); }

// "18.00" or "18.00 ± 5.98" when the evaluation stated U.
std::string WithU(double value, const std::optional<double>& u) {
  return report::FormatFixed(value, 2) + (u ? " ± " + report::FormatFixed(*u, 2) : std::string());
}

std::string WithU(double value, const JsonValue& u) {
  return WithU(value, u.is_number() ? std::optional<double>(u.number) : std::nullopt);
}

JsonValue PairsJson(const std::vector<std::pair<std::string, std::string>>& pairs) {
  JsonValue o = JsonValue::Object();
  for (const auto& [k, v] : pairs) o.object.emplace_back(k, v);
  return o;
}

}  // namespace

Expected<std::vector<LoadedResult>> LoadResults(const std::string& path) {
  std::error_code ec;
  std::vector<std::string> files;
  if (std::filesystem::is_directory(path, ec)) {
    // increment(ec), not ++: the library reports a directory it cannot list instead of throwing.
    for (std::filesystem::directory_iterator it(path, ec), end; !ec && it != end;
         it.increment(ec)) {
      if (it->path().extension() == ".json") files.push_back(it->path().string());
    }
    if (ec) return Fail(Error::kIoError, path + ": cannot list: " + ec.message());
    std::sort(files.begin(), files.end());
  } else if (std::filesystem::is_regular_file(path, ec)) {
    files.push_back(path);
  } else {
    return Refuse(path + ": no such report directory or result file");
  }
  std::vector<LoadedResult> out;
  for (const std::string& f : files) {
    VOLCOMP_TRY_ASSIGN(const std::string text, tools::ReadTextFile(f));
    VOLCOMP_TRY_ASSIGN(JsonValue json, tools::ParseJson(text, f));
    LoadedResult r{std::filesystem::path(f).stem().string(), f, std::move(json)};
    const std::string command = Command(r.json);
    if (command == "evaluate positioning" || command == "evaluate diagonal" ||
        command == "evaluate circular") {
      out.push_back(std::move(r));
    } else if (files.size() == 1) {
      return Refuse(f +
                    ": not a result of `volcomp evaluate positioning`, `evaluate diagonal` or "
                    "`evaluate circular` (written by --report or --json)");
    }
  }
  if (out.empty()) return Refuse(path + ": no positioning, diagonal or circular results (*.json)");
  return out;
}

Expected<Comparison> CompareResults(const std::vector<LoadedResult>& before,
                                    const std::vector<LoadedResult>& after) {
  Comparison c;
  const bool single = before.size() == 1 && after.size() == 1;
  for (const LoadedResult& b : before) {
    const LoadedResult* a = nullptr;
    for (const LoadedResult& x : after) {
      if (x.name == b.name || single) a = &x;
    }
    if (a == nullptr) {
      c.warnings.push_back(b.name + " (" + b.path + "): no after result of that name");
      continue;
    }
    if (Command(b.json) != Command(a->json)) {
      c.warnings.push_back(b.name + ": " + b.path + " and " + a->path +
                           " hold different kinds of results; not compared");
      continue;
    }
    ComparedResult r;
    r.name = b.name;
    r.before_source = Text(b.json.get("source"));
    r.after_source = Text(a->json.get("source"));
    r.conditions_before = Conditions(b.json);
    r.conditions_after = Conditions(a->json);
    if (Command(b.json) == "evaluate positioning") {
      r.kind = "positioning";
      ComparePositioning(b.json, a->json, &r, &c.warnings);
    } else if (Command(b.json) == "evaluate circular") {
      r.kind = "circular";
      CompareCircular(b.json, a->json, &r);
    } else {
      r.kind = "diagonal";
      CompareDiagonals(b.json, a->json, &r, &c.warnings);
    }
    c.results.push_back(std::move(r));
  }
  for (const LoadedResult& a : after) {
    bool paired = single;
    for (const LoadedResult& b : before) paired = paired || b.name == a.name;
    if (!paired) c.warnings.push_back(a.name + " (" + a.path + "): no before result of that name");
  }
  if (c.results.empty()) {
    return Refuse("no result appears both before and after (results are paired by name)");
  }
  return c;
}

JsonValue ComparisonJson(const Comparison& c) {
  JsonValue j = JsonValue::Object();
  j.Set("command", "report compare");
  JsonValue results = JsonValue::Array();
  for (const ComparedResult& r : c.results) {
    JsonValue o = JsonValue::Object();
    o.Set("name", r.name);
    o.Set("kind", r.kind);
    o.Set("before_source", r.before_source);
    o.Set("after_source", r.after_source);
    o.Set("conditions_before", PairsJson(r.conditions_before));
    o.Set("conditions_after", PairsJson(r.conditions_after));
    JsonValue tables = JsonValue::Array();
    for (const ComparedTable& t : r.tables) {
      JsonValue table = JsonValue::Object();
      table.Set("title", t.title);
      table.Set("unit", t.unit);
      JsonValue values = JsonValue::Array();
      for (const ComparedValue& v : t.values) {
        JsonValue value = JsonValue::Object();
        value.Set("symbol", v.symbol);
        value.Set("meaning", v.meaning);
        value.Set("before", v.before);
        value.Set("after", v.after);
        value.Set("reduction_pct", v.reduction_pct ? JsonValue(*v.reduction_pct) : JsonValue());
        value.Set("before_U", v.u_before ? JsonValue(*v.u_before) : JsonValue());
        value.Set("after_U", v.u_after ? JsonValue(*v.u_after) : JsonValue());
        values.Push(std::move(value));
      }
      table.Set("values", std::move(values));
      tables.Push(std::move(table));
    }
    o.Set("tables", std::move(tables));
    results.Push(std::move(o));
  }
  j.Set("results", std::move(results));
  JsonValue warnings = JsonValue::Array();
  for (const std::string& w : c.warnings) warnings.Push(w);
  j.Set("warnings", std::move(warnings));
  return j;
}

void WriteComparisonText(std::ostream& out, const JsonValue& comparison) {
  for (const JsonValue& r : json::At(comparison, "results").array) {
    out << json::Text(r, "name") << " (" << json::Text(r, "kind") << "): before "
        << json::Text(r, "before_source") << ", after " << json::Text(r, "after_source") << "\n";
    for (const JsonValue& t : json::At(r, "tables").array) {
      const std::string& title = json::Text(t, "title");
      out << "  " << title << ", values in " << json::Text(t, "unit") << "\n";
      for (const JsonValue& v : json::At(t, "values").array) {
        const JsonValue& pct = json::At(v, "reduction_pct");
        char line[200];
        std::snprintf(
            line, sizeof line, "    %s %10s -> %10s   %9s",
            report::PadRight(json::Text(v, "symbol"), 6).c_str(),
            WithU(json::Number(v, "before"), json::At(v, "before_U")).c_str(),
            WithU(json::Number(v, "after"), json::At(v, "after_U")).c_str(),
            Reduction(pct.is_null() ? std::nullopt : std::optional<double>(pct.number)).c_str());
        out << line;
        if (title == "each diagonal") out << "   " << json::Text(v, "meaning");
        out << "\n";
      }
    }
    out << "\n";
  }
}

void AddComparisonSections(report::HtmlPage* page, const Comparison& c) {
  std::vector<std::vector<std::string>> summary;
  for (const ComparedResult& r : c.results) {
    for (const ComparedTable& t : r.tables) {
      for (const ComparedValue& v : t.values) {
        if (v.symbol == "A" || v.symbol == "E_d" || v.symbol == "G(b)" || v.symbol == "H") {
          summary.push_back({r.name, t.title, v.symbol, report::FormatFixed(v.before, 2),
                             report::FormatFixed(v.after, 2), Reduction(v)});
        }
      }
    }
  }
  page->Paragraph(
      "Reduction = (|before| − |after|) / |before|. Values in µm (arc-seconds for "
      "rotary axes).");
  if (!summary.empty()) {
    page->Heading(2, "Summary");
    page->Table({"result", "evaluation", "parameter", "before", "after", "reduction"}, summary);
  }
  if (!c.warnings.empty()) {
    page->Heading(3, "Warnings");
    page->List(c.warnings);
  }
  for (const ComparedResult& r : c.results) {
    page->Heading(2, r.name);
    page->Paragraph("Before: " + r.before_source + ". After: " + r.after_source + ".");
    if (!r.conditions_before.empty() || !r.conditions_after.empty()) {
      std::vector<std::vector<std::string>> rows;
      std::vector<std::string> keys;
      for (const auto& kv : r.conditions_before) keys.push_back(kv.first);
      for (const auto& kv : r.conditions_after) {
        if (std::find(keys.begin(), keys.end(), kv.first) == keys.end()) keys.push_back(kv.first);
      }
      auto value = [](const std::vector<std::pair<std::string, std::string>>& list,
                      const std::string& k) {
        for (const auto& kv : list) {
          if (kv.first == k) return kv.second;
        }
        return std::string("-");
      };
      for (const auto& k : keys) {
        rows.push_back({k, value(r.conditions_before, k), value(r.conditions_after, k)});
      }
      page->Table({"test condition", "before", "after"}, rows);
    }
    for (const ComparedTable& t : r.tables) {
      page->Heading(3, t.title);
      std::vector<std::vector<std::string>> rows;
      for (const ComparedValue& v : t.values) {
        rows.push_back({v.symbol, WithU(v.before, v.u_before), WithU(v.after, v.u_after),
                        Reduction(v), v.meaning});
      }
      page->Table({"parameter", "before, " + t.unit, "after, " + t.unit, "reduction", "meaning"},
                  rows);
    }
    for (const ComparedSeries& s : r.series) {
      report::XyChart chart;
      chart.title = s.title;
      chart.x_label = s.x_label;
      chart.y_label = "mean deviation, " + s.unit;
      struct Line {
        const std::vector<double>* x;
        const std::vector<double>* y;
        const char* label;
        const char* color;
        const char* dash;
        report::Marker marker;
      };
      for (const Line& l :
           {Line{&s.x_before, &s.up_before, "before x̄↑", "#c0392b", "",
                 report::Marker::kTriangleUp},
            Line{&s.x_before, &s.down_before, "before x̄↓", "#c0392b", "6 3",
                 report::Marker::kTriangleDown},
            Line{&s.x_after, &s.up_after, "after x̄↑", "#1f5fbf", "", report::Marker::kTriangleUp},
            Line{&s.x_after, &s.down_after, "after x̄↓", "#1f5fbf", "6 3",
                 report::Marker::kTriangleDown}}) {
        report::XySeries series;
        series.label = l.label;
        series.x = *l.x;
        series.y = *l.y;
        series.color = l.color;
        series.dash = l.dash;
        series.marker = l.marker;
        if (!series.x.empty()) chart.series.push_back(series);
      }
      page->Figure(chart.Render(760, 320), s.title + ".");
    }
    for (const ComparedPolar& p : r.polars) {
      report::PolarChart chart;
      chart.title = p.title + " (µm)";
      for (const auto* side : {&p.before, &p.after}) {
        for (const ComparedPolar::Path& path : *side) {
          report::PolarTrace trace;
          trace.label = path.label;
          const bool before = side == &p.before;
          const bool cw = path.label.find("CCW") == std::string::npos;
          trace.color = before ? (cw ? "#c0392b" : "#e67e22") : (cw ? "#1f5fbf" : "#17becf");
          trace.width_px = before ? 1.2 : 1.8;
          trace.angle_deg = path.angle_deg;
          trace.value = path.value_um;
          chart.traces.push_back(std::move(trace));
        }
      }
      chart.centres.push_back({"least-squares centre", 0.0, 0.0, "#000000"});
      page->Figure(chart.Render(),
                   p.title +
                       ", each about its own least-squares centre, the deviation magnified "
                       "on one scale for both.");
    }
  }
}

}  // namespace volcomp::metrology
