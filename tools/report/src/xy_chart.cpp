// XY chart rendering.
#include "volcomp/report/xy_chart.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "volcomp/report/format.hpp"
#include "volcomp/report/scale.hpp"
#include "volcomp/report/svg.hpp"

namespace volcomp::report {
namespace {

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void Add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool Empty() const { return lo > hi; }
};

int DecimalsFor(double step) {
  if (!(step > 0.0)) return 0;
  const int d = static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  return std::clamp(d, 0, 6);
}

void DrawMarker(Svg* svg, Marker m, Point p, const std::string& color) {
  Style s;
  s.stroke = color;
  s.fill = color;
  const double r = 3.0;
  switch (m) {
    case Marker::kNone:
      break;
    case Marker::kCircle:
      svg->Circle(p, r, s);
      break;
    case Marker::kSquare:
      svg->Rect(p.x - r, p.y - r, 2 * r, 2 * r, s);
      break;
    case Marker::kTriangleUp:
      svg->Polygon({{p.x, p.y - r - 1}, {p.x - r - 1, p.y + r}, {p.x + r + 1, p.y + r}}, s);
      break;
    case Marker::kTriangleDown:
      svg->Polygon({{p.x, p.y + r + 1}, {p.x - r - 1, p.y - r}, {p.x + r + 1, p.y - r}}, s);
      break;
  }
}

}  // namespace

std::string XyChart::Render(double width_px, double height_px) const {
  Range xr, yr;
  for (const auto& s : series) {
    for (double v : s.x) xr.Add(v);
    for (double v : s.y) yr.Add(v);
  }
  for (const auto& iv : intervals) {
    for (double v : iv.x) xr.Add(v);
    for (double v : iv.lower) yr.Add(v);
    for (double v : iv.upper) yr.Add(v);
  }
  for (const auto& b : bars) {
    for (double v : b.x) xr.Add(v);
    for (double v : b.y) yr.Add(v);
  }
  for (const auto& h : hlines) yr.Add(h.y);
  if (include_zero) yr.Add(0.0);
  if (xr.Empty()) xr.lo = 0.0, xr.hi = 1.0;
  if (yr.Empty()) yr.lo = -1.0, yr.hi = 1.0;
  ExpandToNice(&yr.lo, &yr.hi, 6);
  // Leave a margin on both x ends so markers and bars at the ends stay inside the plot.
  const double xspan = xr.hi > xr.lo ? xr.hi - xr.lo : 1.0;
  const double x_lo = xr.lo - 0.04 * xspan, x_hi = xr.hi + 0.04 * xspan;

  const double left = 70, right = 150, top = 40, bottom = 50;
  const double pw = std::max(50.0, width_px - left - right);
  const double ph = std::max(50.0, height_px - top - bottom);
  const LinearScale sx(x_lo, x_hi, left, left + pw);
  const LinearScale sy(yr.lo, yr.hi, top + ph, top);

  Svg svg(width_px, height_px);
  svg.Title(title);
  Style frame;
  frame.stroke = "#333333";
  Style grid;
  grid.stroke = "#e0e0e0";
  TextStyle small;
  small.size_px = 11;

  // Grid and ticks.
  const auto yt = NiceTicks(yr.lo, yr.hi, 6);
  const int ydec = yt.size() > 1 ? DecimalsFor(yt[1] - yt[0]) : 0;
  for (double t : yt) {
    svg.Line({left, sy(t)}, {left + pw, sy(t)}, grid);
    TextStyle ts = small;
    ts.anchor = Anchor::kEnd;
    svg.Text({left - 6, sy(t) + 4}, FormatFixed(t, ydec), ts);
  }
  const auto xt = NiceTicks(xr.lo, xr.hi, 8);
  const int xdec = xt.size() > 1 ? DecimalsFor(xt[1] - xt[0]) : 0;
  for (double t : xt) {
    svg.Line({sx(t), top}, {sx(t), top + ph}, grid);
    TextStyle ts = small;
    ts.anchor = Anchor::kMiddle;
    svg.Text({sx(t), top + ph + 16}, FormatFixed(t, xdec), ts);
  }
  if (yr.lo < 0.0 && yr.hi > 0.0) {
    Style zero;
    zero.stroke = "#888888";
    svg.Line({left, sy(0.0)}, {left + pw, sy(0.0)}, zero);
  }
  svg.Rect(left, top, pw, ph, frame);

  // Titles.
  TextStyle tt;
  tt.size_px = 14;
  tt.bold = true;
  tt.anchor = Anchor::kMiddle;
  svg.Text({left + pw / 2, top - 16}, title, tt);
  TextStyle lt = small;
  lt.anchor = Anchor::kMiddle;
  svg.Text({left + pw / 2, top + ph + 38}, x_label, lt);
  TextStyle yl = small;
  yl.anchor = Anchor::kMiddle;
  yl.rotate_deg = -90;
  svg.Text({18, top + ph / 2}, y_label, yl);

  // Bars, then intervals, then series, then reference lines on top.
  for (const auto& b : bars) {
    Style s;
    s.stroke = b.color;
    s.fill = b.color;
    s.opacity = 0.75;
    for (std::size_t i = 0; i < b.x.size() && i < b.y.size(); ++i) {
      if (!std::isfinite(b.y[i])) continue;
      const double x = sx(b.x[i]) + b.offset_px;
      const double y0 = sy(0.0), y1 = sy(b.y[i]);
      svg.Rect(x - b.bar_px / 2, std::min(y0, y1), b.bar_px, std::fabs(y1 - y0), s);
    }
  }
  for (const auto& iv : intervals) {
    Style s;
    s.stroke = iv.color;
    s.stroke_width_px = iv.width_px;
    for (std::size_t i = 0; i < iv.x.size() && i < iv.lower.size() && i < iv.upper.size(); ++i) {
      if (!std::isfinite(iv.lower[i]) || !std::isfinite(iv.upper[i])) continue;
      const double x = sx(iv.x[i]) + iv.offset_px;
      svg.Line({x, sy(iv.lower[i])}, {x, sy(iv.upper[i])}, s);
      svg.Line({x - 4, sy(iv.lower[i])}, {x + 4, sy(iv.lower[i])}, s);
      svg.Line({x - 4, sy(iv.upper[i])}, {x + 4, sy(iv.upper[i])}, s);
    }
  }
  for (const auto& se : series) {
    Style s;
    s.stroke = se.color;
    s.stroke_width_px = se.width_px;
    s.dash = se.dash;
    std::vector<Point> run;
    auto flush = [&]() {
      if (se.line) svg.Polyline(run, s);
      run.clear();
    };
    for (std::size_t i = 0; i < se.x.size() && i < se.y.size(); ++i) {
      if (!std::isfinite(se.x[i]) || !std::isfinite(se.y[i])) {
        flush();
        continue;
      }
      run.push_back({sx(se.x[i]), sy(se.y[i])});
    }
    flush();
    for (std::size_t i = 0; i < se.x.size() && i < se.y.size(); ++i) {
      if (std::isfinite(se.x[i]) && std::isfinite(se.y[i])) {
        DrawMarker(&svg, se.marker, {sx(se.x[i]), sy(se.y[i])}, se.color);
      }
    }
  }
  for (const auto& h : hlines) {
    Style s;
    s.stroke = h.color;
    s.dash = h.dash;
    svg.Line({left, sy(h.y)}, {left + pw, sy(h.y)}, s);
    TextStyle ts = small;
    ts.fill = h.color;
    ts.anchor = Anchor::kEnd;
    // Label inside the plot, on the side of the line facing the nearer frame edge.
    const double dy = sy(h.y) > top + ph / 2 ? 13.0 : -4.0;
    svg.Text({left + pw - 4, sy(h.y) + dy}, h.label, ts);
  }

  // Legend (right margin).
  double ly = top + 8;
  const double lx = left + pw + 10;
  auto legend_row = [&](const std::string& label, const std::string& color, const std::string& dash,
                        Marker m, bool box) {
    if (label.empty()) return;
    if (box) {
      Style s;
      s.stroke = color;
      s.fill = color;
      svg.Rect(lx, ly - 6, 18, 8, s);
    } else {
      Style s;
      s.stroke = color;
      s.stroke_width_px = 1.5;
      s.dash = dash;
      svg.Line({lx, ly - 2}, {lx + 18, ly - 2}, s);
      DrawMarker(&svg, m, {lx + 9, ly - 2}, color);
    }
    svg.Text({lx + 24, ly + 2}, label, small);
    ly += 16;
  };
  for (const auto& se : series) legend_row(se.label, se.color, se.dash, se.marker, false);
  for (const auto& iv : intervals) legend_row(iv.label, iv.color, "", Marker::kNone, false);
  for (const auto& b : bars) legend_row(b.label, b.color, "", Marker::kNone, true);
  return svg.str();
}

}  // namespace volcomp::report
