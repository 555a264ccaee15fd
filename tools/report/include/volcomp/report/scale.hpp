// Linear mapping from data values to pixels, and "nice" axis ticks (1, 2, 5 × 10^k steps).
#pragma once

#include <vector>

namespace volcomp::report {

/// Maps [domain_lo, domain_hi] linearly onto [range_lo, range_hi] (pixels; may be reversed).
class LinearScale {
 public:
  LinearScale(double domain_lo, double domain_hi, double range_lo, double range_hi);
  double operator()(double value) const;
  double domain_lo() const { return d0_; }
  double domain_hi() const { return d1_; }

 private:
  double d0_, d1_, r0_, r1_;
};

/// A tick step of 1, 2 or 5 × 10^k giving about `target_count` intervals over [lo, hi].
double NiceStep(double lo, double hi, int target_count);

/// Ticks at multiples of NiceStep() covering [lo, hi] (inclusive within rounding).
std::vector<double> NiceTicks(double lo, double hi, int target_count);

/// Widens [*lo, *hi] outwards to multiples of NiceStep(); a zero-width range becomes ±1 around it.
void ExpandToNice(double* lo, double* hi, int target_count);

}  // namespace volcomp::report
