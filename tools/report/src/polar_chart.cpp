// Polar plot rendering.
#include "volcomp/report/polar_chart.hpp"

#include <algorithm>
#include <cmath>

#include "volcomp/report/format.hpp"
#include "volcomp/report/scale.hpp"
#include "volcomp/report/svg.hpp"

namespace volcomp::report {
namespace {
constexpr double kPi = 3.14159265358979323846;
}

std::string PolarChart::Render(double size_px) const {
  Svg svg(size_px + 200, size_px + 40);
  svg.Title(title);
  const double cx = size_px / 2 + 10, cy = size_px / 2 + 30;
  const double rp = size_px / 2 - 20;  // outer radius of the plot area

  // The largest magnitude to show decides the gain; the base circle sits at 55 % of the radius.
  double vmax = 0.0;
  for (const auto& t : traces) {
    for (double v : t.value) {
      if (std::isfinite(v)) vmax = std::max(vmax, std::fabs(v));
    }
  }
  for (const auto& z : zones) {
    vmax = std::max({vmax, std::fabs(z.inner) + std::hypot(z.cx, z.cy),
                     std::fabs(z.outer) + std::hypot(z.cx, z.cy)});
  }
  for (const auto& c : centres) vmax = std::max(vmax, std::hypot(c.x, c.y));
  if (!(vmax > 0.0)) vmax = 1.0;
  const double step = NiceStep(0.0, vmax, 2);
  const double vfull = std::ceil(vmax / step - 1e-9) * step;
  const double r0 = 0.55 * rp;
  const double gain = 0.42 * rp / vfull;
  auto at = [&](double angle_deg, double v) {
    const double r = std::max(0.0, r0 + gain * v);
    const double a = angle_deg * kPi / 180.0;
    return Point{cx + r * std::cos(a), cy - r * std::sin(a)};
  };

  // Grid: base circle, rings at ±step, spokes every 30°.
  Style grid;
  grid.stroke = "#dddddd";
  for (double v = -vfull; v <= vfull + 1e-9 * vfull; v += step) {
    Style s = grid;
    if (std::fabs(v) < 1e-12 * vfull) s.stroke = "#999999";
    if (r0 + gain * v > 0) svg.Circle({cx, cy}, r0 + gain * v, s);
  }
  TextStyle small;
  small.size_px = 10;
  for (int a = 0; a < 360; a += 30) {
    svg.Line(at(a, -vfull), at(a, vfull), grid);
    TextStyle ts = small;
    ts.anchor = Anchor::kMiddle;
    const double rad = a * kPi / 180.0;
    svg.Text({cx + (rp + 10) * std::cos(rad), cy - (rp + 10) * std::sin(rad) + 4},
             std::to_string(a) + "°", ts);
  }

  for (const auto& z : zones) {
    Style s;
    s.stroke = z.color;
    s.dash = "4 3";
    const Point c{cx + gain * z.cx, cy - gain * z.cy};
    svg.Circle(c, std::max(0.0, r0 + gain * z.inner), s);
    svg.Circle(c, std::max(0.0, r0 + gain * z.outer), s);
  }
  for (const auto& t : traces) {
    std::vector<Point> pts;
    for (std::size_t i = 0; i < t.angle_deg.size() && i < t.value.size(); ++i) {
      if (std::isfinite(t.value[i])) pts.push_back(at(t.angle_deg[i], t.value[i]));
    }
    Style s;
    s.stroke = t.color;
    s.stroke_width_px = t.width_px;
    s.opacity = t.opacity;
    if (t.dots) {
      Style d = s;
      d.stroke = "none";
      d.fill = t.color;
      for (const Point& p : pts) svg.Circle(p, 1.0, d);
    } else if (t.closed) {
      svg.Polygon(pts, s);
    } else {
      svg.Polyline(pts, s);
    }
  }
  for (const auto& c : centres) {
    Style s;
    s.stroke = c.color;
    s.stroke_width_px = 1.5;
    const Point p{cx + gain * c.x, cy - gain * c.y};
    svg.Line({p.x - 5, p.y}, {p.x + 5, p.y}, s);
    svg.Line({p.x, p.y - 5}, {p.x, p.y + 5}, s);
  }

  TextStyle tt;
  tt.size_px = 13;
  tt.bold = true;
  svg.Text({10, 16}, title, tt);
  // Legend and scale on the right.
  double ly = 40;
  const double lx = size_px + 20;
  auto row = [&](const std::string& label, const std::string& color, bool cross) {
    if (label.empty()) return;
    Style s;
    s.stroke = color;
    s.stroke_width_px = 1.5;
    if (cross) {
      svg.Line({lx + 4, ly - 4}, {lx + 14, ly - 4}, s);
      svg.Line({lx + 9, ly - 9}, {lx + 9, ly + 1}, s);
    } else {
      svg.Line({lx, ly - 4}, {lx + 18, ly - 4}, s);
    }
    svg.Text({lx + 24, ly}, label, small);
    ly += 18;
  };
  for (const auto& t : traces) row(t.label, t.color, false);
  for (const auto& z : zones) row(z.label, z.color, false);
  for (const auto& c : centres) row(c.label, c.color, true);
  svg.Text({lx, ly + 10}, "rings: " + FormatFixed(step, step < 1 ? 2 : 1) + " " + units + " apart",
           small);
  svg.Text({lx, ly + 26}, "PC = chart centre", small);
  return svg.str();
}

}  // namespace volcomp::report
