// Sample statistics (statistics.hpp): Student's t and Grubbs' critical values against published
// tables; NaN outside each function's domain.
#include "volcomp/metrology/statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace volcomp::metrology {
namespace {

TEST(MetrologyStatistics, MeanStdDevAndRange) {
  EXPECT_DOUBLE_EQ(Mean({1, 2, 3, 6}), 3.0);
  EXPECT_DOUBLE_EQ(SampleStdDev({1, 2, 3, 4, 5}), std::sqrt(2.5));
  EXPECT_DOUBLE_EQ(Range({-1, 4, 2}), 5.0);
}

TEST(MetrologyStatistics, OutsideTheDomainIsNaN) {
  EXPECT_TRUE(std::isnan(Mean({})));
  EXPECT_TRUE(std::isnan(SampleStdDev({1.0})));
  EXPECT_TRUE(std::isnan(Range({})));
  EXPECT_TRUE(std::isnan(StudentTCdf(1.0, 0)));
  EXPECT_TRUE(std::isnan(StudentTQuantile(1.0, 5)));
  EXPECT_TRUE(std::isnan(GrubbsCritical(2, 0.01)));
  EXPECT_TRUE(std::isnan(GrubbsCritical(5, 1.5)));
}

// Two-sided Student t quantiles t_{p, ν} from the standard table (e.g. NIST/SEMATECH
// e-Handbook §1.3.6.7.2; Abramowitz & Stegun table 26.10).
TEST(MetrologyStatistics, StudentTQuantilesMatchTheTable) {
  struct Row {
    double p;
    int dof;
    double t;
  };
  for (const Row& r : {Row{0.95, 1, 6.314}, Row{0.975, 1, 12.706}, Row{0.975, 10, 2.228},
                       Row{0.995, 8, 3.355}, Row{0.999, 3, 10.215}, Row{0.9995, 3, 12.924},
                       Row{0.975, 30, 2.042}, Row{0.995, 120, 2.617}}) {
    EXPECT_NEAR(StudentTQuantile(r.p, r.dof), r.t, 0.0015) << r.p << " " << r.dof;
    EXPECT_NEAR(StudentTCdf(r.t, r.dof), r.p, 5e-5);
    EXPECT_NEAR(StudentTQuantile(1.0 - r.p, r.dof), -r.t, 0.0015);
  }
}

// Critical values of Grubbs' test (G_10, two-sided) as tabulated in Grubbs (1969) and ASTM
// E178, as reproduced e.g. in the LibreTexts "Critical Values for Grubb's Test" appendix (whose
// α = 0.05 entry for n = 7 prints 2.202, a transposition of 2.020, and whose n = 15 row repeats
// the n = 14 value at α = 0.01; the true values are used here).
TEST(MetrologyStatistics, GrubbsCriticalValuesMatchThePublishedTable) {
  const double at_001[] = {1.155, 1.496, 1.764, 1.973, 2.139, 2.274,
                           2.387, 2.482, 2.564, 2.636, 2.699, 2.755};
  const double at_005[] = {1.155, 1.481, 1.715, 1.887, 2.020, 2.126,
                           2.215, 2.290, 2.355, 2.412, 2.462, 2.507};
  for (int n = 3; n <= 14; ++n) {
    EXPECT_NEAR(GrubbsCritical(n, 0.01), at_001[n - 3], 1e-3) << n;
    EXPECT_NEAR(GrubbsCritical(n, 0.05), at_005[n - 3], 1e-3) << n;
  }
  // No sample of n can exceed (n − 1)/√n; the critical value stays below it.
  for (int n = 3; n <= 30; ++n) EXPECT_LT(GrubbsCritical(n, 0.01), (n - 1) / std::sqrt(n));
}

}  // namespace
}  // namespace volcomp::metrology
