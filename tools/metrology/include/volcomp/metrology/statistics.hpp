// Sample statistics used by the positioning evaluations (values in any one unit). A call outside
// a function's stated domain returns NaN (the callers check sizes first; nothing is thrown).
#pragma once

#include <optional>
#include <vector>

namespace volcomp::metrology {

/// Arithmetic mean; NaN for an empty sample.
double Mean(const std::vector<double>& v);
/// Sample standard deviation with the n − 1 divisor (GOST 27843 formula (5), ISO 230-2 s);
/// NaN for n < 2.
double SampleStdDev(const std::vector<double>& v);
/// Range max − min (GOST 27843 formula (4), W_j); NaN for an empty sample.
double Range(const std::vector<double>& v);

/// The coefficient a_n of GOST 27843-88 formula (6), S = W·a_n, for n = 5..10 repeated
/// measurements (1/d2(n) of a normal sample); nullopt outside that range. docs/metrology.md gives
/// the value used for the misprinted a_10.
std::optional<double> GostRangeCoefficient(int n);

/// Cumulative distribution of Student's t with `dof` ≥ 1 degrees of freedom:
/// F(t) = 1 − ½·I_x(dof/2, ½) for t ≥ 0, x = dof/(dof + t²) (Abramowitz & Stegun 26.7.1 with
/// 26.5.27), the regularized incomplete beta function I_x evaluated by its continued fraction
/// (A&S 26.5.8).
double StudentTCdf(double t, int dof);

/// The quantile t_{p, dof}: F(t) = p, for 0 < p < 1 (bisection on StudentTCdf to 1e-12).
double StudentTQuantile(double p, int dof);

/// Critical value of Grubbs' test for one outlier in a normal sample of n ≥ 3, two-sided at
/// significance `alpha` (0.01 = "at 99 %"): G_crit = (n − 1)/√n · √(t² / (n − 2 + t²)) with
/// t = t_{1 − α/(2n), n − 2} (Grubbs 1969, Technometrics 11(1); NIST/SEMATECH e-Handbook of
/// Statistical Methods §1.3.5.17). The sample's G = max|x_i − x̄|/s (n − 1 divisor) above G_crit
/// marks the most extreme value an outlier.
double GrubbsCritical(int n, double alpha);

}  // namespace volcomp::metrology
