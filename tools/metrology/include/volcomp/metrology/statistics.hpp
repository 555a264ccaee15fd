// Sample statistics used by the positioning evaluations (values in any one unit).
#pragma once

#include <optional>
#include <vector>

namespace volcomp::metrology {

/// Arithmetic mean; requires a non-empty sample.
double Mean(const std::vector<double>& v);
/// Sample standard deviation with the n − 1 divisor (GOST 27843 formula (5), ISO 230-2 s);
/// requires n ≥ 2.
double SampleStdDev(const std::vector<double>& v);
/// Range max − min (GOST 27843 formula (4), W_j); requires a non-empty sample.
double Range(const std::vector<double>& v);

/// The coefficient a_n of GOST 27843-88 formula (6), S = W·a_n, for n = 5..10 repeated
/// measurements; nullopt outside that range. a_n = 1/d2(n), the range-to-sigma factor of a
/// normal sample. The seed prints a_10 = 0.3429, which breaks the decreasing sequence; the value
/// 1/d2(10) = 1/3.078 = 0.3249 is used (digit transposition in the print).
std::optional<double> GostRangeCoefficient(int n);

}  // namespace volcomp::metrology
