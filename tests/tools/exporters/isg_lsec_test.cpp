// ISG leadscrew error compensation lists of a rotary axis: the units of P-COMP-00019/23/24 for
// rotary axes (0.0001°) worked by hand; 0.0001° = 0.36″.
#include "volcomp/exporters/isg_lsec.hpp"

#include <gtest/gtest.h>

#include "expected_value.hpp"

namespace volcomp::exporters {
namespace {

TEST(exporters_isg_lsec, RotaryAxisIn0001Degrees) {
  model::PositioningData d;
  d.rotary = true;
  d.position = {0, 90, 180};
  d.dev_forward = {0, 3.6, -7.2};  // arcsec
  d.dev_reverse = {0.36, 0, 1.8};
  const IsgLsec list = testing::ValueOf(BuildIsgLsec(d, {}));
  ASSERT_EQ(list.rows.size(), 3u);
  EXPECT_TRUE(list.bilateral);
  EXPECT_EQ(list.rows[1].setpoint, 900000);  // 90° / 0.0001°
  EXPECT_EQ(list.rows[2].setpoint, 1800000);
  EXPECT_EQ(list.rows[1].pos, 10);  // 3.6″ / 0.36″
  EXPECT_EQ(list.rows[2].pos, -20);
  EXPECT_EQ(list.rows[0].neg, 1);
  EXPECT_EQ(list.rows[2].neg, 5);
}

TEST(exporters_isg_lsec, NeedsTwoPositionsAndRespectsMaxPoints) {
  model::PositioningData d;
  d.position = {0};
  d.dev_forward = {1};
  const auto one = BuildIsgLsec(d, {});
  ASSERT_FALSE(one.ok());
  EXPECT_EQ(one.error().message, "a compensation list needs at least 2 positions, the test has 1");
  d.position = {0, 1};
  d.dev_forward = {1, 2};
  IsgLsecOptions o;
  o.max_points = 2;
  EXPECT_FALSE(BuildIsgLsec(d, o).ok());
  o.max_points = 3;
  EXPECT_TRUE(BuildIsgLsec(d, o).ok());
}

}  // namespace
}  // namespace volcomp::exporters
