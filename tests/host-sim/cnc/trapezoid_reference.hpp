// The path position of a rest-to-rest trapezoidal profile in closed form, written apart from
// TrapezoidProfile: the reference the CNC's step times and the profile itself are checked against.
#pragma once

#include <algorithm>
#include <cmath>

namespace volcomp::testing {

/// Path position (mm) at time `t` (s) of a move of length L (mm) at speed v (mm/s) and
/// acceleration a (mm/s²).
inline double TrapezoidPosition(double L, double v, double a, double t) {
  const double vp = std::min(v, std::sqrt(a * L));
  const double ta = vp / a, sa = 0.5 * vp * ta;
  const double T = 2 * ta + (L - 2 * sa) / vp;
  if (t <= 0) return 0;
  if (t >= T) return L;
  if (t < ta) return 0.5 * a * t * t;
  if (t < T - ta) return sa + vp * (t - ta);
  return L - 0.5 * a * (T - t) * (T - t);
}

}  // namespace volcomp::testing
