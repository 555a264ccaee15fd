// Centres of polar profiles (polar_fit.hpp): the minimum-zone (MRS) centre is exact on
// equi-oscillating profiles, never worse than LSC or PC, and locally optimal (the zone is convex in
// the centre, so local = global); the LSC closed form; too few angles are failures.
#include "volcomp/metrology/polar_fit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

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

// Hand-worked: eight angles 45° apart, a single spike p(0°) = 1, zero elsewhere. The smallest
// circle that contains it is centred halfway to the spike, a = 0.5 (residuals 0.5 at 0° and at
// 180°; b = 0 by symmetry, which also gives the largest inner circle, −0.5·cos 45°); the largest
// inscribed circle is only at the PC centre (±b at 90°/270° force b = 0, ∓0.707·a at 45°/135°
// force a = 0), with inner radius 0 and value 1.
TEST(MetrologyOneSidedCentres, HandWorkedSpike) {
  std::vector<double> a, p;
  for (int j = 0; j < 8; ++j) a.push_back(45.0 * j), p.push_back(j == 0 ? 1.0 : 0.0);
  const CentreFit mcc = ValueOf(FitMinimumCircumscribedCentre(a, p));
  EXPECT_NEAR(mcc.a, 0.5, 1e-9);
  EXPECT_NEAR(mcc.b, 0.0, 1e-9);
  EXPECT_NEAR(mcc.mean, 0.5, 1e-9);
  EXPECT_NEAR(ValueAbout(a, p, mcc.a, mcc.b), 0.5 + 0.5 * std::sqrt(0.5), 1e-9);
  const CentreFit mic = ValueOf(FitMaximumInscribedCentre(a, p));
  EXPECT_NEAR(mic.a, 0.0, 1e-9);
  EXPECT_NEAR(mic.b, 0.0, 1e-9);
  EXPECT_NEAR(mic.mean, 0.0, 1e-9);
  EXPECT_NEAR(ValueAbout(a, p, mic.a, mic.b), 1.0, 1e-9);
}

// Hand-worked tie: p = (2, 0, 0, 0) at 0/90/180/270°. MCC: u = max(2 − a, a, |b|) is smallest,
// 1, only at (1, 0). MIC: min(2 − a, a, −b, b) is largest, 0, for every a in [0, 2] with b = 0;
// the tie-break (smallest outer radius, max(2 − a, a)) picks a = 1.
TEST(MetrologyOneSidedCentres, TieBrokenBySmallestValue) {
  const std::vector<double> a = {0, 90, 180, 270}, p = {2, 0, 0, 0};
  const CentreFit mic = ValueOf(FitMaximumInscribedCentre(a, p));
  EXPECT_NEAR(mic.a, 1.0, 1e-9);
  EXPECT_NEAR(mic.b, 0.0, 1e-9);
  EXPECT_NEAR(mic.mean, 0.0, 1e-9);
  const CentreFit mcc = ValueOf(FitMinimumCircumscribedCentre(a, p));
  EXPECT_NEAR(mcc.a, 1.0, 1e-9);
  EXPECT_NEAR(mcc.mean, 1.0, 1e-9);
}

// The oracle shares nothing with the fit: the optimum of a linear min-max in (a, b) lies where
// three residuals are equal (a vertex), so every triple of angles is solved by Cramer's rule and
// the best vertex that keeps all residuals on its side is the answer.
struct Vertex {
  double radius, a, b;
};
Vertex BruteForceCentre(const std::vector<double>& deg, const std::vector<double>& p, bool outer) {
  const std::size_t n = p.size();
  std::vector<double> c(n), s(n);
  for (std::size_t j = 0; j < n; ++j)
    c[j] = std::cos(deg[j] * kPi / 180), s[j] = std::sin(deg[j] * kPi / 180);
  Vertex best{outer ? 1e300 : -1e300, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      for (std::size_t k = j + 1; k < n; ++k) {
        // r = p − a c − b s equal at i, j, k:  a (c_i − c_j) + b (s_i − s_j) = p_i − p_j, and k.
        const double m11 = c[i] - c[j], m12 = s[i] - s[j], v1 = p[i] - p[j];
        const double m21 = c[i] - c[k], m22 = s[i] - s[k], v2 = p[i] - p[k];
        const double det = m11 * m22 - m12 * m21;
        if (std::fabs(det) < 1e-12) continue;
        const double a = (v1 * m22 - m12 * v2) / det, b = (m11 * v2 - v1 * m21) / det;
        const double r = p[i] - a * c[i] - b * s[i];
        bool ok = true;
        for (std::size_t q = 0; q < n && ok; ++q) {
          const double rq = p[q] - a * c[q] - b * s[q];
          ok = outer ? rq <= r + 1e-12 : rq >= r - 1e-12;
        }
        if (ok && (outer ? r < best.radius : r > best.radius)) best = {r, a, b};
      }
    }
  }
  return best;
}

TEST(MetrologyOneSidedCentres, MatchBruteForceVerticesOnRandomProfiles) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 25; ++trial) {
    const int n = 6 + trial;
    std::vector<double> a, p;
    for (int j = 0; j < n; ++j) {
      a.push_back(360.0 * (j + 0.3 * u(rng) + 0.3) / n);  // unequal spacing on purpose
      p.push_back(3.0 * u(rng) + 2.0 * std::cos(a.back() * kPi / 180 - 0.7));
    }
    const Vertex outer = BruteForceCentre(a, p, true), inner = BruteForceCentre(a, p, false);
    const CentreFit mcc = ValueOf(FitMinimumCircumscribedCentre(a, p));
    const CentreFit mic = ValueOf(FitMaximumInscribedCentre(a, p));
    EXPECT_NEAR(mcc.mean, outer.radius, 1e-8) << trial;
    EXPECT_NEAR(mcc.a, outer.a, 1e-6) << trial;
    EXPECT_NEAR(mcc.b, outer.b, 1e-6) << trial;
    EXPECT_NEAR(mic.mean, inner.radius, 1e-8) << trial;
    EXPECT_NEAR(mic.a, inner.a, 1e-6) << trial;
    EXPECT_NEAR(mic.b, inner.b, 1e-6) << trial;
    // And the definitions: no other centre has a smaller outer / larger inner circle.
    const CentreFit mz = ValueOf(FitMinimumZoneCentre(a, p));
    for (const auto& [ca, cb] : {std::pair{0.0, 0.0}, std::pair{mz.a, mz.b}}) {
      const auto r = ResidualsAbout(a, p, ca, cb);
      EXPECT_LE(mcc.mean, *std::max_element(r.begin(), r.end()) + 1e-9) << trial;
      EXPECT_GE(mic.mean, *std::min_element(r.begin(), r.end()) - 1e-9) << trial;
    }
    EXPECT_GE(ValueAbout(a, p, mcc.a, mcc.b), ValueAbout(a, p, mz.a, mz.b) - 1e-9) << trial;
  }
}

TEST(MetrologyOneSidedCentres, RefuseAnglesWithinAHalfCircle) {
  // All angles within 0..150°: a circle can be shrunk without bound by moving its centre away.
  ExpectFailure(FitMinimumCircumscribedCentre({0, 50, 100, 150}, {1, 2, 0, 1}),
                Error::kInvalidArgument,
                {"minimum circumscribed centre: no centre", "half circle"});
  ExpectFailure(FitMaximumInscribedCentre({0, 90, 180}, {1, 2, 3}), Error::kInvalidArgument,
                {"maximum inscribed centre needs at least 4 distinct angles"});
}

}  // namespace
}  // namespace volcomp::metrology
