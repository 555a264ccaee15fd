// Trapezoidal velocity profile.
#include "volcomp/sim/trapezoid.hpp"

#include <algorithm>
#include <cmath>

#include "volcomp/sim/contract.hpp"

namespace volcomp::sim {

TrapezoidProfile::TrapezoidProfile(double length_mm, double speed_mm_s, double accel_mm_s2)
    : length_(length_mm), accel_(accel_mm_s2) {
  VOLCOMP_SIM_EXPECT(length_mm >= 0 && speed_mm_s > 0 && accel_mm_s2 > 0,
                     "trapezoid: need length >= 0, speed > 0, acceleration > 0");
  peak_ = std::min(speed_mm_s, std::sqrt(accel_mm_s2 * length_mm));
  ramp_s_ = peak_ / accel_;
  ramp_mm_ = 0.5 * peak_ * ramp_s_;
  const double cruise_mm = std::max(0.0, length_ - 2 * ramp_mm_);
  duration_ = 2 * ramp_s_ + (peak_ > 0 ? cruise_mm / peak_ : 0.0);
}

double TrapezoidProfile::TimeAt(double s_mm) const {
  const double s = std::clamp(s_mm, 0.0, length_);
  if (s <= ramp_mm_) return std::sqrt(2 * s / accel_);
  if (s <= length_ - ramp_mm_) return ramp_s_ + (s - ramp_mm_) / peak_;
  return duration_ - std::sqrt(std::max(0.0, 2 * (length_ - s) / accel_));
}

double TrapezoidProfile::PositionAt(double t_s) const {
  const double t = std::clamp(t_s, 0.0, duration_);
  if (t <= ramp_s_) return 0.5 * accel_ * t * t;
  if (t <= duration_ - ramp_s_) return ramp_mm_ + peak_ * (t - ramp_s_);
  const double r = duration_ - t;
  return length_ - 0.5 * accel_ * r * r;
}

}  // namespace volcomp::sim
