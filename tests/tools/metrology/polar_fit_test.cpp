// Centres of polar profiles (polar_fit.hpp): the minimum-zone (MRS) centre is exact on
// equi-oscillating profiles, never worse than LSC or PC, and locally optimal (the zone is convex in
// the centre, so local = global); the LSC closed form; too few angles are failures.
#include "volcomp/metrology/polar_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_support.hpp"

namespace volcomp::metrology {
namespace {

using testing::ExpectFailure;
using testing::ValueOf;

constexpr double kPi = 3.14159265358979323846;

TEST(MetrologyMinimumZone, RecoversTheCentreOfAnOffsetLobedProfile) {
  // p = 1 + 0.3 cos θ + 0.2 sin θ + A cos 3θ: the lobes equi-oscillate, so MZ = LSC = (0.3, 0.2)
  // and the zone is 2A.
  const double A = 0.05;
  std::vector<double> a, p;
  for (int j = 0; j < 90; ++j) {
    const double th = 2 * kPi * j / 90;
    a.push_back(4.0 * j);
    p.push_back(1 + 0.3 * std::cos(th) + 0.2 * std::sin(th) + A * std::cos(3 * th));
  }
  const CentreFit mz = ValueOf(FitMinimumZoneCentre(a, p));
  EXPECT_NEAR(mz.a, 0.3, 1e-9);
  EXPECT_NEAR(mz.b, 0.2, 1e-9);
  EXPECT_NEAR(ValueAbout(a, p, mz.a, mz.b), 2 * A, 1e-9);
}

TEST(MetrologyMinimumZone, NeverWiderThanLscOrPcAndLocallyOptimal) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 8 + trial * 7;
    std::vector<double> a, p;
    for (int j = 0; j < n; ++j) {
      // Unequal spacing on purpose.
      a.push_back(360.0 * (j + 0.3 * u(rng) + 0.3) / n);
      p.push_back(u(rng) + 0.5 * std::cos(a.back() * kPi / 180 + 1.0));
    }
    const CentreFit lsc = ValueOf(FitLeastSquaresCentre(a, p));
    const CentreFit mz = ValueOf(FitMinimumZoneCentre(a, p));
    const double v = ValueAbout(a, p, mz.a, mz.b);
    EXPECT_LE(v, ValueAbout(a, p, lsc.a, lsc.b) + 1e-12) << trial;
    EXPECT_LE(v, ValueAbout(a, p, 0.0, 0.0) + 1e-12) << trial;
    for (int d = 0; d < 16; ++d) {
      const double h = 1e-4, ang = 2 * kPi * d / 16;
      EXPECT_GE(ValueAbout(a, p, mz.a + h * std::cos(ang), mz.b + h * std::sin(ang)), v - 1e-12)
          << "trial " << trial << " direction " << d;
    }
  }
}

TEST(MetrologyLeastSquaresCentre, ClosedFormForEqualSpacing) {
  std::vector<double> a, p;
  for (int j = 0; j < 36; ++j) {
    const double th = 2 * kPi * j / 36;
    a.push_back(10.0 * j);
    p.push_back(0.7 - 0.4 * std::cos(th) + 0.9 * std::sin(th) + 0.1 * std::cos(2 * th));
  }
  const CentreFit c = ValueOf(FitLeastSquaresCentre(a, p));
  EXPECT_NEAR(c.mean, 0.7, 1e-12);
  EXPECT_NEAR(c.a, -0.4, 1e-12);
  EXPECT_NEAR(c.b, 0.9, 1e-12);
}

TEST(MetrologyCentres, RejectTooFewAngles) {
  ExpectFailure(FitLeastSquaresCentre({0, 0, 360}, {1, 2, 3}), Error::kInvalidArgument,
                {"least-squares centre needs at least 3 distinct angles"});
  ExpectFailure(FitMinimumZoneCentre({0, 90, 180}, {1, 2, 3}), Error::kInvalidArgument,
                {"minimum-zone centre needs at least 4 distinct angles"});
}

}  // namespace
}  // namespace volcomp::metrology
