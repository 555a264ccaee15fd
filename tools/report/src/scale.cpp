// Linear scales and tick selection.
#include "volcomp/report/scale.hpp"

#include <cmath>

namespace volcomp::report {

LinearScale::LinearScale(double domain_lo, double domain_hi, double range_lo, double range_hi)
    : d0_(domain_lo), d1_(domain_hi), r0_(range_lo), r1_(range_hi) {}

double LinearScale::operator()(double value) const {
  const double span = d1_ - d0_;
  if (span == 0.0) return 0.5 * (r0_ + r1_);
  return r0_ + (value - d0_) / span * (r1_ - r0_);
}

double NiceStep(double lo, double hi, int target_count) {
  const double span = std::fabs(hi - lo);
  if (!(span > 0.0) || !std::isfinite(span)) return 1.0;
  if (target_count < 1) target_count = 1;
  const double raw = span / target_count;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / mag;
  const double nice = f < 1.5 ? 1.0 : f < 3.5 ? 2.0 : f < 7.5 ? 5.0 : 10.0;
  return nice * mag;
}

std::vector<double> NiceTicks(double lo, double hi, int target_count) {
  std::vector<double> ticks;
  if (!std::isfinite(lo) || !std::isfinite(hi)) return ticks;
  if (hi < lo) std::swap(lo, hi);
  const double step = NiceStep(lo, hi, target_count);
  const double eps = step * 1e-9;
  for (double t = std::ceil((lo - eps) / step) * step; t <= hi + eps && ticks.size() < 200;
       t += step) {
    ticks.push_back(std::fabs(t) < eps ? 0.0 : t);
  }
  return ticks;
}

void ExpandToNice(double* lo, double* hi, int target_count) {
  if (!std::isfinite(*lo) || !std::isfinite(*hi)) {
    *lo = -1.0;
    *hi = 1.0;
    return;
  }
  if (*hi < *lo) std::swap(*lo, *hi);
  if (*hi - *lo < 1e-12 * (std::fabs(*lo) + std::fabs(*hi)) || *hi == *lo) {
    *lo -= 1.0;
    *hi += 1.0;
  }
  const double step = NiceStep(*lo, *hi, target_count);
  *lo = std::floor(*lo / step + 1e-9) * step;
  *hi = std::ceil(*hi / step - 1e-9) * step;
}

}  // namespace volcomp::report
