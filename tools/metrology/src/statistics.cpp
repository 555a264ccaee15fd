// Sample statistics.
#include "volcomp/metrology/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace volcomp::metrology {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

double Mean(const std::vector<double>& v) {
  if (v.empty()) return kNaN;
  double s = 0.0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

double SampleStdDev(const std::vector<double>& v) {
  if (v.size() < 2) return kNaN;
  const double m = Mean(v);
  double ss = 0.0;
  for (double x : v) ss += (x - m) * (x - m);
  return std::sqrt(ss / static_cast<double>(v.size() - 1));
}

double Range(const std::vector<double>& v) {
  if (v.empty()) return kNaN;
  const auto mm = std::minmax_element(v.begin(), v.end());
  return *mm.second - *mm.first;
}

std::optional<double> GostRangeCoefficient(int n) {
  switch (n) {
    case 5:
      return 0.4299;
    case 6:
      return 0.3946;
    case 7:
      return 0.3698;
    case 8:
      return 0.3512;
    case 9:
      return 0.3367;
    case 10:
      return 0.3249;
    default:
      return std::nullopt;
  }
}

namespace {

// Continued fraction of the incomplete beta function (A&S 26.5.8), evaluated from the front by the
// modified Lentz method: terms d_{2m} = m(b − m)x / ((a + 2m − 1)(a + 2m)),
// d_{2m+1} = −(a + m)(a + b + m)x / ((a + 2m)(a + 2m + 1)).
double BetaContinuedFraction(double a, double b, double x) {
  constexpr double kTiny = 1e-300;
  auto guard = [](double v) { return std::fabs(v) < kTiny ? kTiny : v; };
  double c = 1.0;
  double d = 1.0 / guard(1.0 - (a + b) * x / (a + 1.0));
  double h = d;
  for (int m = 1; m <= 500; ++m) {
    const double even = m * (b - m) * x / ((a + 2.0 * m - 1.0) * (a + 2.0 * m));
    d = 1.0 / guard(1.0 + even * d);
    c = guard(1.0 + even / c);
    h *= d * c;
    const double odd = -(a + m) * (a + b + m) * x / ((a + 2.0 * m) * (a + 2.0 * m + 1.0));
    d = 1.0 / guard(1.0 + odd * d);
    c = guard(1.0 + odd / c);
    const double step = d * c;
    h *= step;
    if (std::fabs(step - 1.0) < 1e-15) break;
  }
  return h;
}

// Regularized incomplete beta I_x(a, b), 0 ≤ x ≤ 1.
double IncompleteBeta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) +
                                a * std::log(x) + b * std::log1p(-x));
  // The fraction converges fast for x < (a + 1)/(a + b + 2); otherwise use I_x(a,b) = 1 −
  // I_{1−x}(b,a).
  if (x < (a + 1.0) / (a + b + 2.0)) return front * BetaContinuedFraction(a, b, x) / a;
  return 1.0 - front * BetaContinuedFraction(b, a, 1.0 - x) / b;
}

}  // namespace

double StudentTCdf(double t, int dof) {
  if (dof < 1) return kNaN;
  const double nu = dof;
  const double tail = 0.5 * IncompleteBeta(0.5 * nu, 0.5, nu / (nu + t * t));
  return t >= 0.0 ? 1.0 - tail : tail;
}

double StudentTQuantile(double p, int dof) {
  if (!(p > 0.0 && p < 1.0) || dof < 1) return kNaN;
  if (p < 0.5) return -StudentTQuantile(1.0 - p, dof);
  double lo = 0.0, hi = 1.0;
  while (StudentTCdf(hi, dof) < p) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e12) return kNaN;
  }
  for (int i = 0; i < 200 && hi - lo > 1e-12 * std::max(1.0, hi); ++i) {
    const double mid = 0.5 * (lo + hi);
    (StudentTCdf(mid, dof) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double GrubbsCritical(int n, double alpha) {
  if (n < 3 || !(alpha > 0.0 && alpha < 1.0)) return kNaN;
  const double t = StudentTQuantile(1.0 - alpha / (2.0 * n), n - 2);
  const double t2 = t * t;
  return (n - 1) / std::sqrt(static_cast<double>(n)) * std::sqrt(t2 / (n - 2 + t2));
}

}  // namespace volcomp::metrology
