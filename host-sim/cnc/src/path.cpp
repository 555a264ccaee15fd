// Line and arc geometry of the simulated CNC's motion blocks.
#include "volcomp/sim/path.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace volcomp::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFullCircleChordMm = 1e-6;

std::string Mm(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4f mm", v);
  return b;
}

std::array<int, 3> PlaneAxes(int plane) {
  if (plane == 18) return {2, 0, 1};
  if (plane == 19) return {1, 2, 0};
  return {0, 1, 2};
}

// Wraps an angle into (0, 2 pi].
double PositiveTurn(double a) {
  a = std::fmod(a, 2 * kPi);
  return a <= 0 ? a + 2 * kPi : a;
}

}  // namespace

PathSegment PathSegment::Line(const Point3& start_mm, const Point3& end_mm) {
  PathSegment p;
  p.start_ = start_mm;
  p.end_ = end_mm;
  double len2 = 0;
  for (size_t a = 0; a < 3; ++a) len2 += (end_mm[a] - start_mm[a]) * (end_mm[a] - start_mm[a]);
  p.length_ = std::sqrt(len2);
  return p;
}

Expected<PathSegment> PathSegment::Resolve(const Point3& start_mm, const PathRequest& request) {
  if (!request.arc) return Line(start_mm, request.end_mm);
  PathSegment p;
  p.arc_ = true;
  p.start_ = start_mm;
  p.end_ = request.end_mm;
  p.axes_ = PlaneAxes(request.plane);
  const size_t f = static_cast<size_t>(p.axes_[0]), g = static_cast<size_t>(p.axes_[1]),
               n = static_cast<size_t>(p.axes_[2]);
  const double sf = start_mm[f], sg = start_mm[g];
  const double ef = request.end_mm[f], eg = request.end_mm[g];
  const double chord = std::hypot(ef - sf, eg - sg);
  if (request.radius_form) {
    if (chord < kFullCircleChordMm) {
      return Fail(Error::kInputInvalid,
                  "R cannot describe a full circle (the end point is the start); give the centre "
                  "with I, J, K");
    }
    const double r = std::fabs(request.radius_mm);
    const double half = chord / 2;
    if (r < half - std::max(0.002, 0.001 * half)) {
      return Fail(Error::kInputInvalid,
                  "R " + Mm(r) + " is shorter than half the chord (" + Mm(half) + ")");
    }
    const double h = std::sqrt(std::max(0.0, r * r - half * half));
    const double nf = -(eg - sg) / chord, ng = (ef - sf) / chord;  // left of the chord
    const double side = (!request.clockwise) == (request.radius_mm > 0) ? 1.0 : -1.0;
    p.centre_[0] = (sf + ef) / 2 + side * h * nf;
    p.centre_[1] = (sg + eg) / 2 + side * h * ng;
  } else {
    p.centre_[0] = sf + request.centre_offset_mm[f];
    p.centre_[1] = sg + request.centre_offset_mm[g];
  }
  const double rs = std::hypot(sf - p.centre_[0], sg - p.centre_[1]);
  const double re = std::hypot(ef - p.centre_[0], eg - p.centre_[1]);
  if (rs < 1e-6) return Fail(Error::kInputInvalid, "arc of radius 0 (the centre is the start)");
  if (std::fabs(re - rs) > std::max(0.002, 0.001 * rs)) {
    return Fail(Error::kInputInvalid, "the arc's end point is " + Mm(re) +
                                          " from the centre, its start " + Mm(rs) +
                                          " (they may differ by max(0.002 mm, 0.1 %))");
  }
  p.radius_ = rs;
  p.angle0_ = std::atan2(sg - p.centre_[1], sf - p.centre_[0]);
  const double end_angle = std::atan2(eg - p.centre_[1], ef - p.centre_[0]);
  const bool full = chord < kFullCircleChordMm;
  const double ccw = full ? 2 * kPi : PositiveTurn(end_angle - p.angle0_);
  const double cw = full ? 2 * kPi : PositiveTurn(p.angle0_ - end_angle);
  p.sweep_ = request.clockwise ? -cw : ccw;
  p.normal_travel_mm_ = request.end_mm[n] - start_mm[n];
  p.length_ = std::hypot(rs * std::fabs(p.sweep_), p.normal_travel_mm_);
  return p;
}

Point3 PathSegment::centre_mm() const {
  if (!arc_) return start_;
  Point3 c = start_;
  c[static_cast<size_t>(axes_[0])] = centre_[0];
  c[static_cast<size_t>(axes_[1])] = centre_[1];
  return c;
}

bool PathSegment::full_circle() const {
  return arc_ && std::fabs(std::fabs(sweep_) - 2 * kPi) < 1e-9;
}

Point3 PathSegment::PointAt(double s_mm) const {
  if (length_ == 0) return start_;
  const double f = std::clamp(s_mm / length_, 0.0, 1.0);
  Point3 q = start_;
  if (!arc_) {
    for (size_t a = 0; a < 3; ++a) q[a] = start_[a] + (end_[a] - start_[a]) * f;
    return q;
  }
  const double th = angle0_ + sweep_ * f;
  q[static_cast<size_t>(axes_[0])] = centre_[0] + radius_ * std::cos(th);
  q[static_cast<size_t>(axes_[1])] = centre_[1] + radius_ * std::sin(th);
  q[static_cast<size_t>(axes_[2])] = start_[static_cast<size_t>(axes_[2])] + normal_travel_mm_ * f;
  return q;
}

Point3 PathSegment::TangentAt(double s_mm) const {
  Point3 t = {0, 0, 0};
  if (length_ == 0) return t;
  if (!arc_) {
    for (size_t a = 0; a < 3; ++a) t[a] = (end_[a] - start_[a]) / length_;
    return t;
  }
  const double th = PlaneAngle(std::clamp(s_mm, 0.0, length_));
  const double k = radius_ * sweep_ / length_;  // in-plane mm per mm of path, signed
  t[static_cast<size_t>(axes_[0])] = -k * std::sin(th);
  t[static_cast<size_t>(axes_[1])] = k * std::cos(th);
  t[static_cast<size_t>(axes_[2])] = normal_travel_mm_ / length_;
  return t;
}

double PathSegment::LineCrossing(double u0, double u1, double s_from, double level, int dir) const {
  const double du = u1 - u0;
  if (dir * du <= 0) return -1;
  const double s = (level - u0) * length_ / du;
  const double eps = 1e-12 * std::max(1.0, length_);
  if (s <= s_from + eps || s > length_ + eps) return -1;
  return std::min(s, length_);
}

double PathSegment::NextCrossing(int axis, double s_from_mm, double level_mm, int dir) const {
  if (length_ == 0) return -1;
  const size_t a = static_cast<size_t>(axis);
  if (!arc_) return LineCrossing(start_[a], end_[a], s_from_mm, level_mm, dir);
  if (axis == axes_[2]) {
    return LineCrossing(start_[a], start_[a] + normal_travel_mm_, s_from_mm, level_mm, dir);
  }
  // u(s) = c + r cos(beta), beta = beta0 + k s; cos is monotone on [m pi, (m + 1) pi].
  const bool first = axis == axes_[0];
  const double c = first ? centre_[0] : centre_[1];
  const double beta0 = angle0_ - (first ? 0.0 : kPi / 2);
  const double k = sweep_ / length_;
  const double up = k > 0 ? 1.0 : -1.0;
  const double eps = 1e-12 * std::max(1.0, length_);
  const double beta_from = beta0 + k * s_from_mm;
  double m = k > 0 ? std::floor(beta_from / kPi) : std::ceil(beta_from / kPi) - 1;  // whole
  for (;;) {
    const double b_enter = k > 0 ? m * kPi : (m + 1) * kPi;
    const double b_leave = k > 0 ? (m + 1) * kPi : m * kPi;
    const double s_enter = (b_enter - beta0) / k, s_leave = (b_leave - beta0) / k;
    if (s_enter > length_ + eps) break;
    const bool even = std::fmod(std::fabs(m), 2.0) == 0;
    const int piece_dir = static_cast<int>((even ? -1.0 : 1.0) * up);
    const double v = (level_mm - c) / radius_;
    if (piece_dir == dir && std::fabs(v) <= 1) {
      const double t = std::acos(even ? v : -v);
      const double s = (m * kPi + t - beta0) / k;
      if (s > s_from_mm + eps && s >= s_enter - eps && s <= std::min(s_leave, length_) + eps) {
        return std::clamp(s, 0.0, length_);
      }
    }
    if (s_leave >= length_) break;
    m += up;
  }
  return -1;
}

double PathSegment::DistanceTo(const Point3& p_mm) const {
  auto distance = [&](const Point3& q) {
    return std::sqrt((p_mm[0] - q[0]) * (p_mm[0] - q[0]) + (p_mm[1] - q[1]) * (p_mm[1] - q[1]) +
                     (p_mm[2] - q[2]) * (p_mm[2] - q[2]));
  };
  if (length_ == 0) return distance(start_);
  if (!arc_) {
    double along = 0;
    for (size_t a = 0; a < 3; ++a) along += (p_mm[a] - start_[a]) * (end_[a] - start_[a]);
    return distance(PointAt(std::clamp(along / length_, 0.0, length_)));
  }
  const double df = p_mm[static_cast<size_t>(axes_[0])] - centre_[0];
  const double dg = p_mm[static_cast<size_t>(axes_[1])] - centre_[1];
  // The point's angle from the start, in the direction of travel, within one turn.
  double turned = std::atan2(dg, df) - angle0_;
  if (sweep_ < 0) turned = -turned;
  turned = std::fmod(turned, 2 * kPi);
  if (turned < 0) turned += 2 * kPi;
  const double best = std::min(distance(start_), distance(end_mm()));
  if (turned > std::fabs(sweep_)) return best;
  return std::min(best, distance(PointAt(length_ * turned / std::fabs(sweep_))));
}

double PathSegment::SpeedLimit(const Point3& axis_speed_mm_s, double accel_mm_s2) const {
  double v = INFINITY;
  if (length_ == 0) return v;
  if (!arc_) {
    for (size_t a = 0; a < 3; ++a) {
      const double d = std::fabs(end_[a] - start_[a]);
      if (d > 0) v = std::min(v, axis_speed_mm_s[a] * length_ / d);
    }
    return v;
  }
  // In-plane speed = v * r |sweep| / length; each in-plane axis moves at up to the in-plane speed.
  const double plane_per_path = radius_ * std::fabs(sweep_) / length_;
  for (int i = 0; i < 2; ++i) {
    v = std::min(v, axis_speed_mm_s[static_cast<size_t>(axes_[i])] / plane_per_path);
  }
  const double travel = std::fabs(normal_travel_mm_);
  if (travel > 0) {
    v = std::min(v, axis_speed_mm_s[static_cast<size_t>(axes_[2])] * length_ / travel);
  }
  return std::min(v, std::sqrt(accel_mm_s2 * radius_) / plane_per_path);
}

}  // namespace volcomp::sim
