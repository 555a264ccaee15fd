// Marlin M852 / M425 against lines written by hand from Marlin's G-code (M852.cpp: I J K skew
// factors within SKEW_FACTOR_MIN..MAX = −1..1; M425.cpp: F, X Y Z in mm) and the hand-worked
// inputs of hobby_test_data.hpp; the backlash's figures against ISO 230-2's reversal.
#include <gtest/gtest.h>

#include <string>

#include "comment_lines.hpp"
#include "hobby_test_data.hpp"
#include "volcomp/exporters/marlin_gcode.hpp"

namespace volcomp::exporters {
namespace {

using test_data::Backlash;
using test_data::Square;
using testing::ExpectFailure;
using testing::ValueOf;
using testing::WithoutCommentLines;

TEST(HobbyBacklash, LostMotionIsMinusTheMeanReversal) {
  const AxisBacklash b = Backlash('X');
  EXPECT_DOUBLE_EQ(b.lost_motion_um, 19.4);
  EXPECT_DOUBLE_EQ(b.reversal_mean_um, -19.4);
  EXPECT_DOUBLE_EQ(b.reversal_max_um, 21.0);
  EXPECT_NEAR(b.spread_um, 1.6, 1e-12);
  EXPECT_EQ(b.targets, 5);
  EXPECT_NEAR(Backlash('X', false, true).lost_motion_um, -19.4, 1e-12);
}

TEST(HobbyBacklash, OneDirectionHasNoReversal) {
  model::PositioningData d = test_data::LostMotionTest();
  d.dev_reverse.clear();
  ExpectFailure(BacklashFromTest('Y', "y.csv", d, false), Error::kInvalidArgument,
                {"y.csv", "one direction", "both directions"});
}

// xy = −tan(−500 µrad) = 0.000500000, xz = tan(200 µrad) = 0.000200000,
// yz = −tan(−300 µrad)/cos(200 µrad) = 0.000300000; backlash 19.4 µm = 0.0194 mm.
TEST(MarlinGcode, SkewAndBacklashAsWorkedByHand) {
  const MarlinGcode m = ValueOf(BuildMarlinGcode(Square(), {Backlash('X'), Backlash('Z')}, false));
  EXPECT_EQ(WithoutCommentLines(m.text, ";"),
            "G21 ; millimetres: M852 and M425 read their values as lengths (G20 would scale them)\n"
            "M852 I0.000500000 J0.000200000 K0.000300000\n"
            "M425 F1 X0.0194 Z0.0194\n"
            "M500 ; store the settings (EEPROM_SETTINGS)\n");
  EXPECT_NE(m.text.find("I = -tan C0Y, J = tan B0Z, K = -tan A0Z / cos B0Z"), std::string::npos);
  EXPECT_NE(m.text.find("; backlash X: 19.40 um"), std::string::npos) << m.text;
}

TEST(MarlinGcode, OnlyWhatWasGiven) {
  HobbySquareness xy;
  xy.xy = PlaneSquareness{-500, "--squareness-xy-urad"};
  const MarlinGcode m = ValueOf(BuildMarlinGcode(xy, {}, true));
  EXPECT_EQ(WithoutCommentLines(m.text, ";"),
            "G21 ; millimetres: M852 and M425 read their values as lengths (G20 would scale them)\n"
            "M852 I-0.000500000\n"
            "M500 ; store the settings (EEPROM_SETTINGS)\n");
  EXPECT_NE(m.text.find("; XZ, YZ: no squareness given, not written"), std::string::npos);
  EXPECT_NE(m.text.find("NEGATED"), std::string::npos);
}

TEST(MarlinGcode, RefusesWhatMarlinCannotTake) {
  ExpectFailure(BuildMarlinGcode({}, {}, false), Error::kInvalidArgument, {"neither"});
  HobbySquareness steep;  // tan(0.8 rad) = 1.0296 > SKEW_FACTOR_MAX
  steep.xy = PlaneSquareness{-800000, "--squareness-xy-urad"};
  ExpectFailure(BuildMarlinGcode(steep, {}, false), Error::kInvalidArgument,
                {"I (XY) = 1.029639", "SKEW_FACTOR_MIN..MAX = -1..1"});
  ExpectFailure(BuildMarlinGcode({}, {Backlash('A')}, false), Error::kInvalidArgument,
                {"axis A", "Marlin's M425 takes the backlash of XYZ"});
  ExpectFailure(BuildMarlinGcode({}, {Backlash('X', false, true)}, false), Error::kInvalidArgument,
                {"X backlash -19.400 um", "B = +19.400 um", ">= 0", "--negate-tests"});
}

}  // namespace
}  // namespace volcomp::exporters
