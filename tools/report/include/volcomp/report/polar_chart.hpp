// Polar error-motion plot (ISO 230-7 figs. 7-9 style): each trace value v(θ) is drawn at radius
// r0 + gain·v about the chart centre (the PC centre), where r0 is an arbitrary base circle. Centre
// markers (LSC, MZ, ...) and two-circle zones are given as offsets in the same units as the
// values, so the picture is the usual linearized (limaçon) view of the error motion.
// Angles are in degrees, counter-clockwise from the +x direction (right).
#pragma once

#include <string>
#include <vector>

namespace volcomp::report {

struct PolarTrace {
  std::string label;
  std::vector<double> angle_deg;
  std::vector<double> value;  // same size as angle_deg, e.g. µm
  std::string color = "#1f77b4";
  double width_px = 1.2;
  bool closed = true;  // join the last point to the first
  bool dots = false;   // draw points instead of a line (e.g. the total-motion cloud)
  double opacity = 1.0;
};

/// A centre marker at offset (x, y) from the PC centre, in value units.
struct PolarCentre {
  std::string label;
  double x = 0.0;
  double y = 0.0;
  std::string color = "#d62728";
};

/// Two concentric circles about (cx, cy) bounding the profile: inner/outer are values (radial
/// deviations from the base circle), so they are drawn at r0 + gain·inner and r0 + gain·outer.
struct PolarZone {
  std::string label;
  double cx = 0.0;
  double cy = 0.0;
  double inner = 0.0;
  double outer = 0.0;
  std::string color = "#2ca02c";
};

struct PolarChart {
  std::string title;
  std::string units = "µm";
  std::vector<PolarTrace> traces;
  std::vector<PolarCentre> centres;
  std::vector<PolarZone> zones;

  std::string Render(double size_px = 420.0) const;
};

}  // namespace volcomp::report
