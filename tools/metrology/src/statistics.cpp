// Sample statistics.
#include "volcomp/metrology/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace volcomp::metrology {

double Mean(const std::vector<double>& v) {
  if (v.empty()) throw std::invalid_argument("Mean of an empty sample");
  double s = 0.0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

double SampleStdDev(const std::vector<double>& v) {
  if (v.size() < 2) throw std::invalid_argument("standard deviation needs at least 2 values");
  const double m = Mean(v);
  double ss = 0.0;
  for (double x : v) ss += (x - m) * (x - m);
  return std::sqrt(ss / static_cast<double>(v.size() - 1));
}

double Range(const std::vector<double>& v) {
  if (v.empty()) throw std::invalid_argument("Range of an empty sample");
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

}  // namespace volcomp::metrology
