// Arc and line geometry (PathSegment) against hand-worked cases: the RS274/ISO 6983 plane and
// direction conventions, centre and radius forms, full circles, helices, crossings, speed limits.
#include "volcomp/sim/path.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace volcomp::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

PathRequest Arc(bool cw, int plane, Point3 end, Point3 ijk) {
  PathRequest r;
  r.arc = true;
  r.clockwise = cw;
  r.plane = plane;
  r.end_mm = end;
  r.centre_offset_mm = ijk;
  return r;
}

PathRequest RadiusArc(bool cw, Point3 end, double radius) {
  PathRequest r = Arc(cw, 17, end, {0, 0, 0});
  r.radius_form = true;
  r.radius_mm = radius;
  return r;
}

void ExpectNear(const Point3& p, double x, double y, double z) {
  EXPECT_NEAR(p[0], x, 1e-9);
  EXPECT_NEAR(p[1], y, 1e-9);
  EXPECT_NEAR(p[2], z, 1e-9);
}

TEST(SimPath, G3QuarterInXyTurnsCounterClockwiseSeenFromPlusZ) {
  // From (10, 0) about the origin to (0, 10): a quarter turn counter-clockwise.
  auto s = PathSegment::Resolve({10, 0, 0}, Arc(false, 17, {0, 10, 0}, {-10, 0, 0}));
  ASSERT_TRUE(s.ok());
  EXPECT_NEAR(s->length_mm(), 10 * kPi / 2, 1e-9);
  const double h = 10 / std::sqrt(2.0);
  ExpectNear(s->PointAt(s->length_mm() / 2), h, h, 0);
  ExpectNear(s->end_mm(), 0, 10, 0);
  ExpectNear(s->TangentAt(0), 0, 1, 0);  // leaves (10, 0) towards +Y
}

TEST(SimPath, G2ToTheSameEndTakesTheOtherThreeQuarters) {
  auto s = PathSegment::Resolve({10, 0, 0}, Arc(true, 17, {0, 10, 0}, {-10, 0, 0}));
  ASSERT_TRUE(s.ok());
  EXPECT_NEAR(s->length_mm(), 10 * 3 * kPi / 2, 1e-9);
  const double h = 10 / std::sqrt(2.0);
  ExpectNear(s->PointAt(s->length_mm() / 2), -h, -h, 0);
  ExpectNear(s->TangentAt(0), 0, -1, 0);
}

TEST(SimPath, G18IsTheZxPlaneSeenFromPlusY) {
  // Counter-clockwise about +Y turns +X towards -Z: from X10 to Z10 about the origin is 270 deg.
  auto ccw = PathSegment::Resolve({10, 0, 0}, Arc(false, 18, {0, 0, 10}, {-10, 0, 0}));
  ASSERT_TRUE(ccw.ok());
  EXPECT_NEAR(ccw->length_mm(), 10 * 3 * kPi / 2, 1e-9);
  ExpectNear(ccw->PointAt(10 * kPi / 2), 0, 0, -10);
  auto cw = PathSegment::Resolve({10, 0, 0}, Arc(true, 18, {0, 0, 10}, {-10, 0, 0}));
  ASSERT_TRUE(cw.ok());
  EXPECT_NEAR(cw->length_mm(), 10 * kPi / 2, 1e-9);
}

TEST(SimPath, G19IsTheYzPlaneSeenFromPlusX) {
  // Counter-clockwise about +X turns +Y towards +Z.
  auto s = PathSegment::Resolve({0, 10, 0}, Arc(false, 19, {0, 0, 10}, {0, -10, 0}));
  ASSERT_TRUE(s.ok());
  EXPECT_NEAR(s->length_mm(), 10 * kPi / 2, 1e-9);
}

TEST(SimPath, EndEqualToStartIsAFullCircle) {
  auto s = PathSegment::Resolve({5, 0, 0}, Arc(true, 17, {5, 0, 0}, {-5, 0, 0}));
  ASSERT_TRUE(s.ok());
  EXPECT_NEAR(s->length_mm(), 2 * kPi * 5, 1e-9);
  ExpectNear(s->PointAt(s->length_mm() / 4), 0, -5, 0);  // clockwise: down first
}

TEST(SimPath, RadiusFormPicksTheShortOrTheLongArc) {
  // (0,0) to (10,0), R 5: a half circle; G2 with R > 0 goes over the top (centre to the right
  // of the chord when clockwise), R = -7 the longer arc.
  auto half = PathSegment::Resolve({0, 0, 0}, RadiusArc(true, {10, 0, 0}, 5));
  ASSERT_TRUE(half.ok());
  EXPECT_NEAR(half->length_mm(), 5 * kPi, 1e-6);
  ExpectNear(half->PointAt(half->length_mm() / 2), 5, 5, 0);
  auto shorter = PathSegment::Resolve({0, 0, 0}, RadiusArc(false, {10, 0, 0}, 7));
  auto longer = PathSegment::Resolve({0, 0, 0}, RadiusArc(false, {10, 0, 0}, -7));
  ASSERT_TRUE(shorter.ok() && longer.ok());
  const double half_angle = std::asin(5.0 / 7.0);
  EXPECT_NEAR(shorter->length_mm(), 7 * 2 * half_angle, 1e-9);
  EXPECT_NEAR(longer->length_mm(), 7 * (2 * kPi - 2 * half_angle), 1e-9);
  // G3 R > 0 from (0,0) to (10,0) goes below the chord.
  EXPECT_LT(shorter->PointAt(shorter->length_mm() / 2)[1], 0);
}

TEST(SimPath, AHelixMovesTheNormalAxisInProportion) {
  auto s = PathSegment::Resolve({10, 0, 0}, Arc(false, 17, {10, 0, 3}, {-10, 0, 0}));
  ASSERT_TRUE(s.ok());
  EXPECT_NEAR(s->length_mm(), std::hypot(2 * kPi * 10, 3), 1e-9);
  EXPECT_NEAR(s->PointAt(s->length_mm() / 2)[2], 1.5, 1e-9);
  ExpectNear(s->PointAt(s->length_mm() / 2), -10, 0, 1.5);
}

TEST(SimPath, RefusesInconsistentArcs) {
  auto mismatch = PathSegment::Resolve({10, 0, 0}, Arc(false, 17, {0, 10.05, 0}, {-10, 0, 0}));
  ASSERT_FALSE(mismatch.ok());
  EXPECT_EQ(mismatch.error().code, Error::kInputInvalid);
  EXPECT_NE(mismatch.error().message.find("10.0500 mm from the centre"), std::string::npos)
      << mismatch.error().message;
  auto short_r = PathSegment::Resolve({0, 0, 0}, RadiusArc(true, {10, 0, 0}, 4));
  ASSERT_FALSE(short_r.ok());
  EXPECT_NE(short_r.error().message.find("shorter than half the chord"), std::string::npos);
  auto full_r = PathSegment::Resolve({0, 0, 0}, RadiusArc(true, {0, 0, 0}, 4));
  ASSERT_FALSE(full_r.ok());
  EXPECT_NE(full_r.error().message.find("full circle"), std::string::npos);
  EXPECT_FALSE(PathSegment::Resolve({0, 0, 0}, Arc(true, 17, {0, 0, 0}, {0, 0, 0})).ok());
}

TEST(SimPath, CrossingsFollowTheCircleThroughItsExtremes) {
  // Full circle of radius 1 about the origin from (1, 0), counter-clockwise. X goes down to -1
  // and back; the crossings of x = 0.5 downward and upward, by hand: at 60 and 300 degrees.
  auto s = PathSegment::Resolve({1, 0, 0}, Arc(false, 17, {1, 0, 0}, {-1, 0, 0}));
  ASSERT_TRUE(s.ok());
  EXPECT_NEAR(s->NextCrossing(0, 0, 0.5, -1), kPi / 3, 1e-9);
  EXPECT_NEAR(s->NextCrossing(0, 0, 0.5, 1), 5 * kPi / 3, 1e-9);
  EXPECT_NEAR(s->NextCrossing(0, kPi / 3, 0.5, -1), -1, 0);  // once downward only
  // Y rises to 1 at 90 degrees, falls through 0.5 at 150 degrees.
  EXPECT_NEAR(s->NextCrossing(1, 0, 0.5, 1), kPi / 6, 1e-9);
  EXPECT_NEAR(s->NextCrossing(1, kPi / 6, 0.5, -1), 5 * kPi / 6, 1e-9);
  EXPECT_LT(s->NextCrossing(1, 0, 1.5, 1), 0);  // outside the circle
}

TEST(SimPath, DistanceToTheArcIsRadialOnItAndToTheNearerEndOffIt) {
  auto s = PathSegment::Resolve({10, 0, 0}, Arc(false, 17, {0, 10, 0}, {-10, 0, 0}));
  ASSERT_TRUE(s.ok());
  EXPECT_NEAR(s->DistanceTo({0, 0, 0}), 10, 1e-9);
  EXPECT_NEAR(s->DistanceTo({3 * std::sqrt(8.0), 3 * std::sqrt(8.0), 0}), 2, 1e-9);  // r = 12
  EXPECT_NEAR(s->DistanceTo({6, 8, 1}), 1, 1e-9);                                    // 1 above
  EXPECT_NEAR(s->DistanceTo({-10, 0, 0}), std::sqrt(200.0), 1e-9);  // off the arc: the end
  const PathSegment line = PathSegment::Line({0, 0, 0}, {10, 0, 0});
  EXPECT_NEAR(line.DistanceTo({1, 5, 0}), 5, 1e-12);
  EXPECT_NEAR(line.DistanceTo({13, 4, 0}), 5, 1e-12);
}

TEST(SimPath, SpeedLimitKeepsTheCentripetalAccelerationAndTheAxisRates) {
  auto s = PathSegment::Resolve({10, 0, 0}, Arc(false, 17, {10, 0, 0}, {-10, 0, 0}));
  ASSERT_TRUE(s.ok());
  EXPECT_NEAR(s->SpeedLimit({1000, 1000, 1000}, 1000), 100, 1e-9);  // sqrt(1000 * 10)
  EXPECT_NEAR(s->SpeedLimit({50, 1000, 1000}, 1000), 50, 1e-9);
  const PathSegment line = PathSegment::Line({0, 0, 0}, {3, 4, 0});
  EXPECT_NEAR(line.SpeedLimit({30, 1000, 1000}, 1), 50, 1e-9);  // X moves 3/5 of the path
}

}  // namespace
}  // namespace volcomp::sim
