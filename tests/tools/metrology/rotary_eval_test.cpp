// ISO 230-7 evaluation of a record (rotary_eval.hpp): profiles from the channels for both
// sensitive directions, tilt, axial and face, the Donaldson reversal, and options that do not fit
// the channels (failures naming the file).
#include "volcomp/metrology/rotary_eval.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <utility>

#include "rotary_fixtures.hpp"
#include "test_support.hpp"

namespace volcomp::metrology {
namespace {

using testing::Angles;
using testing::Csv;
using testing::ExpectFailure;
using testing::kPi;
using testing::Make;
using testing::Record;
using testing::ValueOf;

RotaryRecord Load(const std::string& csv) { return ValueOf(ReadRotaryCsv(Csv(csv, "r.csv"))); }

TEST(MetrologyErrorMotion, TwoLobeMotionFixedVersusRotatingSensitiveDirection) {
  // A.11-A.18: ΔX = A cos 2θ, ΔY = A sin 2θ.
  const double A = 0.8;
  const int n = 72, k = 2;  // 5° steps: the peaks of cos 2θ are sampled
  const auto x = Make(n, k, [&](double t) { return A * std::cos(2 * t); });
  const auto y = Make(n, k, [&](double t) { return A * std::sin(2 * t); });
  RotaryOptions fsd;
  fsd.sensitive = SensitiveDirection::kFixed;
  fsd.fsd_angle_deg = 0.0;
  const auto f = ValueOf(EvaluateRotary(Record(n, k, {{"x_um", x}, {"y_um", y}}), fsd));
  EXPECT_NEAR(f.measurements[0].motion.lsc.synchronous, 2 * A, 1e-9);  // (A.14): 2A
  EXPECT_NEAR(f.measurements[0].motion.pc.synchronous, 2 * A, 1e-9);
  const auto r = ValueOf(EvaluateRotary(Record(n, k, {{"x_um", x}, {"y_um", y}}), RotaryOptions{}));
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
  const auto rsd =
      ValueOf(EvaluateRotary(Record(n, k, {{"x_um", x}, {"y_um", y}}), RotaryOptions{}));
  EXPECT_NEAR(rsd.measurements[0].motion.lsc.synchronous, 2 * d, 1e-9);  // r = r0 + e − δ cos 2θ
  ASSERT_TRUE(rsd.radial_fundamentals);
  EXPECT_NEAR(rsd.radial_fundamentals->positive_um, e, 1e-9);  // c₊ = e
  EXPECT_NEAR(rsd.radial_fundamentals->negative_um, d, 1e-9);  // c₋ = −δ
  EXPECT_NEAR(std::fabs(rsd.radial_fundamentals->negative_phase_deg), 180.0, 1e-7);
  for (double angle : {0.0, 90.0}) {
    RotaryOptions o;
    o.sensitive = SensitiveDirection::kFixed;
    o.fsd_angle_deg = angle;
    const auto f = ValueOf(EvaluateRotary(Record(n, k, {{"x_um", x}, {"y_um", y}}), o));
    EXPECT_NEAR(f.measurements[0].motion.lsc.synchronous, 0.0, 1e-9) << angle;
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
    const ReversalResult r = ValueOf(DonaldsonReversal(a, t1, t2, proc));
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
  const auto ev = ValueOf(EvaluateRotary(
      Record(
          n, k,
          {{"x_um", at(z1)}, {"x2_um", at(z1 + L)}, {"z_um", Make(n, k, e_z)}, {"face_um", face}}),
      o));
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
  const auto ev = ValueOf(EvaluateRotary(
      Record(n, k, {{"x_um", zero}, {"y_um", zero}, {"x2_um", x2}, {"y2_um", y2}}), o));
  for (const auto& m : ev.measurements) {
    if (m.key != "tilt") continue;
    // r = ΔX cos θ + ΔY sin θ = 2 µrad · cos 2θ.
    EXPECT_NEAR(m.motion.lsc.synchronous, 4.0, 1e-9);
    return;
  }
  FAIL() << "no tilt measurement";
}

TEST(MetrologyRotaryEvaluation, OptionsThatDoNotFitTheChannels) {
  const RotaryRecord only_x = Load("rev,angle_deg,x_um\n1,0,0\n1,90,1\n1,180,0\n1,270,1\n");
  ExpectFailure(EvaluateRotary(only_x, RotaryOptions{}), Error::kInputInvalid,
                {"r.csv: ", "rotating sensitive direction", "y_um"});
  RotaryOptions fixed45;
  fixed45.sensitive = SensitiveDirection::kFixed;
  fixed45.fsd_angle_deg = 45.0;
  ExpectFailure(EvaluateRotary(only_x, fixed45), Error::kInputInvalid, {"y_um"});
  std::string csv = "rev,angle_deg,x_um,y_um,x2_um,y2_um\n";
  for (int j = 0; j < 8; ++j) csv += "1," + std::to_string(45 * j) + ",0,0,0,0\n";
  const auto ev = ValueOf(EvaluateRotary(Load(csv), RotaryOptions{}));
  ASSERT_EQ(ev.measurements.size(), 2u);  // radial at both planes, no tilt
  ASSERT_FALSE(ev.warnings.empty());
  EXPECT_NE(ev.warnings.front().find("--tilt-distance-mm"), std::string::npos);
}

TEST(MetrologyRotaryEvaluation, ReversalOfTwoRecordsNeedsTheSameAnglesAndTheChannel) {
  const int n = 8;
  const auto lobes = Make(n, 2, [](double t) { return std::cos(2 * t); });
  const RotaryRecord one = Record(n, 2, {{"x_um", lobes}});
  RotaryRecord two = Record(n, 2, {{"x_um", lobes}});
  two.source = "setup2.csv";
  const ReversalResult r = ValueOf(DonaldsonReversal(one, two, "x_um", ReversalProcedure::kS));
  EXPECT_NEAR(r.spindle_value, 2.0, 1e-9);  // S = (T1 + T2)/2 = cos 2θ
  EXPECT_NEAR(r.artefact_value, 0.0, 1e-9);
  ExpectFailure(DonaldsonReversal(one, two, "y_um", ReversalProcedure::kP), Error::kInputInvalid,
                {"synthetic: no column \"y_um\" for the reversal"});
  RotaryRecord other = Record(n + 1, 2, {{"x_um", Make(n + 1, 2, [](double) { return 0.0; })}});
  other.source = "setup2.csv";
  ExpectFailure(DonaldsonReversal(one, other, "x_um", ReversalProcedure::kP), Error::kInputInvalid,
                {"setup2.csv: the reversal record has 9 angles per revolution, synthetic has 8"});
  other = Record(n, 2, {{"x_um", lobes}});
  other.source = "setup2.csv";
  other.angle_deg[1] += 1.0;
  ExpectFailure(DonaldsonReversal(one, other, "x_um", ReversalProcedure::kP), Error::kInputInvalid,
                {"setup2.csv: the reversal record must use the angles of synthetic"});
  ExpectFailure(DonaldsonReversal(Angles(n), {1.0}, {1.0}, ReversalProcedure::kP),
                Error::kInvalidArgument, {"same angles"});
}

// CW revolutions carry 2·cos 3θ, CCW ones 1·cos 3θ (µm): about LSC the synchronous values are 4
// and 2 per direction and 3 pooled (the mean, 1.5·cos 3θ); the pooled record's asynchronous
// value is the largest spread between the two, (2 − 1)·|cos 3θ| = 1; and the note on pooling.
TEST(MetrologyRotaryEvaluation, ValuesPerDirectionAndPooled) {
  const int n = 36;
  Revolutions u = Make(n, 2, [](double t) { return 2.0 * std::cos(3 * t); });
  const Revolutions ccw = Make(n, 2, [](double t) { return std::cos(3 * t); });
  u.insert(u.end(), ccw.begin(), ccw.end());
  RotaryRecord rec = Record(n, 4, {{"z_um", u}});
  rec.rev_sense = {RotationSense::kCw, RotationSense::kCw, RotationSense::kCcw,
                   RotationSense::kCcw};
  const auto ev = ValueOf(EvaluateRotary(rec, RotaryOptions{}));
  EXPECT_EQ(ev.revolutions_cw, 2);
  EXPECT_EQ(ev.revolutions_ccw, 2);
  EXPECT_NEAR(ev.measurements[0].motion.pc.synchronous, 3.0, 1e-9);
  EXPECT_NEAR(ev.measurements[0].motion.asynchronous_value, 1.0, 1e-9);
  ASSERT_EQ(ev.by_direction.size(), 2u);
  EXPECT_EQ(ev.by_direction[0].sense, RotationSense::kCw);
  EXPECT_EQ(ev.by_direction[0].revolutions, 2);
  EXPECT_NEAR(ev.by_direction[0].measurements[0].motion.pc.synchronous, 4.0, 1e-9);
  EXPECT_NEAR(ev.by_direction[1].measurements[0].motion.pc.synchronous, 2.0, 1e-9);
  EXPECT_NEAR(ev.by_direction[1].measurements[0].motion.asynchronous_value, 0.0, 1e-12);
  bool noted = false;
  for (const auto& w : ev.warnings)
    noted |= w.find("does not say whether CW and CCW") != std::string::npos;
  EXPECT_TRUE(noted);
}

bool Warns(const RotaryEvaluation& ev, const std::string& text) {
  for (const auto& w : ev.warnings) {
    if (w.find(text) != std::string::npos) return true;
  }
  return false;
}

// The revolution rules of the kind of axis: spindles 20; tables radial 4 + 4, axial 5 + 5;
// heads radial 2 + 2; static tests 2 revolutions of 8 stops.
TEST(MetrologyRotaryEvaluation, NumberOfRevolutionsRules) {
  const auto flat = [](int k) { return Make(8, k, [](double) { return 0.0; }); };
  RotaryOptions spindle;
  EXPECT_TRUE(Warns(ValueOf(EvaluateRotary(Record(8, 19, {{"z_um", flat(19)}}), spindle)),
                    "19 revolution(s): ISO 230-7 asks at least 20"));
  EXPECT_FALSE(Warns(ValueOf(EvaluateRotary(Record(8, 20, {{"z_um", flat(20)}}), spindle)),
                     "asks at least 20"));
  RotaryOptions table;
  table.axis = RotaryAxisKind::kTable;
  RotaryRecord rec = Record(8, 7, {{"x_um", flat(7)}, {"y_um", flat(7)}, {"z_um", flat(7)}});
  rec.rev_sense.assign(7, RotationSense::kCw);
  for (int k = 3; k < 7; ++k) rec.rev_sense[k] = RotationSense::kCcw;
  const auto t = ValueOf(EvaluateRotary(rec, table));
  EXPECT_TRUE(Warns(t,
                    "3 CW and 4 CCW revolutions: ISO 230-7 asks at least 4 CW + 4 CCW for the "
                    "radial and tilt error motion of a rotary table (6.3.2, 6.4.2)"));
  EXPECT_TRUE(Warns(t, "asks at least 5 CW + 5 CCW for the axial error motion of a rotary table"));
  RotaryOptions head;
  head.axis = RotaryAxisKind::kHead;
  const auto h = ValueOf(EvaluateRotary(rec, head));
  EXPECT_FALSE(Warns(h, "2 CW + 2 CCW"));  // 3 + 4 meets 2 + 2
  EXPECT_TRUE(Warns(h, "5 CW + 5 CCW for the axial error motion of a swivelling head"));
  RotaryRecord unstated = Record(8, 8, {{"x_um", flat(8)}, {"y_um", flat(8)}});
  EXPECT_TRUE(Warns(ValueOf(EvaluateRotary(unstated, table)),
                    "(8 without a direction; add a direction column)"));
  RotaryOptions stat;
  stat.static_test = true;
  const auto s = ValueOf(
      EvaluateRotary(Record(6, 1, {{"z_um", Make(6, 1, [](double) { return 0.0; })}}), stat));
  EXPECT_TRUE(Warns(s, "1 revolution(s): a static test asks at least 2 (ISO 230-7 E.2)"));
  EXPECT_TRUE(Warns(s, "6 stops per revolution: a static test asks at least 8"));
  EXPECT_FALSE(Warns(s, "asks at least 20"));
}

// Annex F on each value: radial in µm as stated, tilt scaled by √2·1000/L into µrad; no
// instrument, no U and a warning.
TEST(MetrologyRotaryEvaluation, EachValueCarriesItsUncertainty) {
  const int n = 16, k = 4;
  const auto x = Make(n, k, [](double t) { return std::cos(2 * t); });
  const auto x2 = Make(n, k, [](double t) { return 0.5 * std::cos(2 * t); });
  RotaryOptions o;
  o.sensitive = SensitiveDirection::kFixed;
  o.tilt_distance_mm = 100.0;
  const RotaryRecord rec = Record(n, k, {{"x_um", x}, {"x2_um", x2}});
  const auto none = ValueOf(EvaluateRotary(rec, o));
  EXPECT_FALSE(none.measurements[0].u);
  EXPECT_TRUE(Warns(none, "no measurement uncertainty"));
  o.uncertainty.device_calibration_um = 0.1;
  o.uncertainty.drift_range_um = 0.5;  // U_EVE 0.3
  const auto ev = ValueOf(EvaluateRotary(rec, o));
  ASSERT_EQ(ev.measurements.size(), 3u);  // radial, plane 2, tilt
  ASSERT_TRUE(ev.measurements[0].u);
  // U_sync value = 1.4·sqrt(0.01 + 0.09/4) = 1.4·0.180278 = 0.252389 µm.
  EXPECT_NEAR(ev.measurements[0].u->synchronous_value, 0.252389, 1e-6);
  EXPECT_EQ(ev.measurements[2].key, "tilt");
  EXPECT_NEAR(ev.measurements[2].u->synchronous_value, 0.252389 * std::sqrt(2.0) * 10.0, 1e-5);
  EXPECT_FALSE(Warns(ev, "no measurement uncertainty"));
}

}  // namespace
}  // namespace volcomp::metrology
