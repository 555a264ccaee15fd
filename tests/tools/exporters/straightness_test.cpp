// The reference line of a straightness test (straightness.hpp), worked by hand: forward readings
// 2 + 0.01 x + bow (bow 0, 3, 4, 3, 0 µm at 0..200 mm), reverse 2 µm below. Both directions
// pooled: 1 + 0.01 x + bow, least-squares line 3 + 0.01 x (the bow's own line is flat at its mean
// 2): forward −1, 2, 3, 2, −1 and reverse −3, 0, 1, 0, −3; zeroed at 100 mm (forward 3 there):
// forward −4, −1, 0, −1, −4 and reverse −6, −3, −2, −3, −6.
#include "volcomp/exporters/straightness.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace volcomp::exporters {
namespace {

ErrorTable Bowed() {
  ErrorTable t;
  t.position = {0, 50, 100, 150, 200};
  const double bow[] = {0, 3, 4, 3, 0};
  for (int i = 0; i < 5; ++i) {
    t.forward_um.push_back(2 + 0.01 * t.position[i] + bow[i]);
    t.reverse_um.push_back(t.forward_um.back() - 2);
  }
  t.spacing = 50;
  return t;
}

void ExpectValues(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-9) << i;
}

TEST(Straightness, LeastSquaresLineOfBothDirections) {
  ErrorTable t = Bowed();
  const auto ref = RemoveReferenceLine(&t, StraightnessLine::kLeastSquares);
  ASSERT_TRUE(ref.ok());
  EXPECT_NEAR(ref->slope_um_per_m, 10.0, 1e-9);
  EXPECT_NEAR(ref->offset_um, 3.0, 1e-9);
  ExpectValues(t.forward_um, {-1, 2, 3, 2, -1});
  ExpectValues(t.reverse_um, {-3, 0, 1, 0, -3});
}

// The same test on an inch machine (positions 0, 2, ... 8 in): the slope is still 10 µm per metre
// (0.01 µm/mm × 25.4 mm/in = 0.254 µm per inch of travel); one direction, so the residuals are
// the bow less its mean 2 µm.
TEST(Straightness, InchPositionsGiveTheSlopePerMetre) {
  ErrorTable t;
  t.unit = LengthUnit::kInch;
  const double bow[] = {0, 3, 4, 3, 0};
  for (int i = 0; i < 5; ++i) {
    t.position.push_back(2.0 * i);
    t.forward_um.push_back(2 + 0.254 * t.position[i] + bow[i]);
  }
  const auto ref = RemoveReferenceLine(&t, StraightnessLine::kLeastSquares);
  ASSERT_TRUE(ref.ok());
  EXPECT_NEAR(ref->slope_um_per_m, 10.0, 1e-9);
  ExpectValues(t.forward_um, {-2, 1, 2, 1, -2});
}

TEST(Straightness, ZeroedAgainAtTheReference) {
  ErrorTable t = Bowed();
  t.zero_at = 100.0;
  ASSERT_TRUE(RemoveReferenceLine(&t, StraightnessLine::kLeastSquares).ok());
  ExpectValues(t.forward_um, {-4, -1, 0, -1, -4});
  ExpectValues(t.reverse_um, {-6, -3, -2, -3, -6});
}

TEST(Straightness, EndPointsAndNone) {
  ErrorTable t = Bowed();
  // Pooled ends 1 (at 0) and 3 (at 200): line 1 + 0.01 x; forward keeps the bow + 1.
  ASSERT_TRUE(RemoveReferenceLine(&t, StraightnessLine::kEndPoints).ok());
  ExpectValues(t.forward_um, {1, 4, 5, 4, 1});
  ErrorTable u = Bowed();
  const auto none = RemoveReferenceLine(&u, StraightnessLine::kNone);
  ASSERT_TRUE(none.ok());
  EXPECT_EQ(none->slope_um_per_m, 0.0);
  ExpectValues(u.forward_um, Bowed().forward_um);
}

TEST(Straightness, Refusals) {
  ErrorTable t = Bowed();
  t.rotary = true;
  EXPECT_FALSE(RemoveReferenceLine(&t, StraightnessLine::kLeastSquares).ok());
  ErrorTable one;
  one.position = {0};
  one.forward_um = {1};
  EXPECT_FALSE(RemoveReferenceLine(&one, StraightnessLine::kLeastSquares).ok());
}

}  // namespace
}  // namespace volcomp::exporters
