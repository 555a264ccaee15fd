// A rest-to-rest trapezoidal velocity profile along a path of length L (mm): constant
// acceleration a up to the cruise speed v (or a triangle when L < v^2/a), cruise, constant
// deceleration to rest at L. Times in seconds from the start of the move.
#pragma once

namespace volcomp::sim {

class TrapezoidProfile {
 public:
  /// Preconditions: `length_mm` >= 0, `speed_mm_s` > 0, `accel_mm_s2` > 0.
  TrapezoidProfile(double length_mm, double speed_mm_s, double accel_mm_s2);

  double length_mm() const { return length_; }
  double duration_s() const { return duration_; }
  /// The highest speed reached (v, or sqrt(a L) for a triangle).
  double peak_speed_mm_s() const { return peak_; }
  /// Time at which the path position reaches `s_mm` (0 <= s <= L; clamped).
  double TimeAt(double s_mm) const;
  /// Path position at time `t_s` (clamped to [0, duration]).
  double PositionAt(double t_s) const;

 private:
  double length_, accel_, peak_;
  double ramp_s_;   // duration of the acceleration (and of the deceleration)
  double ramp_mm_;  // distance covered while accelerating
  double duration_;
};

}  // namespace volcomp::sim
