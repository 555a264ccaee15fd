// ISO 230-7 closed-form cases (reference digest §8): eccentricity, two-lobe motion (A.11),
// stiffness asymmetry (A.10), half-speed component, noise averaging, FFT equivalence, Donaldson
// reversal round trip, tilt and face consistency (A.2, A.3, A.5, A.6).
#include "volcomp/metrology/error_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>

#include "volcomp/metrology/polar_fit.hpp"
#include "volcomp/metrology/rotary_eval.hpp"

namespace volcomp::metrology {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<double> Angles(int n) {
  std::vector<double> a(n);
  for (int j = 0; j < n; ++j) a[j] = 360.0 * j / n;
  return a;
}

// u[k][j] = f(θ_total) with θ_total = θ_j + 360°·k in radians.
template <typename F>
Revolutions Make(int n, int k_revs, F f) {
  Revolutions u(k_revs, std::vector<double>(n));
  for (int k = 0; k < k_revs; ++k) {
    for (int j = 0; j < n; ++j) u[k][j] = f(2 * kPi * (j / static_cast<double>(n) + k));
  }
  return u;
}

// A record with the given channels, sampled at n angles over k revolutions.
RotaryRecord Record(int n, int k_revs, const std::map<std::string, Revolutions>& channels) {
  RotaryRecord r;
  r.source = "synthetic";
  r.angle_deg = Angles(n);
  for (int k = 0; k < k_revs; ++k) r.revs.push_back(k + 1);
  r.channels = channels;
  return r;
}

TEST(MetrologyErrorMotion, PureEccentricityFixedDirection) {
  const double e = 3.0, phi = 35.0 * kPi / 180;  // peaks fall on the 5° sampling grid
  const auto em = AnalyseErrorMotion(
      Angles(72), Make(72, 4, [&](double t) { return e * std::cos(t + phi); }), true);
  EXPECT_NEAR(em.lsc.synchronous, 0.0, 1e-9);
  EXPECT_NEAR(em.pc.synchronous, 2 * e, 1e-9);
  EXPECT_NEAR(em.fundamental_value, 2 * e, 1e-9);
  EXPECT_NEAR(std::hypot(em.lsc.a, em.lsc.b), e, 1e-9);
  EXPECT_NEAR(em.fundamental_angle_deg, -phi * 180 / kPi, 1e-7);
  EXPECT_NEAR(em.asynchronous_value, 0.0, 1e-12);
  EXPECT_NEAR(em.mz->synchronous, 0.0, 1e-7);
}

TEST(MetrologyErrorMotion, TwoLobeMotionFixedVersusRotatingSensitiveDirection) {
  // A.11-A.18: ΔX = A cos 2θ, ΔY = A sin 2θ.
  const double A = 0.8;
  const int n = 72, k = 2;  // 5° steps: the peaks of cos 2θ are sampled
  const auto x = Make(n, k, [&](double t) { return A * std::cos(2 * t); });
  const auto y = Make(n, k, [&](double t) { return A * std::sin(2 * t); });
  RotaryOptions fsd;
  fsd.sensitive = SensitiveDirection::kFixed;
  fsd.fsd_angle_deg = 0.0;
  const auto f = EvaluateRotary(Record(n, k, {{"x_um", x}, {"y_um", y}}), fsd);
  EXPECT_NEAR(f.measurements[0].motion.lsc.synchronous, 2 * A, 1e-9);  // (A.14): 2A
  EXPECT_NEAR(f.measurements[0].motion.pc.synchronous, 2 * A, 1e-9);
  const auto r = EvaluateRotary(Record(n, k, {{"x_um", x}, {"y_um", y}}), RotaryOptions{});
  // (A.15)-(A.18): r = r0 + A cos θ, a circle: 0 about LSC, 2A about PC.
  EXPECT_NEAR(r.measurements[0].motion.lsc.synchronous, 0.0, 1e-9);
  EXPECT_NEAR(r.measurements[0].motion.pc.synchronous, 2 * A, 1e-9);
}

TEST(MetrologyErrorMotion, StiffnessAsymmetry) {
  // A.10: ΔX = (e − δ) cos θ, ΔY = (e + δ) sin θ.
  const double e = 2.0, d = 0.25;
  const int n = 64, k = 2;
  const auto x = Make(n, k, [&](double t) { return (e - d) * std::cos(t); });
  const auto y = Make(n, k, [&](double t) { return (e + d) * std::sin(t); });
  const auto rsd = EvaluateRotary(Record(n, k, {{"x_um", x}, {"y_um", y}}), RotaryOptions{});
  EXPECT_NEAR(rsd.measurements[0].motion.lsc.synchronous, 2 * d, 1e-9);  // r = r0 + e − δ cos 2θ
  ASSERT_TRUE(rsd.radial_fundamentals);
  EXPECT_NEAR(rsd.radial_fundamentals->positive_um, e, 1e-9);  // c₊ = e
  EXPECT_NEAR(rsd.radial_fundamentals->negative_um, d, 1e-9);  // c₋ = −δ
  EXPECT_NEAR(std::fabs(rsd.radial_fundamentals->negative_phase_deg), 180.0, 1e-7);
  for (double angle : {0.0, 90.0}) {
    RotaryOptions o;
    o.sensitive = SensitiveDirection::kFixed;
    o.fsd_angle_deg = angle;
    const auto f = EvaluateRotary(Record(n, k, {{"x_um", x}, {"y_um", y}}), o);
    EXPECT_NEAR(f.measurements[0].motion.lsc.synchronous, 0.0, 1e-9) << angle;
  }
}

TEST(MetrologyErrorMotion, HalfSpeedComponentIsAsynchronous) {
  const double B = 0.4;
  const int n = 48;
  for (int k : {2, 4, 8}) {
    const auto base = Make(n, k, [](double t) { return 0.5 * std::cos(3 * t); });
    const auto with =
        Make(n, k, [&](double t) { return 0.5 * std::cos(3 * t) + B * std::cos(t / 2); });
    const auto a = AnalyseErrorMotion(Angles(n), base, false);
    const auto b = AnalyseErrorMotion(Angles(n), with, false);
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
        AnalyseErrorMotion(Angles(n), Make(n, k, [&](double) { return noise(rng); }), false);
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
  const auto em = AnalyseErrorMotion(Angles(n), u, false);
  for (int t = 0; t < n; ++t) {
    std::complex<double> s = 0;
    for (int f = 0; f < total; f += k) s += spec[f] * std::polar(1.0, 2 * kPi * f * t / total);
    EXPECT_NEAR(s.real() / total, em.synchronous[t], 1e-10);
  }
}

TEST(MetrologyErrorMotion, DonaldsonReversalRoundTrip) {
  std::mt19937 rng(9);
  std::normal_distribution<double> noise(0.0, 0.002);
  const int n = 120;
  const auto a = Angles(n);
  std::vector<double> p(n), s(n), t1(n), t2p(n), t2s(n);
  for (int j = 0; j < n; ++j) {
    const double th = a[j] * kPi / 180;
    p[j] = 0.5 * std::cos(3 * th + 0.3);  // artefact: 3 lobes
    s[j] = 0.2 * std::cos(2 * th - 0.4);  // spindle: 2 lobes
    t1[j] = p[j] + s[j] + noise(rng);     // (B.1)
    t2p[j] = p[j] - s[j] + noise(rng);    // (B.2)
    t2s[j] = -t2p[j];                     // (B.4)
  }
  for (const auto& [t2, proc] :
       {std::make_pair(t2p, ReversalProcedure::kP), std::make_pair(t2s, ReversalProcedure::kS)}) {
    const ReversalResult r = DonaldsonReversal(a, t1, t2, proc);
    for (int j = 0; j < n; ++j) {
      EXPECT_NEAR(r.artefact[j], p[j], 0.01);
      EXPECT_NEAR(r.spindle[j], s[j], 0.01);
    }
    EXPECT_NEAR(r.artefact_value, 1.0, 0.02);
    EXPECT_NEAR(r.spindle_value, 0.4, 0.02);
  }
}

TEST(MetrologyErrorMotion, TiltFromTwoPlanesAndFromAxialAndFace) {
  // E_X0C(θ) pure radial and E_BC(θ) tilt (rad); planes z1 and z2 = z1 + L (A.2):
  // E_XC|z = E_X0C + z·E_BC. Face at radius R (A.3): E_ZC|R = E_ZC − R·E_BC.
  const double L = 100.0, z1 = 40.0, R = 50.0;                                         // mm
  auto e_x0 = [](double t) { return 0.3 * std::cos(2 * t) + 0.1 * std::sin(5 * t); };  // µm
  auto e_b = [](double t) { return 4e-6 * std::cos(3 * t + 0.2); };                    // rad
  auto e_z = [](double t) { return 0.2 * std::cos(t) + 0.05 * std::cos(4 * t); };      // µm
  const int n = 180, k = 3;
  auto at = [&](double z) {
    return Make(n, k, [&, z](double t) { return e_x0(t) + z * 1000.0 * e_b(t); });  // µm
  };
  const auto face = Make(n, k, [&](double t) { return e_z(t) - R * 1000.0 * e_b(t); });
  RotaryOptions o;
  o.sensitive = SensitiveDirection::kFixed;
  o.tilt_distance_mm = L;
  o.face_radius_mm = R;
  const auto ev = EvaluateRotary(
      Record(
          n, k,
          {{"x_um", at(z1)}, {"x2_um", at(z1 + L)}, {"z_um", Make(n, k, e_z)}, {"face_um", face}}),
      o);
  const RotaryMeasurement* tilt = nullptr;
  const RotaryMeasurement* tilt_af = nullptr;
  const RotaryMeasurement* axial = nullptr;
  for (const auto& m : ev.measurements) {
    if (m.key == "tilt") tilt = &m;
    if (m.key == "tilt_axial_face") tilt_af = &m;
    if (m.key == "axial") axial = &m;
  }
  ASSERT_TRUE(tilt && tilt_af && axial);
  EXPECT_EQ(tilt->unit, "µrad");
  for (int j = 0; j < n; ++j) {
    const double t = 2 * kPi * j / n;
    EXPECT_NEAR(tilt->motion.synchronous[j], e_b(t) * 1e6, 1e-9);     // (A.6), formula (5)
    EXPECT_NEAR(tilt_af->motion.synchronous[j], e_b(t) * 1e6, 1e-9);  // (A.5)
  }
  EXPECT_NEAR(tilt->motion.lsc.synchronous, 8.0, 1e-3);  // 2 × 4 µrad (3 lobes, no fundamental)
  // Axial: PC centre; the fundamental axial value is the peak-to-peak of 0.2 cos θ.
  EXPECT_EQ(axial->preferred, CentreKind::kPc);
  EXPECT_NEAR(axial->motion.fundamental_value, 0.4, 1e-9);
  double lo = 1e9, hi = -1e9;
  for (int j = 0; j < n; ++j) {
    const double v = e_z(2 * kPi * j / n);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_NEAR(axial->motion.pc.synchronous, hi - lo, 1e-12);
}

TEST(MetrologyErrorMotion, RotatingTiltUsesThePlaneDifferenceInFormulaOne) {
  // Tilt about Y and X of a rotating direction: ΔX = L·E_BC, ΔY = −L·E_AC at the second plane.
  const double L = 80.0;
  const int n = 120, k = 2;
  const auto zero = Make(n, k, [](double) { return 0.0; });
  const auto x2 =
      Make(n, k, [&](double t) { return L * 1000.0 * 2e-6 * std::cos(t) * std::cos(2 * t); });
  const auto y2 =
      Make(n, k, [&](double t) { return L * 1000.0 * 2e-6 * std::sin(t) * std::cos(2 * t); });
  RotaryOptions o;
  o.tilt_distance_mm = L;
  const auto ev = EvaluateRotary(
      Record(n, k, {{"x_um", zero}, {"y_um", zero}, {"x2_um", x2}, {"y2_um", y2}}), o);
  for (const auto& m : ev.measurements) {
    if (m.key != "tilt") continue;
    // r = ΔX cos θ + ΔY sin θ = 2 µrad · cos 2θ.
    EXPECT_NEAR(m.motion.lsc.synchronous, 4.0, 1e-9);
    return;
  }
  FAIL() << "no tilt measurement";
}

}  // namespace
}  // namespace volcomp::metrology
