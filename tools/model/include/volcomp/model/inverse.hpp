// Inverse of a forward error map by fixed-point iteration: find q with q + e(q) = target.
//
// Machine error maps have Jacobians of order 1e-3 (straightness slopes, squareness, angular errors
// times lever arms), so q ← target − e(q) contracts by about that factor per step and converges in
// a handful of iterations even across the kinks of piecewise-linear tables.
#pragma once

#include <cmath>

#include "volcomp/model/vec3.hpp"

namespace volcomp::model {

struct InverseSolution {
  Vec3 command_mm;
  double residual_mm = 0;  // ‖q + e(q) − target‖ at the returned q
  int iterations = 0;
  bool converged = false;  // the last step was ≤ tolerance
};

/// `error_mm(q)` returns the error (actual − nominal, mm) at command q.
template <typename ErrorMm>
InverseSolution InvertError(const ErrorMm& error_mm,
                            const Vec3& target_mm,
                            double tolerance_mm,
                            int max_iterations = 100) {
  InverseSolution s;
  Vec3 q = target_mm;
  Vec3 e = error_mm(q);
  for (int i = 0; i < max_iterations; ++i) {
    const Vec3 next = target_mm - e;
    const double step = MaxAbs(next - q);
    q = next;
    e = error_mm(q);
    s.iterations = i + 1;
    if (step <= tolerance_mm) {
      s.converged = true;
      break;
    }
  }
  s.command_mm = q;
  s.residual_mm = Norm(q + e - target_mm);
  return s;
}

}  // namespace volcomp::model
