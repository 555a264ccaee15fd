// Text, JSON and HTML output of positioning evaluations.
#include "volcomp/metrology/positioning_report.hpp"

#include <cmath>
#include <optional>
#include <sstream>

#include "volcomp/report/format.hpp"
#include "volcomp/report/xy_chart.hpp"

namespace volcomp::metrology {
namespace {

using report::FormatFixed;

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
};

std::vector<Parameter> Parameters(const PositioningResult& r) {
  std::vector<Parameter> out;
  const bool gost = r.standard == Standard::kGost27843;
  auto span = [&](const char* sym, const char* key, const std::string& meaning,
                  const std::optional<Span>& s) {
    if (s) out.push_back({sym, key, meaning, s->value, s, std::nullopt});
  };
  auto ext = [&](const char* sym, const char* key, const std::string& meaning,
                 const std::optional<Extreme>& e) {
    if (e) out.push_back({sym, key, meaning, e->value, std::nullopt, e});
  };
  auto val = [&](const char* sym, const char* key, const std::string& meaning,
                 const std::optional<double>& v) {
    if (v) out.push_back({sym, key, meaning, *v, std::nullopt, std::nullopt});
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

std::string SigmaText(const PositioningResult& r) {
  if (r.standard == Standard::kIso230_2) return "s with the n − 1 divisor, coverage factor 2";
  return r.sigma == SigmaMethod::kFormula ? "S by formula (5), X̄ ± 3S"
                                          : "S = W·a_n by the range method (6), X̄ ± 3S";
}

void JsonLocation(tools::JsonWriter& j, const PositioningResult& r, const Extreme& e) {
  j.begin_object();
  j.key("value").value(e.value);
  j.key("position").value(static_cast<int64_t>(e.position + 1));
  j.key(std::string("target_") + TargetUnit(r.kind)).value(r.positions[e.position].target);
  if (e.direction) j.key("direction").value(DirectionName(*e.direction));
  j.end_object();
}

void JsonDirection(tools::JsonWriter& j, const DirectionStats& s) {
  j.begin_object();
  j.key("n").value(s.n);
  j.key("mean").value(s.mean);
  j.key("s").value(s.s);
  j.key("range_w").value(s.range);
  j.key("mean_plus_ks").value(s.upper);
  j.key("mean_minus_ks").value(s.lower);
  j.key("repeatability").value(s.repeatability);
  j.end_object();
}

std::string Opt(const std::optional<double>& v, int decimals) {
  return v ? FormatFixed(*v, decimals) : std::string("-");
}

}  // namespace

std::string DescribeLocation(const PositioningResult& r, const Extreme& e) {
  std::string s = "j=" + std::to_string(e.position + 1);
  if (e.direction) s += std::string(" ") + DirectionSymbol(*e.direction);
  s += " (" + Num(r.positions[e.position].target) + " " + TargetUnit(r.kind) + ")";
  return s;
}

void WritePositioningText(std::ostream& out, const PositioningResult& r) {
  const std::string u = DeviationUnit(r.kind);
  out << StandardName(r.standard) << " (" << SigmaText(r) << "), values in " << u << "\n";
  for (const Parameter& p : Parameters(r)) {
    const std::size_t width = report::DisplayWidth(p.symbol);
    out << "  " << p.symbol << std::string(width < 8 ? 8 - width : 1, ' ') << "= "
        << FormatFixed(p.value, 2);
    if (p.span) {
      out << "   max " << FormatFixed(p.span->max.value, 2) << " at "
          << DescribeLocation(r, p.span->max) << ", min " << FormatFixed(p.span->min.value, 2)
          << " at " << DescribeLocation(r, p.span->min);
    } else if (p.at) {
      out << "   at " << DescribeLocation(r, *p.at);
    }
    out << "\n";
  }
  const bool gost = r.standard == Standard::kGost27843;
  const std::string ks = gost ? "3S" : "2s";
  out << "  per position:\n";
  out << "   j  P_j " << TargetUnit(r.kind)
      << "        X̄↑      S↑       X̄↓      S↓      B_j     R_j↑    R_j↓     R_j   X̄↑+" << ks
      << " X̄↑−" << ks << " X̄↓+" << ks << " X̄↓−" << ks << "\n";
  for (const auto& p : r.positions) {
    char line[320];
    auto f = [](const std::optional<DirectionStats>& s, double DirectionStats::*m, int d) {
      return s ? FormatFixed((*s).*m, d) : std::string("-");
    };
    std::snprintf(
        line, sizeof line, "  %2zu %11s %8s %7s %8s %7s %8s %7s %7s %7s %7s %7s %7s %7s\n",
        p.index + 1, FormatFixed(p.target, 3).c_str(), f(p.up, &DirectionStats::mean, 2).c_str(),
        f(p.up, &DirectionStats::s, 3).c_str(), f(p.down, &DirectionStats::mean, 2).c_str(),
        f(p.down, &DirectionStats::s, 3).c_str(), Opt(p.reversal, 2).c_str(),
        f(p.up, &DirectionStats::repeatability, 2).c_str(),
        f(p.down, &DirectionStats::repeatability, 2).c_str(),
        Opt(p.repeatability_bidirectional, 2).c_str(), f(p.up, &DirectionStats::upper, 2).c_str(),
        f(p.up, &DirectionStats::lower, 2).c_str(), f(p.down, &DirectionStats::upper, 2).c_str(),
        f(p.down, &DirectionStats::lower, 2).c_str());
    out << line;
  }
}

void WritePositioningJson(tools::JsonWriter& j, const PositioningResult& r) {
  j.begin_object();
  j.key("standard").value(StandardName(r.standard));
  j.key("coverage_factor").value(r.k);
  j.key("sigma_method")
      .value(r.standard == Standard::kIso230_2  ? "sample"
             : r.sigma == SigmaMethod::kFormula ? "formula_5"
                                                : "range_6");
  j.key("axis").value(r.kind == AxisKind::kLinear ? "linear" : "rotary");
  j.key("deviation_unit").value(DeviationUnitAscii(r.kind));
  j.key("target_unit").value(TargetUnit(r.kind));
  j.key("bidirectional").value(r.bidirectional);
  j.key("parameters").begin_object();
  for (const Parameter& p : Parameters(r)) {
    j.key(p.key).begin_object();
    j.key("symbol").value(p.symbol);
    j.key("value").value(p.value);
    if (p.span) {
      j.key("max");
      JsonLocation(j, r, p.span->max);
      j.key("min");
      JsonLocation(j, r, p.span->min);
    } else if (p.at) {
      j.key("at");
      JsonLocation(j, r, *p.at);
    }
    j.key("meaning").value(p.meaning);
    j.end_object();
  }
  j.end_object();
  j.key("positions").begin_array();
  for (const auto& p : r.positions) {
    j.begin_object();
    j.key("j").value(static_cast<int64_t>(p.index + 1));
    j.key(std::string("target_") + TargetUnit(r.kind)).value(p.target);
    j.key("up");
    if (p.up)
      JsonDirection(j, *p.up);
    else
      j.null();
    j.key("down");
    if (p.down)
      JsonDirection(j, *p.down);
    else
      j.null();
    j.key("reversal_B");
    if (p.reversal)
      j.value(*p.reversal);
    else
      j.null();
    j.key("mean_bidirectional");
    if (p.mean_bidirectional)
      j.value(*p.mean_bidirectional);
    else
      j.null();
    j.key("repeatability_bidirectional");
    if (p.repeatability_bidirectional)
      j.value(*p.repeatability_bidirectional);
    else
      j.null();
    j.end_object();
  }
  j.end_array();
  j.key("warnings").begin_array();
  for (const auto& w : r.warnings) j.value(w);
  j.end_array();
  j.end_object();
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
    rows.push_back({p.symbol, FormatFixed(p.value, 2), where, p.meaning});
  }
  page->Table({"parameter", u, "where", "meaning"}, rows);

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

}  // namespace volcomp::metrology
