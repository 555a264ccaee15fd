// XY chart rendered to SVG: polylines with markers, vertical intervals (mean ± k·s bars as in
// GOST 27843 fig. 10), bars from zero, and horizontal reference lines, with axes, ticks and a
// legend. All data are in user units; the chart picks ranges covering every element.
#pragma once

#include <string>
#include <vector>

namespace volcomp::report {

enum class Marker { kNone, kCircle, kSquare, kTriangleUp, kTriangleDown };

struct XySeries {
  std::string label;  // legend text; empty = not in the legend
  std::vector<double> x;
  std::vector<double> y;  // same size as x; non-finite values break the line
  std::string color = "#1f77b4";
  std::string dash;  // SVG dash pattern, empty = solid
  double width_px = 1.5;
  bool line = true;
  Marker marker = Marker::kCircle;
};

/// Vertical segments from lower[i] to upper[i] at x[i], shifted by offset_px horizontally.
struct XyIntervals {
  std::string label;
  std::vector<double> x;
  std::vector<double> lower;
  std::vector<double> upper;
  std::string color = "#1f77b4";
  double offset_px = 0.0;
  double width_px = 1.5;
};

/// Bars from 0 to y[i] at x[i], `bar_px` wide, shifted by offset_px.
struct XyBars {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;
  std::string color = "#1f77b4";
  double bar_px = 8.0;
  double offset_px = 0.0;
};

struct XyHLine {
  std::string label;  // drawn at the right end of the line
  double y = 0.0;
  std::string color = "#555555";
  std::string dash = "5 3";
};

struct XyChart {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<XySeries> series;
  std::vector<XyIntervals> intervals;
  std::vector<XyBars> bars;
  std::vector<XyHLine> hlines;
  bool include_zero = true;  // y range always contains 0

  /// The chart as a standalone <svg> element.
  std::string Render(double width_px = 760.0, double height_px = 380.0) const;
};

}  // namespace volcomp::report
