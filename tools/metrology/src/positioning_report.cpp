// Text, JSON and HTML output of positioning evaluations.
#include "volcomp/metrology/positioning_report.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include "json_fields.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/report/xy_chart.hpp"

namespace volcomp::metrology {
namespace {

using report::FormatFixed;
using tools::JsonValue;

std::string Num(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

// One overall parameter: either a span (max − min) or a single extreme or a plain value.
struct Parameter {
  std::string symbol;  // as printed in the standard, e.g. "A↑"
  std::string key;     // JSON key, e.g. "A_up"
  std::string meaning;
  double value = 0.0;
  std::optional<Span> span;
  std::optional<Extreme> at;
  std::optional<double> u;  // U at k = 2 when the test states its instrument
};

std::vector<Parameter> Parameters(const PositioningResult& r) {
  std::vector<Parameter> out;
  const bool gost = r.standard == Standard::kGost27843;
  // Spans over the travel carry U_length; the reversal (B) U_local; repeatability none (it is
  // the machine's scatter itself).
  std::optional<double> u_length, u_local;
  if (r.uncertainty) u_length = r.uncertainty->span_u, u_local = r.uncertainty->local_u;
  auto u_of = [&](const std::string& key) {
    return key == "B" || key == "B_max" || key == "B_mean" ? u_local : std::nullopt;
  };
  auto span = [&](const char* sym, const char* key, const std::string& meaning,
                  const std::optional<Span>& s) {
    if (s) out.push_back({sym, key, meaning, s->value, s, std::nullopt, u_length});
  };
  auto ext = [&](const char* sym, const char* key, const std::string& meaning,
                 const std::optional<Extreme>& e) {
    if (e) out.push_back({sym, key, meaning, e->value, std::nullopt, e, u_of(key)});
  };
  auto val = [&](const char* sym, const char* key, const std::string& meaning,
                 const std::optional<double>& v) {
    if (v) out.push_back({sym, key, meaning, *v, std::nullopt, std::nullopt, u_of(key)});
  };
  if (gost) {
    span("A", "A", "accuracy of bidirectional positioning, max(X̄+3S) − min(X̄−3S) (§1.14, (10))",
         r.accuracy);
    ext("R_max", "R_max", "repeatability of bidirectional positioning, max R_j (§1.11, (8))",
        r.repeatability);
    ext("B_max", "B_max", "maximum reversal (dead band), max |B_j| (§1.16)", r.reversal_max);
    span("A↑", "A_up", "accuracy of unidirectional positioning ↑ (§2.14.4)", r.accuracy_up);
    span("A↓", "A_down", "accuracy of unidirectional positioning ↓ (§2.14.4)", r.accuracy_down);
    ext("R↑", "R_up", "repeatability of unidirectional positioning ↑, max 6S_j↑ (§1.10, (7))",
        r.repeatability_up);
    ext("R↓", "R_down", "repeatability of unidirectional positioning ↓, max 6S_j↓ (§1.10, (7))",
        r.repeatability_down);
    val("B̄", "B_mean", "mean reversal, (1/m)·ΣB_j (§1.15)", r.reversal_mean);
    val("R̄", "R_mean", "mean bidirectional repeatability, (ΣR_j↑ + ΣR_j↓)/2m (§1.12, (9))",
        r.mean_repeatability);
  } else {
    span("E↑", "E_up", "unidirectional systematic positioning error ↑, max x̄↑ − min x̄↑",
         r.systematic_up);
    span("E↓", "E_down", "unidirectional systematic positioning error ↓", r.systematic_down);
    span("E", "E", "bidirectional systematic positioning error, max(x̄↑,x̄↓) − min(x̄↑,x̄↓)",
         r.systematic);
    span("M", "M", "range of mean bidirectional positioning error, max x̄_j − min x̄_j",
         r.mean_bidirectional_range);
    span("A↑", "A_up", "unidirectional accuracy ↑, max(x̄↑+2s↑) − min(x̄↑−2s↑)", r.accuracy_up);
    span("A↓", "A_down", "unidirectional accuracy ↓, max(x̄↓+2s↓) − min(x̄↓−2s↓)", r.accuracy_down);
    span("A", "A", "bidirectional accuracy, max(x̄+2s) − min(x̄−2s) over both directions",
         r.accuracy);
    ext("R↑", "R_up", "unidirectional repeatability ↑, max 4s_j↑", r.repeatability_up);
    ext("R↓", "R_down", "unidirectional repeatability ↓, max 4s_j↓", r.repeatability_down);
    ext("R", "R", "bidirectional repeatability, max R_j, R_j = max(2s↑+2s↓+|B_j|, R_j↑, R_j↓)",
        r.repeatability);
    ext("B", "B", "reversal value of the axis, max |B_j|", r.reversal_max);
    val("B̄", "B_mean", "mean reversal value, (1/m)·ΣB_j", r.reversal_mean);
  }
  return out;
}

// The sigma method as the JSON names it.
const char* SigmaKey(const PositioningResult& r) {
  if (r.standard == Standard::kIso230_2) return "sample";
  return r.sigma == SigmaMethod::kFormula ? "formula_5" : "range_6";
}

std::string SigmaText(const std::string& key) {
  if (key == "sample") return "s with the n − 1 divisor, coverage factor 2";
  return key == "formula_5" ? "S by formula (5), X̄ ± 3S"
                            : "S = W·a_n by the range method (6), X̄ ± 3S";
}

std::string SigmaText(const PositioningResult& r) { return SigmaText(SigmaKey(r)); }

JsonValue LocationJson(const PositioningResult& r, const Extreme& e) {
  JsonValue j = JsonValue::Object();
  j.Set("value", e.value);
  j.Set("position", static_cast<int64_t>(e.position + 1));
  j.Set(std::string("target_") + TargetUnit(r.kind), r.positions[e.position].target);
  if (e.direction) j.Set("direction", DirectionName(*e.direction));
  return j;
}

JsonValue DirectionJson(const std::optional<DirectionStats>& s) {
  if (!s) return JsonValue();
  JsonValue j = JsonValue::Object();
  j.Set("n", s->n);
  j.Set("mean", s->mean);
  j.Set("s", s->s);
  j.Set("range_w", s->range);
  j.Set("mean_plus_ks", s->upper);
  j.Set("mean_minus_ks", s->lower);
  j.Set("repeatability", s->repeatability);
  return j;
}

JsonValue OptionalJson(const std::optional<double>& v) { return v ? JsonValue(*v) : JsonValue(); }

std::string Cell(const JsonValue& v, int decimals) {
  return v.is_null() ? std::string("-") : FormatFixed(v.number, decimals);
}

std::string Opt(const std::optional<double>& v, int decimals) {
  return v ? FormatFixed(*v, decimals) : std::string("-");
}

}  // namespace

std::string UncertaintyTermsText(const JsonValue& terms, const char* u_key) {
  std::string text;
  for (const JsonValue& t : terms.array) {
    if (!text.empty()) text += ", ";
    text += json::Text(t, "name") + " " + FormatFixed(json::Number(t, u_key), 2);
  }
  return text;
}

JsonValue UncertaintyJson(const std::optional<PositioningUncertainty>& u, bool with_local) {
  if (!u) return JsonValue();
  JsonValue j = JsonValue::Object();
  const UncertaintyJsonKeys keys = UncertaintyKeys(u->kind);
  j.Set("k", 2);
  j.Set(keys.span, u->span);
  j.Set(keys.span_u, u->span_u);
  if (with_local) j.Set(keys.local_u, u->local_u);
  JsonValue terms = JsonValue::Array();
  for (const auto& t : u->terms) {
    JsonValue o = JsonValue::Object();
    o.Set("name", t.name);
    o.Set(keys.term_u, t.u);
    o.Set("basis", t.basis);
    terms.Push(std::move(o));
  }
  j.Set("terms", std::move(terms));
  return j;
}

std::string DescribeLocation(const PositioningResult& r, const Extreme& e) {
  std::string s = "j=" + std::to_string(e.position + 1);
  if (e.direction) s += std::string(" ") + DirectionSymbol(*e.direction);
  s += " (" + Num(r.positions[e.position].target) + " " + TargetUnit(r.kind) + ")";
  return s;
}

std::string DescribeLocation(const JsonValue& location,
                             const std::string& target_key,
                             const std::string& unit) {
  std::string s = "j=" + std::to_string(json::Integer(location, "position"));
  if (const JsonValue* d = location.get("direction")) {
    s += std::string(" ") + DirectionSymbol(d->string == "up" ? Direction::kUp : Direction::kDown);
  }
  return s + " (" + Num(json::Number(location, target_key)) + " " + unit + ")";
}

void WritePositioningText(std::ostream& out, const JsonValue& r) {
  const AxisKind kind = json::Text(r, "axis") == "rotary" ? AxisKind::kRotary : AxisKind::kLinear;
  const std::string& tu = json::Text(r, "target_unit");
  const std::string& standard = json::Text(r, "standard");
  out << standard << " (" << SigmaText(json::Text(r, "sigma_method")) << "), values in "
      << DeviationUnit(kind) << "\n";
  for (const auto& [key, p] : json::At(r, "parameters").object) {
    const std::string& symbol = json::Text(p, "symbol");
    const std::size_t width = report::DisplayWidth(symbol);
    out << "  " << symbol << std::string(width < 8 ? 8 - width : 1, ' ') << "= "
        << FormatFixed(json::Number(p, "value"), 2);
    const JsonValue& u = json::At(p, "U");
    if (!u.is_null()) out << " ± " << FormatFixed(u.number, 2);
    if (const JsonValue* max = p.get("max")) {
      const JsonValue& min = json::At(p, "min");
      out << "   max " << FormatFixed(json::Number(*max, "value"), 2) << " at "
          << DescribeLocation(*max, "target_" + tu, tu) << ", min "
          << FormatFixed(json::Number(min, "value"), 2) << " at "
          << DescribeLocation(min, "target_" + tu, tu);
    } else if (const JsonValue* at = p.get("at")) {
      out << "   at " << DescribeLocation(*at, "target_" + tu, tu);
    }
    out << "\n";
  }
  const JsonValue& budget = json::At(r, "uncertainty");
  if (!budget.is_null()) {
    const UncertaintyJsonKeys keys = UncertaintyKeys(kind);
    out << "  U (k = 2) of E, A, M over " << FormatFixed(json::Number(budget, keys.span), 1) << " "
        << tu << ": " << FormatFixed(json::Number(budget, keys.span_u), 2) << ", of B "
        << FormatFixed(json::Number(budget, keys.local_u), 2) << " (simplified budget:";
    out << " " << UncertaintyTermsText(json::At(budget, "terms"), keys.term_u) << ")\n";
  }
  const std::string ks = standard == StandardName(Standard::kGost27843) ? "3S" : "2s";
  out << "  per position:\n";
  out << "   j  P_j " << tu
      << "        X̄↑      S↑       X̄↓      S↓      B_j     R_j↑    R_j↓     R_j   X̄↑+" << ks
      << " X̄↑−" << ks << " X̄↓+" << ks << " X̄↓−" << ks << "\n";
  for (const JsonValue& p : json::At(r, "positions").array) {
    const JsonValue& up = json::At(p, "up");
    const JsonValue& down = json::At(p, "down");
    auto f = [](const JsonValue& dir, const char* key, int d) {
      return dir.is_null() ? std::string("-") : FormatFixed(json::Number(dir, key), d);
    };
    char line[320];
    std::snprintf(line, sizeof line,
                  "  %2lld %11s %8s %7s %8s %7s %8s %7s %7s %7s %7s %7s %7s %7s\n",
                  static_cast<long long>(json::Integer(p, "j")),
                  FormatFixed(json::Number(p, "target_" + tu), 3).c_str(), f(up, "mean", 2).c_str(),
                  f(up, "s", 3).c_str(), f(down, "mean", 2).c_str(), f(down, "s", 3).c_str(),
                  Cell(json::At(p, "reversal_B"), 2).c_str(), f(up, "repeatability", 2).c_str(),
                  f(down, "repeatability", 2).c_str(),
                  Cell(json::At(p, "repeatability_bidirectional"), 2).c_str(),
                  f(up, "mean_plus_ks", 2).c_str(), f(up, "mean_minus_ks", 2).c_str(),
                  f(down, "mean_plus_ks", 2).c_str(), f(down, "mean_minus_ks", 2).c_str());
    out << line;
  }
}

JsonValue PositioningJson(const PositioningResult& r) {
  JsonValue j = JsonValue::Object();
  j.Set("standard", StandardName(r.standard));
  j.Set("coverage_factor", r.k);
  j.Set("sigma_method", SigmaKey(r));
  j.Set("axis", r.kind == AxisKind::kLinear ? "linear" : "rotary");
  j.Set("deviation_unit", DeviationUnitAscii(r.kind));
  j.Set("target_unit", TargetUnit(r.kind));
  j.Set("bidirectional", r.bidirectional);
  JsonValue& parameters = j["parameters"] = JsonValue::Object();
  for (const Parameter& p : Parameters(r)) {
    JsonValue o = JsonValue::Object();
    o.Set("symbol", p.symbol);
    o.Set("value", p.value);
    o.Set("U", OptionalJson(p.u));
    if (p.span) {
      o.Set("max", LocationJson(r, p.span->max));
      o.Set("min", LocationJson(r, p.span->min));
    } else if (p.at) {
      o.Set("at", LocationJson(r, *p.at));
    }
    o.Set("meaning", p.meaning);
    parameters.Set(p.key, std::move(o));
  }
  JsonValue& positions = j["positions"] = JsonValue::Array();
  for (const auto& p : r.positions) {
    JsonValue o = JsonValue::Object();
    o.Set("j", static_cast<int64_t>(p.index + 1));
    o.Set(std::string("target_") + TargetUnit(r.kind), p.target);
    o.Set("up", DirectionJson(p.up));
    o.Set("down", DirectionJson(p.down));
    o.Set("reversal_B", OptionalJson(p.reversal));
    o.Set("mean_bidirectional", OptionalJson(p.mean_bidirectional));
    o.Set("repeatability_bidirectional", OptionalJson(p.repeatability_bidirectional));
    positions.Push(std::move(o));
  }
  j.Set("uncertainty", UncertaintyJson(r.uncertainty));
  JsonValue& warnings = j["warnings"] = JsonValue::Array();
  for (const auto& w : r.warnings) warnings.Push(w);
  return j;
}

std::string PositioningDeviationChart(const PositioningResult& r, const std::string& title) {
  const bool gost = r.standard == Standard::kGost27843;
  const std::string ks = gost ? "3S" : "2s";
  report::XyChart c;
  c.title = title;
  c.x_label = std::string("target position P_j, ") + TargetUnit(r.kind);
  c.y_label = std::string("deviation, ") + DeviationUnit(r.kind);
  struct DirSpec {
    Direction d;
    const char* color;
    const char* dash;
    report::Marker marker;
    double offset;
  };
  const DirSpec specs[] = {
      {Direction::kUp, "#1f5fbf", "", report::Marker::kTriangleUp, -3.0},
      {Direction::kDown, "#c0392b", "6 3", report::Marker::kTriangleDown, 3.0}};
  for (const auto& sp : specs) {
    report::XySeries mean, upper, lower;
    report::XyIntervals iv;
    for (const auto& p : r.positions) {
      const auto& s = sp.d == Direction::kUp ? p.up : p.down;
      if (!s) continue;
      mean.x.push_back(p.target);
      mean.y.push_back(s->mean);
      upper.x.push_back(p.target);
      upper.y.push_back(s->upper);
      lower.x.push_back(p.target);
      lower.y.push_back(s->lower);
      iv.x.push_back(p.target);
      iv.lower.push_back(s->lower);
      iv.upper.push_back(s->upper);
    }
    if (mean.x.empty()) continue;
    const std::string sym = DirectionSymbol(sp.d);
    mean.label = "X̄" + sym;
    mean.color = upper.color = lower.color = iv.color = sp.color;
    mean.dash = sp.dash;
    mean.marker = sp.marker;
    upper.label = "X̄" + sym + " ± " + ks;
    upper.dash = lower.dash = "2 2";
    upper.width_px = lower.width_px = 0.8;
    upper.marker = lower.marker = report::Marker::kNone;
    iv.offset_px = sp.offset;
    c.series.push_back(mean);
    c.series.push_back(upper);
    c.series.push_back(lower);
    c.intervals.push_back(iv);
  }
  const auto& a = r.accuracy ? r.accuracy : (r.accuracy_up ? r.accuracy_up : r.accuracy_down);
  if (a) {
    const std::string u = DeviationUnit(r.kind);
    c.hlines.push_back({"max(X̄+" + ks + ") = " + FormatFixed(a->max.value, 2), a->max.value});
    c.hlines.push_back({"min(X̄−" + ks + ") = " + FormatFixed(a->min.value, 2) +
                            "; A = " + FormatFixed(a->value, 2) + " " + u,
                        a->min.value});
  }
  return c.Render();
}

void AddPositioningSection(report::HtmlPage* page, const PositioningResult& r) {
  const bool gost = r.standard == Standard::kGost27843;
  const std::string u = DeviationUnit(r.kind);
  const std::string tu = TargetUnit(r.kind);
  page->Heading(2, std::string(StandardName(r.standard)) + " evaluation");
  page->Paragraph(SigmaText(r) + "; values in " + u + ".");
  std::vector<std::vector<std::string>> rows;
  for (const Parameter& p : Parameters(r)) {
    std::string where;
    if (p.span) {
      where = "max " + FormatFixed(p.span->max.value, 2) + " at " +
              DescribeLocation(r, p.span->max) + "; min " + FormatFixed(p.span->min.value, 2) +
              " at " + DescribeLocation(r, p.span->min);
    } else if (p.at) {
      where = DescribeLocation(r, *p.at);
    }
    rows.push_back({p.symbol,
                    FormatFixed(p.value, 2) + (p.u ? " ± " + FormatFixed(*p.u, 2) : std::string()),
                    where, p.meaning});
  }
  page->Table({"parameter", u + (r.uncertainty ? " (± U, k = 2)" : ""), "where", "meaning"}, rows);
  if (const auto& budget = r.uncertainty) {
    const bool rotary = budget->kind == AxisKind::kRotary;
    std::vector<std::vector<std::string>> terms;
    for (const auto& t : budget->terms) terms.push_back({t.name, FormatFixed(t.u, 2), t.basis});
    terms.push_back({"U of E, A, M", FormatFixed(budget->span_u, 2), "root sum of squares"});
    terms.push_back({"U of B", FormatFixed(budget->local_u, 2),
                     rotary ? "as E, A, M (no term cancels between the directions)"
                            : "instrument calibration and environment (length terms cancel)"});
    page->Paragraph(std::string("Measurement uncertainty (k = 2) over the measured ") +
                    (rotary ? "angle " : "length ") + FormatFixed(budget->span, 1) +
                    (rotary ? " deg" : " mm") +
                    ": a simplified budget after ISO/TR 230-9 (ISO 230-2:2014 Annex A's own "
                    "equations were not available; docs/metrology.md).");
    page->Table({"term", std::string("U, ") + DeviationUnit(budget->kind), "basis"}, terms);
  }

  page->Figure(
      PositioningDeviationChart(r, std::string(StandardName(r.standard)) +
                                       ": mean deviations and ±" + (gost ? "3S" : "2s") + " bands"),
      gost ? "Like GOST 27843-88 fig. 10: X̄↑ (solid) and X̄↓ (dashed) per target, with "
             "the limits X̄ ± 3S as bars and thin lines; A is the distance between the "
             "two horizontal lines."
           : "ISO 230-2: x̄↑ (solid) and x̄↓ (dashed) per target with the x̄ ± 2s limits.");
  if (r.bidirectional) {
    report::XyChart b;
    b.title = "Reversal B_j per position";
    b.x_label = "target position P_j, " + tu;
    b.y_label = "B_j, " + u;
    report::XyBars bars;
    bars.label = "B_j = X̄↑ − X̄↓";
    bars.color = "#8e44ad";
    for (const auto& p : r.positions) {
      bars.x.push_back(p.target);
      bars.y.push_back(*p.reversal);
    }
    b.bars.push_back(bars);
    if (r.reversal_mean)
      b.hlines.push_back({"B̄ = " + FormatFixed(*r.reversal_mean, 2), *r.reversal_mean});
    page->Figure(b.Render(760, 300), "Reversal value (zone of insensitivity) per position.");
  }
  report::XyChart rc;
  rc.title = "Repeatability per position";
  rc.x_label = "target position P_j, " + tu;
  rc.y_label = "R_j, " + u;
  auto add = [&](const char* label, const char* color, report::Marker m, auto get) {
    report::XySeries s;
    s.label = label;
    s.color = color;
    s.marker = m;
    for (const auto& p : r.positions) {
      const std::optional<double> v = get(p);
      if (!v) continue;
      s.x.push_back(p.target);
      s.y.push_back(*v);
    }
    if (!s.x.empty()) rc.series.push_back(s);
  };
  add(gost ? "R_j↑ = 6S↑" : "R_j↑ = 4s↑", "#1f5fbf", report::Marker::kTriangleUp,
      [](const PositionStats& p) {
        return p.up ? std::optional<double>(p.up->repeatability) : std::nullopt;
      });
  add(gost ? "R_j↓ = 6S↓" : "R_j↓ = 4s↓", "#c0392b", report::Marker::kTriangleDown,
      [](const PositionStats& p) {
        return p.down ? std::optional<double>(p.down->repeatability) : std::nullopt;
      });
  add("R_j bidirectional", "#222222", report::Marker::kSquare,
      [](const PositionStats& p) { return p.repeatability_bidirectional; });
  page->Figure(rc.Render(760, 300), "Repeatability of positioning per position.");

  std::vector<std::vector<std::string>> prow;
  for (const auto& p : r.positions) {
    auto f = [](const std::optional<DirectionStats>& s, double DirectionStats::*m, int d) {
      return s ? FormatFixed((*s).*m, d) : std::string("-");
    };
    prow.push_back({std::to_string(p.index + 1), FormatFixed(p.target, 3),
                    f(p.up, &DirectionStats::mean, 2), f(p.up, &DirectionStats::s, 3),
                    f(p.up, &DirectionStats::upper, 2), f(p.up, &DirectionStats::lower, 2),
                    f(p.down, &DirectionStats::mean, 2), f(p.down, &DirectionStats::s, 3),
                    f(p.down, &DirectionStats::upper, 2), f(p.down, &DirectionStats::lower, 2),
                    Opt(p.reversal, 2), Opt(p.repeatability_bidirectional, 2)});
  }
  const std::string ks = gost ? "3S" : "2s";
  const std::string s = gost ? "S" : "s";
  page->Table({"j", "P_j " + tu, "X̄↑", s + "↑", "X̄↑+" + ks, "X̄↑−" + ks, "X̄↓", s + "↓", "X̄↓+" + ks,
               "X̄↓−" + ks, "B_j", "R_j"},
              prow);
  if (!r.warnings.empty()) {
    page->Heading(3, "Warnings");
    page->List(r.warnings);
  }
}

JsonValue PositioningEvaluationJson(const PositioningEvaluation& ev) {
  JsonValue j = JsonValue::Object();
  j.Set("command", "evaluate positioning");
  j.Set("name", PositioningReportName(ev));
  j.Set("source", ev.source);
  j.Set("conditions", ConditionsJson(ev.conditions));
  j.Set("positions", static_cast<int64_t>(ev.positions));
  j.Set("axis_kind", ev.kind == AxisKind::kLinear ? "linear" : "rotary");
  j.Set("input_units", ev.read_in_inches ? "in" : ev.kind == AxisKind::kLinear ? "mm" : "deg");
  JsonValue directions = JsonValue::Array();
  if (ev.has_up) directions.Push(DirectionName(Direction::kUp));
  if (ev.has_down) directions.Push(DirectionName(Direction::kDown));
  j.Set("directions", std::move(directions));
  JsonValue evaluations = JsonValue::Array();
  for (const PositioningResult& r : ev.results) evaluations.Push(PositioningJson(r));
  j.Set("evaluations", std::move(evaluations));
  return j;
}

void WritePositioningEvaluationText(std::ostream& out, const JsonValue& ev) {
  out << "positioning test: " << json::Text(ev, "source") << "\n";
  const JsonValue& conditions = json::At(ev, "conditions");
  if (!conditions.object.empty()) out << "conditions: " << ConditionsText(conditions) << "\n";
  std::string directions;
  for (const JsonValue& d : json::At(ev, "directions").array) {
    directions += DirectionSymbol(d.string == "up" ? Direction::kUp : Direction::kDown);
  }
  out << json::Text(ev, "axis_kind") << " axis, " << json::Integer(ev, "positions")
      << " target positions, directions: " << directions << "\n";
  if (json::Text(ev, "input_units") == "in") out << "units: read in inches, results in mm/µm\n";
  out << "\n";
  for (const JsonValue& r : json::At(ev, "evaluations").array) {
    WritePositioningText(out, r);
    out << "\n";
  }
}

report::HtmlPage PositioningEvaluationPage(const PositioningEvaluation& ev) {
  const auto axis = ev.conditions.Find("axis");
  report::HtmlPage page("Positioning test" + (axis ? " of axis " + *axis : std::string()) + ": " +
                        ev.source);
  page.Paragraph(std::string(ev.kind == AxisKind::kLinear ? "Linear" : "Rotary") + " axis, " +
                 std::to_string(ev.positions) + " target positions.");
  AddConditionsSection(&page, ev.conditions);
  for (const PositioningResult& r : ev.results) AddPositioningSection(&page, r);
  return page;
}

}  // namespace volcomp::metrology
