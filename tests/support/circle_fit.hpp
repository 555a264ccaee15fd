// An evaluation of circular-test readings that shares no code with tools/metrology's circular
// evaluation (which fits the linearized limaçon): the readings as Cartesian points in the plane,
// a geometric least-squares circle by Gauss-Newton, and radial distances from its centre.
// Lengths in the units of the readings (µm); angles in degrees.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace volcomp::testing {

struct PlanePoint {
  double x, y;
};

/// The points of a path: nominal radius `radius` plus each deviation, along its reading's angle.
inline std::vector<PlanePoint> PathPoints(const std::vector<double>& angle_deg,
                                          const std::vector<double>& deviation,
                                          double radius) {
  std::vector<PlanePoint> pts;
  for (std::size_t i = 0; i < angle_deg.size(); ++i) {
    const double r = radius + deviation[i];
    const double t = angle_deg[i] * 3.14159265358979323846 / 180.0;
    pts.push_back({r * std::cos(t), r * std::sin(t)});
  }
  return pts;
}

struct FittedCircle {
  double cx, cy, r;
};

/// Geometric least-squares circle: minimizes Σ (|P − C| − r)² by Gauss-Newton from the centroid.
inline FittedCircle FitCircle(const std::vector<PlanePoint>& pts) {
  FittedCircle c{0, 0, 0};
  const double n = static_cast<double>(pts.size());
  for (const PlanePoint& p : pts) c.cx += p.x / n, c.cy += p.y / n;
  for (const PlanePoint& p : pts) c.r += std::hypot(p.x - c.cx, p.y - c.cy) / n;
  for (int it = 0; it < 50; ++it) {
    double JtJ[3][3] = {}, Jtr[3] = {};
    for (const PlanePoint& p : pts) {
      const double dist = std::hypot(p.x - c.cx, p.y - c.cy);
      const double J[3] = {-(p.x - c.cx) / dist, -(p.y - c.cy) / dist, -1.0};
      const double res = dist - c.r;
      for (int i = 0; i < 3; ++i) {
        Jtr[i] += J[i] * res;
        for (int j = 0; j < 3; ++j) JtJ[i][j] += J[i] * J[j];
      }
    }
    // Cramer's rule for the 3×3 step JtJ·δ = −Jtr.
    auto det = [](double m[3][3]) {
      return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
             m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double d = det(JtJ);
    double step[3];
    for (int k = 0; k < 3; ++k) {
      double m[3][3];
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m[i][j] = j == k ? -Jtr[i] : JtJ[i][j];
      }
      step[k] = det(m) / d;
    }
    c.cx += step[0], c.cy += step[1], c.r += step[2];
  }
  return c;
}

/// Max − min of the distances from `c`.
inline double RadialSpread(const std::vector<PlanePoint>& pts, const FittedCircle& c) {
  double lo = 1e300, hi = -1e300;
  for (const PlanePoint& p : pts) {
    const double d = std::hypot(p.x - c.cx, p.y - c.cy);
    lo = std::min(lo, d), hi = std::max(hi, d);
  }
  return hi - lo;
}

}  // namespace volcomp::testing
