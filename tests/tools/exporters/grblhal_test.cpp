// grblHAL backlash settings against lines written by hand from grblHAL's settings table
// (settings.h: Setting_AxisBacklash = 100 + 6 × 10 = 160, plus the axis index X 0 … V 7; mm, deg
// on a rotary axis) and the hand-worked test of hobby_test_data.hpp.
#include <gtest/gtest.h>

#include <string>

#include "comment_lines.hpp"
#include "hobby_test_data.hpp"
#include "volcomp/exporters/grblhal_settings.hpp"

namespace volcomp::exporters {
namespace {

using test_data::Backlash;
using testing::ExpectFailure;
using testing::ValueOf;
using testing::WithoutCommentLines;

// X 19.4 µm = 0.01940 mm ($160), Z ($162), A rotary: 19.4 arcsec = 0.005389 deg ($163), V ($167).
TEST(GrblhalSettings, SettingNumbersAndValuesAsWorkedByHand) {
  const GrblhalSettings g = ValueOf(
      BuildGrblhalSettings({Backlash('X'), Backlash('Z'), Backlash('A', true), Backlash('V')}));
  EXPECT_EQ(WithoutCommentLines(g.text, ";"),
            "$160=0.01940\n"
            "$162=0.01940\n"
            "$163=0.00539\n"
            "$167=0.01940\n");
  ASSERT_EQ(g.settings.size(), 4u);
  EXPECT_EQ(g.settings[2].number, 163);
  EXPECT_NEAR(g.settings[2].value, 19.4 / 3600, 1e-12);
  EXPECT_NE(g.text.find("ENABLE_BACKLASH_COMPENSATION"), std::string::npos);
}

TEST(GrblhalSettings, RefusesWhatGrblhalCannotTake) {
  ExpectFailure(BuildGrblhalSettings({}), Error::kInvalidArgument, {"no axis"});
  ExpectFailure(BuildGrblhalSettings({Backlash('W')}), Error::kInvalidArgument,
                {"axis W", "grblHAL takes the backlash of XYZABCUV"});
  ExpectFailure(BuildGrblhalSettings({Backlash('X', false, true)}), Error::kInvalidArgument,
                {"X backlash -19.400 um", "grblHAL takes a backlash >= 0"});
}

}  // namespace
}  // namespace volcomp::exporters
