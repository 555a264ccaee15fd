// SVG element writer.
#include "volcomp/report/svg.hpp"

#include <cmath>

#include "volcomp/report/format.hpp"

namespace volcomp::report {
namespace {

std::string Num(double v) { return FormatFixed(v, 2); }

std::string StyleAttrs(const Style& s) {
  std::string a = " stroke=\"" + EscapeXml(s.stroke) + "\" fill=\"" + EscapeXml(s.fill) + "\"";
  if (s.stroke != "none") a += " stroke-width=\"" + Num(s.stroke_width_px) + "\"";
  if (!s.dash.empty()) a += " stroke-dasharray=\"" + EscapeXml(s.dash) + "\"";
  if (s.opacity < 1.0) a += " opacity=\"" + FormatFixed(s.opacity, 3) + "\"";
  return a;
}

std::string Points(const std::vector<Point>& points) {
  std::string p;
  for (const Point& pt : points) {
    if (!std::isfinite(pt.x) || !std::isfinite(pt.y)) continue;
    if (!p.empty()) p += ' ';
    p += Num(pt.x) + "," + Num(pt.y);
  }
  return p;
}

}  // namespace

Svg::Svg(double width_px, double height_px) : width_(width_px), height_(height_px) {}

void Svg::Line(Point a, Point b, const Style& style) {
  body_ << "<line x1=\"" << Num(a.x) << "\" y1=\"" << Num(a.y) << "\" x2=\"" << Num(b.x)
        << "\" y2=\"" << Num(b.y) << "\"" << StyleAttrs(style) << "/>\n";
}

void Svg::Polyline(const std::vector<Point>& points, const Style& style) {
  if (points.size() < 2) return;
  body_ << "<polyline points=\"" << Points(points) << "\"" << StyleAttrs(style)
        << " stroke-linejoin=\"round\"/>\n";
}

void Svg::Polygon(const std::vector<Point>& points, const Style& style) {
  if (points.size() < 3) return;
  body_ << "<polygon points=\"" << Points(points) << "\"" << StyleAttrs(style)
        << " stroke-linejoin=\"round\"/>\n";
}

void Svg::Rect(double x, double y, double w, double h, const Style& style) {
  body_ << "<rect x=\"" << Num(x) << "\" y=\"" << Num(y) << "\" width=\"" << Num(w)
        << "\" height=\"" << Num(h) << "\"" << StyleAttrs(style) << "/>\n";
}

void Svg::Circle(Point centre, double radius_px, const Style& style) {
  body_ << "<circle cx=\"" << Num(centre.x) << "\" cy=\"" << Num(centre.y) << "\" r=\""
        << Num(radius_px) << "\"" << StyleAttrs(style) << "/>\n";
}

void Svg::Text(Point at, const std::string& text, const TextStyle& style) {
  const char* anchor = style.anchor == Anchor::kStart    ? "start"
                       : style.anchor == Anchor::kMiddle ? "middle"
                                                         : "end";
  body_ << "<text x=\"" << Num(at.x) << "\" y=\"" << Num(at.y) << "\" font-size=\""
        << Num(style.size_px) << "\" text-anchor=\"" << anchor << "\" fill=\""
        << EscapeXml(style.fill) << "\"";
  if (style.bold) body_ << " font-weight=\"bold\"";
  if (style.rotate_deg != 0.0) {
    body_ << " transform=\"rotate(" << Num(style.rotate_deg) << " " << Num(at.x) << " " << Num(at.y)
          << ")\"";
  }
  body_ << ">" << EscapeXml(text) << "</text>\n";
}

std::string Svg::str() const {
  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << Num(width_) << "\" height=\""
      << Num(height_) << "\" viewBox=\"0 0 " << Num(width_) << " " << Num(height_)
      << "\" font-family=\"sans-serif\">\n";
  if (!title_.empty()) out << "<title>" << EscapeXml(title_) << "</title>\n";
  out << body_.str() << "</svg>\n";
  return out.str();
}

}  // namespace volcomp::report
