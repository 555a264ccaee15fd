// The simulator's deterministic random generator.
#include "volcomp/sim/random.hpp"

#include <gtest/gtest.h>

namespace volcomp::sim {
namespace {

TEST(SimRandom, DeterministicUniformAndGaussianMoments) {
  Random a(9), b(9);
  for (int i = 0; i < 100; ++i) ASSERT_EQ(a.Next(), b.Next());
  Random r(123);
  const int n = 200000;
  double su = 0, sg = 0, sg2 = 0;
  for (int i = 0; i < n; ++i) {
    const double u = r.Uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    su += u;
    const double g = r.Gaussian();
    sg += g;
    sg2 += g * g;
  }
  EXPECT_NEAR(su / n, 0.5, 0.005);
  EXPECT_NEAR(sg / n, 0.0, 0.01);
  EXPECT_NEAR(sg2 / n, 1.0, 0.015);
}

}  // namespace
}  // namespace volcomp::sim
