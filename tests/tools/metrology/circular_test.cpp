// ISO 230-4 circular test evaluation against outside truths: a case worked by hand, an
// independent geometric evaluator (Cartesian points, Gauss-Newton circle fit, radial distances)
// that shares no code with metrology/circular, and malformed inputs.
#include "volcomp/metrology/circular.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "circle_fit.hpp"
#include "test_support.hpp"

namespace volcomp::metrology {
namespace {

using testing::Csv;
using testing::ExpectFailure;
using testing::ValueOf;

constexpr double kPi = 3.14159265358979323846;
double Rad(double deg) { return deg * kPi / 180.0; }

// The hand-worked case. Eight readings per path at θ_k = 45°·k (k = 0..7):
//   CW:  d(θ) = 5 + 3 cos θ + 2 sin θ + 4 cos 2θ       (centre offset (3, 2), ellipticity ±4 µm)
//   CCW: d(θ) = 1 + 3 cos θ + 2 sin θ + 4 cos 2θ + 12 at θ = 90° only (a reversal spike)
// On 8 equally spaced angles 1, cos θ, sin θ, cos 2θ are orthogonal, so the least-squares centre
// is m = mean, a = (2/8) Σ d cos θ, b = (2/8) Σ d sin θ:
//   CW:  m = 5, (a, b) = (3, 2); residual 5 + 4 cos 2θ: 9 ... 1, G_cw = 8.
//   CCW: m = 1 + 12/8 = 2.5, a = 3, b = 2 + (2/8)·12 = 5; residual 1 + 4 cos 2θ − 3 sin θ + 12δ:
//        k = 0..7: 5, 1 − 3/√2, 6, 1 − 3/√2, 5, 1 + 3/√2, 0, 1 + 3/√2; G_ccw = 6 − (1 − 3/√2)
//        = 5 + 3/√2 = 7.1213.
//   Both (16 readings): m = 3.75, (a, b) = (3, 3.5) = the centre offset.
//        CW about it 5 + 4 cos 2θ − 1.5 sin θ: max 9 (0°), CCW 1 + 4 cos 2θ − 1.5 sin θ + 12δ:
//        min −1.5 (270°); G(b) = 9 − (−1.5) = 10.5.
//   H: CW − CCW at the same angle about one centre = 4 − 12δ: |−8| at 90°, H = 8.
//   F: the raw deviations; CW max 5 + 3 + 4 = 12 at 0°; CCW min 1 − 2 − 4 = −5 at 270°.
CircularData HandCase() {
  CircularData d;
  for (int k = 0; k < 8; ++k) {
    const double t = Rad(45.0 * k);
    const double shape = 3 * std::cos(t) + 2 * std::sin(t) + 4 * std::cos(2 * t);
    d.cw.angle_deg.push_back(45.0 * k);
    d.cw.deviation_um.push_back(5 + shape);
    d.ccw.angle_deg.push_back(45.0 * k);
    d.ccw.deviation_um.push_back(1 + shape + (k == 2 ? 12.0 : 0.0));
  }
  return d;
}

TEST(Circular, HandWorkedCase) {
  const CircularResult r = ValueOf(EvaluateCircular(HandCase()));
  ASSERT_TRUE(r.has_cw && r.has_ccw);
  EXPECT_NEAR(r.G_cw_um, 8.0, 1e-9);
  EXPECT_NEAR(r.G_ccw_um, 5.0 + 3.0 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(r.G_b_um, 10.5, 1e-9);
  EXPECT_NEAR(r.H_um, 8.0, 1e-9);
  EXPECT_NEAR(r.H_angle_deg, 90.0, 1e-9);
  EXPECT_NEAR(r.F_max_um, 12.0, 1e-9);
  EXPECT_NEAR(r.F_min_um, -5.0, 1e-9);
  EXPECT_NEAR(r.centre_offset_x_um, 3.0, 1e-9);
  EXPECT_NEAR(r.centre_offset_y_um, 3.5, 1e-9);
  EXPECT_NEAR(r.mean_radius_dev_um, 3.75, 1e-9);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(Circular, OrderAndAngleRangeDoNotMatter) {
  // The CW path as a ballbar records it (descending angles), written as 0, −45, ..., −315.
  CircularData d = HandCase();
  std::reverse(d.cw.angle_deg.begin(), d.cw.angle_deg.end());
  std::reverse(d.cw.deviation_um.begin(), d.cw.deviation_um.end());
  for (double& a : d.cw.angle_deg) a -= 360.0;
  const CircularResult r = ValueOf(EvaluateCircular(d));
  EXPECT_NEAR(r.G_cw_um, 8.0, 1e-9);
  EXPECT_NEAR(r.G_b_um, 10.5, 1e-9);
  EXPECT_NEAR(r.H_um, 8.0, 1e-9);
}

// --- The independent evaluator (tests/support/circle_fit.hpp): geometry in the plane, no
// linearization. ---

using Point = ::volcomp::testing::PlanePoint;
using Circle = ::volcomp::testing::FittedCircle;
using ::volcomp::testing::FitCircle;

std::vector<Point> Points(const CircularPath& p, double radius_um) {
  return ::volcomp::testing::PathPoints(p.angle_deg, p.deviation_um, radius_um);
}
double Spread(const std::vector<Point>& pts, const Circle& c) {
  return ::volcomp::testing::RadialSpread(pts, c);
}

// A machine's circle: radius 50 mm, centre offset (12, −7) µm, ellipse ±6 µm at 30°, a
// servo-mismatch lobe, reversal spikes at the quadrants where an axis reverses, direction-
// dependent radius (−1.5 µm CW, +1.5 µm CCW), and ±0.2 µm noise from a fixed LCG. Angles: CW
// every 1° from 0.3°, CCW every 0.75° from 0.1° (so H needs interpolation for the second data
// set only when `same_angles` is false).
CircularData Machine(bool same_angles) {
  const double R = 50000.0, ex = 12.0, ey = -7.0;
  std::uint32_t seed = 12345;
  auto noise = [&seed] {
    seed = seed * 1664525u + 1013904223u;
    return (static_cast<double>(seed >> 8) / 16777216.0 - 0.5) * 0.4;
  };
  CircularData d;
  for (int dir = 0; dir < 2; ++dir) {
    CircularPath& p = dir == 0 ? d.cw : d.ccw;
    const double step = dir == 0 || same_angles ? 1.0 : 0.75;
    const double start = dir == 0 || same_angles ? 0.3 : 0.1;
    for (double a = start; a < 360.0; a += step) {
      const double t = Rad(a);
      double radial = (dir == 0 ? -1.5 : 1.5) + 6.0 * std::cos(2 * (t - Rad(30))) +
                      1.2 * std::sin(3 * t) + noise();
      for (double q : {0.0, 90.0, 180.0, 270.0}) {
        const double from = std::fabs(std::remainder(a - q, 360.0));
        if (from < 4.0) radial += (dir == 0 ? 3.0 : 5.0) * (1.0 - from / 4.0);
      }
      // The actual point: on a circle about (ex, ey), measured from the nominal centre (0, 0).
      const double r = R + radial;
      const double x = ex + r * std::cos(t), y = ey + r * std::sin(t);
      p.angle_deg.push_back(std::atan2(y, x) * 180.0 / kPi);
      p.deviation_um.push_back(std::hypot(x, y) - R);
    }
  }
  return d;
}

TEST(Circular, AgreesWithAGeometricCircleFit) {
  const double R = 50000.0;
  const CircularData d = Machine(false);
  const CircularResult r = ValueOf(EvaluateCircular(d));
  const std::vector<Point> cw = Points(d.cw, R), ccw = Points(d.ccw, R);
  std::vector<Point> both = cw;
  both.insert(both.end(), ccw.begin(), ccw.end());
  const Circle c_cw = FitCircle(cw), c_ccw = FitCircle(ccw), c_both = FitCircle(both);
  // Linearization error e²/(2R) < 0.002 µm for e ≈ 14 µm.
  const double tol = 0.01;
  EXPECT_NEAR(r.G_cw_um, Spread(cw, c_cw), tol);
  EXPECT_NEAR(r.G_ccw_um, Spread(ccw, c_ccw), tol);
  EXPECT_NEAR(r.G_b_um, Spread(both, c_both), tol);
  EXPECT_NEAR(r.centre_offset_x_um, c_both.cx, tol);
  EXPECT_NEAR(r.centre_offset_y_um, c_both.cy, tol);
  EXPECT_NEAR(r.mean_radius_dev_um, c_both.r - R, tol);
  // And the centre the data were made with, to within what the lobes and spikes pull it.
  EXPECT_NEAR(r.centre_offset_x_um, 12.0, 0.5);
  EXPECT_NEAR(r.centre_offset_y_um, -7.0, 0.5);
  // F needs no fit: the distance of every point from the nominal centre, minus R.
  double f_lo = 1e300, f_hi = -1e300;
  for (const Point& p : both) {
    f_lo = std::min(f_lo, std::hypot(p.x, p.y) - R),
    f_hi = std::max(f_hi, std::hypot(p.x, p.y) - R);
  }
  EXPECT_NEAR(r.F_max_um, f_hi, 1e-6);
  EXPECT_NEAR(r.F_min_um, f_lo, 1e-6);
  EXPECT_GT(r.G_b_um, r.G_cw_um);
}

TEST(Circular, HysteresisAgreesWithRadialDistancesAtTheSameAngles) {
  const double R = 50000.0;
  const CircularData d = Machine(true);
  const CircularResult r = ValueOf(EvaluateCircular(d));
  const std::vector<Point> cw = Points(d.cw, R), ccw = Points(d.ccw, R);
  std::vector<Point> both = cw;
  both.insert(both.end(), ccw.begin(), ccw.end());
  const Circle c = FitCircle(both);
  // The two paths' points were made at the same nominal angles and are listed in the same
  // order, so the k-th points of both lie on one ray (within µrad) from the common centre.
  ASSERT_EQ(cw.size(), ccw.size());
  double h = 0;
  for (std::size_t k = 0; k < cw.size(); ++k) {
    h = std::max(h, std::fabs(std::hypot(cw[k].x - c.cx, cw[k].y - c.cy) -
                              std::hypot(ccw[k].x - c.cx, ccw[k].y - c.cy)));
  }
  EXPECT_NEAR(r.H_um, h, 0.01);
  // Largest at a reversal (5 − 3 + 3 µm of radius difference, plus noise).
  EXPECT_GT(r.H_um, 4.5);
}

TEST(Circular, HysteresisInterpolatesBetweenDifferentAngles) {
  // CCW read half-way between the CW angles; both the same smooth 3 cos 2θ, CCW 2.5 µm larger:
  // H is 2.5 within the linear interpolation's error (Δθ²/8 · 12 µm = 0.0005 µm at 1°).
  CircularData d;
  for (int k = 0; k < 360; ++k) {
    d.cw.angle_deg.push_back(k);
    d.cw.deviation_um.push_back(3 * std::cos(2 * Rad(k)));
    d.ccw.angle_deg.push_back(k + 0.5);
    d.ccw.deviation_um.push_back(2.5 + 3 * std::cos(2 * Rad(k + 0.5)));
  }
  const CircularResult r = ValueOf(EvaluateCircular(d));
  EXPECT_NEAR(r.H_um, 2.5, 0.001);
  EXPECT_NEAR(r.G_cw_um, 6.0, 0.001);
}

TEST(Circular, OneDirectionOnly) {
  CircularData d = HandCase();
  d.ccw = {};
  const CircularResult r = ValueOf(EvaluateCircular(d));
  EXPECT_TRUE(r.has_cw);
  EXPECT_FALSE(r.has_ccw);
  EXPECT_NEAR(r.G_cw_um, 8.0, 1e-9);
  EXPECT_NEAR(r.centre_offset_x_um, 3.0, 1e-9);
  EXPECT_NEAR(r.centre_offset_y_um, 2.0, 1e-9);
}

TEST(Circular, WideGapIsReported) {
  CircularData d = HandCase();
  d.ccw.angle_deg = {0, 10, 20, 30};
  d.ccw.deviation_um = {1, 2, 3, 4};
  const CircularResult r = ValueOf(EvaluateCircular(d));
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("counter-clockwise (ccw) path has no reading between 30° and 0°"),
            std::string::npos)
      << r.warnings[0];
}

TEST(Circular, TooFewAnglesAreRefused) {
  CircularData d = HandCase();
  d.source = "c.csv";
  d.ccw.angle_deg = {0, 360, 90};
  d.ccw.deviation_um = {1, 1, 2};
  ExpectFailure(EvaluateCircular(d), Error::kInputInvalid,
                {"c.csv: the counter-clockwise (ccw) path has readings at 2 distinct angle(s); "
                 "at least 3 are needed"});
  ExpectFailure(EvaluateCircular(CircularData{}), Error::kInputInvalid, {"no readings"});
  CircularData uneven = HandCase();
  uneven.cw.deviation_um.pop_back();
  ExpectFailure(EvaluateCircular(uneven), Error::kInvalidArgument,
                {"as many angles as deviations are needed"});
}

// --- The reader. ---

TEST(CircularCsv, ReadsDeviationsSemicolonsAndDecimalCommas) {
  const CircularData d = ValueOf(ReadCircularCsv(
      Csv("# machine: MILL-7\ndirection;angle_deg;deviation_um\nCW;0;1,5\nccw;90;-2,25\n", "s.csv"),
      0.0));
  EXPECT_EQ(d.source, "s.csv");
  ASSERT_EQ(d.cw.angle_deg.size(), 1u);
  ASSERT_EQ(d.ccw.angle_deg.size(), 1u);
  EXPECT_DOUBLE_EQ(d.cw.deviation_um[0], 1.5);
  EXPECT_DOUBLE_EQ(d.ccw.angle_deg[0], 90.0);
  EXPECT_DOUBLE_EQ(d.ccw.deviation_um[0], -2.25);
}

TEST(CircularCsv, ReadsRadiiAgainstTheNominalRadius) {
  const CircularData d = ValueOf(ReadCircularCsv(
      Csv("direction,angle_deg,radius_mm\ncw,0,100.0042\nccw,0,99.9975\n", "r.csv"), 100.0));
  EXPECT_NEAR(d.cw.deviation_um[0], 4.2, 1e-6);
  EXPECT_NEAR(d.ccw.deviation_um[0], -2.5, 1e-6);
  EXPECT_DOUBLE_EQ(d.nominal_radius_mm, 100.0);
}

TEST(CircularCsv, MalformedInputsNameFileLineAndColumn) {
  ExpectFailure(ReadCircularCsv(Csv("# note\nangle_deg,deviation_um\n0,1\n", "a.csv"), 0.0),
                Error::kInputInvalid, {"a.csv:2:", "\"direction\""});
  ExpectFailure(ReadCircularCsv(Csv("direction,deviation_um\ncw,1\n", "b.csv"), 0.0),
                Error::kInputInvalid, {"b.csv:1:", "\"angle_deg\""});
  ExpectFailure(ReadCircularCsv(Csv("direction,angle_deg,dev\ncw,0,1\n", "c.csv"), 0.0),
                Error::kInputInvalid,
                {"c.csv:1: missing column \"deviation_um\" (or radius_mm with --radius)"});
  ExpectFailure(ReadCircularCsv(Csv("direction,angle_deg,radius_mm\ncw,0,1\n", "d.csv"), 0.0),
                Error::kInputInvalid, {"d.csv:1:", "give the nominal radius with --radius"});
  ExpectFailure(ReadCircularCsv(Csv("direction,angle_deg,deviation_um\ncw,0,1\n", "e.csv"), 50.0),
                Error::kInputInvalid, {"e.csv:1: missing column \"radius_mm\""});
  ExpectFailure(
      ReadCircularCsv(Csv("direction,angle_deg,deviation_um\ncw,0,1\nup,90,2\n", "f.csv"), 0.0),
      Error::kInputInvalid, {"f.csv:3: column \"direction\": \"up\" is neither cw nor ccw"});
  ExpectFailure(
      ReadCircularCsv(Csv("direction,angle_deg,deviation_um\ncw,0,1\ncw,x,2\n", "g.csv"), 0.0),
      Error::kInputInvalid, {"g.csv:3:", "\"angle_deg\"", "\"x\""});
  ExpectFailure(ReadCircularCsv(Csv("direction,angle_deg,deviation_um\n", "h.csv"), 0.0),
                Error::kInputInvalid, {"h.csv:1: no data rows"});
}

}  // namespace
}  // namespace volcomp::metrology
