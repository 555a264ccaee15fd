// A small SVG writer: shapes in pixel coordinates (origin top-left, y down), emitted as one
// standalone <svg> element suitable for inlining in HTML.
#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace volcomp::report {

struct Point {
  double x = 0.0;  // px
  double y = 0.0;  // px
};

/// Stroke and fill of a shape. Colours are any SVG colour ("#1f77b4", "none", "black").
struct Style {
  std::string stroke = "black";
  std::string fill = "none";
  double stroke_width_px = 1.0;
  std::string dash;      // SVG stroke-dasharray, e.g. "6 3"; empty = solid
  double opacity = 1.0;  // applies to fill and stroke
};

enum class Anchor { kStart, kMiddle, kEnd };

struct TextStyle {
  double size_px = 12.0;
  Anchor anchor = Anchor::kStart;
  std::string fill = "black";
  bool bold = false;
  double rotate_deg = 0.0;  // rotation about the text's anchor point
};

class Svg {
 public:
  Svg(double width_px, double height_px);

  double width() const { return width_; }
  double height() const { return height_; }

  void Line(Point a, Point b, const Style& style);
  void Polyline(const std::vector<Point>& points, const Style& style);
  void Polygon(const std::vector<Point>& points, const Style& style);
  void Rect(double x, double y, double w, double h, const Style& style);
  void Circle(Point centre, double radius_px, const Style& style);
  /// Text is escaped; multi-line text is not supported (one line per call).
  void Text(Point at, const std::string& text, const TextStyle& style);
  /// Optional <title> for accessibility, emitted first.
  void Title(const std::string& title) { title_ = title; }

  /// The complete <svg> element.
  std::string str() const;

 private:
  double width_;
  double height_;
  std::string title_;
  std::ostringstream body_;
};

}  // namespace volcomp::report
