// The geometry of one motion block of the simulated CNC: a straight line or a circular arc (G2/G3
// in the G17/G18/G19 plane, with a linear motion along the plane's normal for a helix), in mm of
// the machine frame, parameterised by the path length s from the block's start.
//
// Arcs (RS274/NGC, ISO 6983): G17 is the X-Y plane, G18 Z-X, G19 Y-Z, each seen from the positive
// end of its normal axis; G3 turns counter-clockwise, G2 clockwise. Centre format: I, J, K are the
// centre's offsets from the start along X, Y, Z; the start and end radii must agree within
// max(0.002 mm, 0.1 % of the radius), and an end point equal to the start is a full circle. Radius
// format: R > 0 is the arc of at most 180 degrees, R < 0 the longer one; a full circle cannot be
// given by R. The arc keeps the start radius; the end point it reaches differs from the programmed
// one by the radius mismatch (the CNC closes that difference at the end of the block).
#pragma once

#include <array>
#include <string>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::sim {

using Point3 = std::array<double, 3>;

/// What a motion block says about its path (a ProgramBlock's motion words, resolved to mm).
struct PathRequest {
  bool arc = false;
  bool clockwise = false;               // G2 (else G3)
  int plane = 17;                       // 17, 18 or 19
  Point3 end_mm = {0, 0, 0};            // absolute end point
  Point3 centre_offset_mm = {0, 0, 0};  // I, J, K (centre format)
  bool radius_form = false;             // R given instead of I/J/K
  double radius_mm = 0;                 // R (signed)
};

class PathSegment {
 public:
  /// A straight line; `start_mm` == `end_mm` gives a segment of length 0.
  static PathSegment Line(const Point3& start_mm, const Point3& end_mm);
  /// The line or arc `request` describes from `start_mm`. Failures (kInputInvalid): the radii
  /// disagree, R shorter than half the chord, R with end == start, an arc of radius 0.
  static Expected<PathSegment> Resolve(const Point3& start_mm, const PathRequest& request);

  bool arc() const { return arc_; }
  double length_mm() const { return length_; }
  double radius_mm() const { return radius_; }
  /// Signed swept angle (rad), > 0 counter-clockwise in the plane's (first, second) axes.
  double sweep_rad() const { return sweep_; }
  const Point3& start_mm() const { return start_; }
  /// The end point of the path (for an arc: on the start radius).
  Point3 end_mm() const { return PointAt(length_); }
  /// An arc's centre (the normal axis at the start's coordinate); a line's start.
  Point3 centre_mm() const;
  /// An arc of a whole turn.
  bool full_circle() const;
  /// Axis indices of the arc plane: first, second, normal (G17: X Y Z, G18: Z X Y, G19: Y Z X).
  const std::array<int, 3>& plane_axes() const { return axes_; }

  /// Position at path length `s_mm` (0 <= s <= length).
  Point3 PointAt(double s_mm) const;
  /// Unit tangent at `s_mm` (the direction of travel; a zero-length line has (0, 0, 0)).
  Point3 TangentAt(double s_mm) const;
  /// The smallest s in (s_from_mm, length] where coordinate `axis` reaches `level_mm` while moving
  /// in direction `dir` (+1 up, -1 down); a negative number when it does not within the segment.
  double NextCrossing(int axis, double s_from_mm, double level_mm, int dir) const;
  /// Distance (mm) from `p_mm` to the nearest point of the segment (an arc's in-plane and normal
  /// deviations at the point's angle when that angle lies on the arc, else the nearer end).
  double DistanceTo(const Point3& p_mm) const;
  /// The highest path speed (mm/s) at which no axis exceeds `axis_speed_mm_s[axis]` anywhere on
  /// the segment and, on an arc, the centripetal acceleration v^2/r stays within `accel_mm_s2`.
  double SpeedLimit(const Point3& axis_speed_mm_s, double accel_mm_s2) const;

 private:
  double PlaneAngle(double s_mm) const { return angle0_ + sweep_ * s_mm / length_; }
  double LineCrossing(double u0, double u1, double s_from, double level, int dir) const;

  bool arc_ = false;
  Point3 start_ = {0, 0, 0};
  Point3 end_ = {0, 0, 0};  // lines: the end point
  std::array<int, 3> axes_ = {0, 1, 2};
  double centre_[2] = {0, 0};
  double radius_ = 0;
  double angle0_ = 0;
  double sweep_ = 0;
  double normal_travel_mm_ = 0;
  double length_ = 0;
};

}  // namespace volcomp::sim
