// ISO 230-7 error-motion analysis of one profile (error_motion.hpp), closed-form cases (reference
// digest §8): eccentricity, half-speed component, noise averaging, FFT equivalence.
#include "volcomp/metrology/error_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>

#include "rotary_fixtures.hpp"
#include "test_support.hpp"
#include "volcomp/metrology/polar_fit.hpp"

namespace volcomp::metrology {
namespace {

using testing::Angles;
using testing::ExpectFailure;
using testing::kPi;
using testing::Make;
using testing::ValueOf;

TEST(MetrologyErrorMotion, PureEccentricityFixedDirection) {
  const double e = 3.0, phi = 35.0 * kPi / 180;  // peaks fall on the 5° sampling grid
  const auto em = ValueOf(
      AnalyseErrorMotion(Angles(72), Make(72, 4, [&](double t) { return e * std::cos(t + phi); }),
                         {true, true, true}));
  EXPECT_NEAR(em.lsc.synchronous, 0.0, 1e-9);
  EXPECT_NEAR(em.pc.synchronous, 2 * e, 1e-9);
  EXPECT_NEAR(em.fundamental_value, 2 * e, 1e-9);
  EXPECT_NEAR(std::hypot(em.lsc.a, em.lsc.b), e, 1e-9);
  EXPECT_NEAR(em.fundamental_angle_deg, -phi * 180 / kPi, 1e-7);
  EXPECT_NEAR(em.asynchronous_value, 0.0, 1e-12);
  // Pure eccentricity is a circle about its own centre: every centre sees zero.
  EXPECT_NEAR(em.mrs->synchronous, 0.0, 1e-7);
  EXPECT_NEAR(em.mic->synchronous, 0.0, 1e-7);
  EXPECT_NEAR(em.mcc->synchronous, 0.0, 1e-7);
}

TEST(MetrologyErrorMotion, CentresAreComputedOnlyWhenChosenAndListedInOrder) {
  const auto u = Make(36, 3, [](double t) { return std::cos(3 * t) + 0.4 * std::cos(t); });
  const auto none = ValueOf(AnalyseErrorMotion(Angles(36), u, {}));
  EXPECT_FALSE(none.mrs || none.mic || none.mcc);
  EXPECT_EQ(&ValuesAbout(none, CentreKind::kMic), &none.lsc);  // not chosen: LSC
  const auto some = ValueOf(AnalyseErrorMotion(Angles(36), u, {false, true, true}));
  const auto list = ComputedCentres(some);
  ASSERT_EQ(list.size(), 4u);
  EXPECT_STREQ(CentreName(list[2]->kind), "MIC");
  EXPECT_STREQ(CentreName(list[3]->kind), "MCC");
  EXPECT_EQ(&ValuesAbout(some, CentreKind::kMcc), &*some.mcc);
}

TEST(MetrologyErrorMotion, HalfSpeedComponentIsAsynchronous) {
  const double B = 0.4;
  const int n = 48;
  for (int k : {2, 4, 8}) {
    const auto base = Make(n, k, [](double t) { return 0.5 * std::cos(3 * t); });
    const auto with =
        Make(n, k, [&](double t) { return 0.5 * std::cos(3 * t) + B * std::cos(t / 2); });
    const auto a = ValueOf(AnalyseErrorMotion(Angles(n), base, {}));
    const auto b = ValueOf(AnalyseErrorMotion(Angles(n), with, {}));
    for (int j = 0; j < n; ++j) EXPECT_NEAR(a.synchronous[j], b.synchronous[j], 1e-12);
    EXPECT_NEAR(b.asynchronous_value, 2 * B, 1e-12) << k;  // at θ = 0 where |cos(θ/2)| = 1
    EXPECT_NEAR(b.asynchronous_angle_deg, 0.0, 1e-12);
    EXPECT_LE(b.pc.total, a.pc.synchronous + 2 * B + 1e-12);
    EXPECT_GE(b.pc.total, b.asynchronous_value);
  }
}

TEST(MetrologyErrorMotion, NoiseInTheSynchronousPlotFallsAsOneOverRootK) {
  std::mt19937 rng(42);
  std::normal_distribution<double> noise(0.0, 1.0);
  const int n = 256;
  auto sync_rms = [&](int k) {
    const auto em =
        ValueOf(AnalyseErrorMotion(Angles(n), Make(n, k, [&](double) { return noise(rng); }), {}));
    double s = 0;
    for (double v : em.synchronous) s += v * v;
    return std::sqrt(s / n);
  };
  const double r4 = sync_rms(4), r64 = sync_rms(64);
  EXPECT_NEAR(r4, 0.5, 0.08);     // 1/√4
  EXPECT_NEAR(r64, 0.125, 0.02);  // 1/√64
}

TEST(MetrologyErrorMotion, AveragingEqualsKeepingTheHarmonicBinsOfTheWholeRecord) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> v(-1.0, 1.0);
  const int n = 16, k = 4, total = n * k;
  Revolutions u(k, std::vector<double>(n));
  std::vector<double> flat;
  for (auto& rev : u) {
    for (double& x : rev) {
      x = v(rng);
      flat.push_back(x);
    }
  }
  // DFT of the K·N record; keep the bins at multiples of K (integer multiples of the rotation
  // frequency), inverse transform, compare with the revolution average.
  std::vector<std::complex<double>> spec(total);
  for (int f = 0; f < total; ++f) {
    for (int t = 0; t < total; ++t) spec[f] += flat[t] * std::polar(1.0, -2 * kPi * f * t / total);
  }
  const auto em = ValueOf(AnalyseErrorMotion(Angles(n), u, {}));
  for (int t = 0; t < n; ++t) {
    std::complex<double> s = 0;
    for (int f = 0; f < total; f += k) s += spec[f] * std::polar(1.0, 2 * kPi * f * t / total);
    EXPECT_NEAR(s.real() / total, em.synchronous[t], 1e-10);
  }
}

TEST(MetrologyErrorMotion, RecordsThatCannotBeAnalysedAreFailures) {
  ExpectFailure(AnalyseErrorMotion(Angles(8), {}, {}), Error::kInvalidArgument,
                {"at least one revolution"});
  ExpectFailure(AnalyseErrorMotion(Angles(3), Make(3, 1, [](double) { return 0.0; }), {}),
                Error::kInvalidArgument, {"at least 4 angles"});
  ExpectFailure(AnalyseErrorMotion(Angles(8), {std::vector<double>(7, 0.0)}, {}),
                Error::kInvalidArgument, {"unequal length"});
}

}  // namespace
}  // namespace volcomp::metrology
