// RepRapFirmware M556 / M425 against lines written by hand from RRF's G-code handling
// (GCodes2.cpp case 556: tangent = X|Y|Z / S for XY, YZ, ZX; Platform.cpp M425: non-negative mm per
// axis letter) and the hand-worked inputs of hobby_test_data.hpp. RRF's tangents are checked
// against the Klipper/Marlin factors of the same machine: its AxisTransform adds what theirs
// subtracts, so each tangent is minus the factor.
#include <gtest/gtest.h>

#include <string>

#include "comment_lines.hpp"
#include "hobby_test_data.hpp"
#include "volcomp/exporters/reprap_gcode.hpp"

namespace volcomp::exporters {
namespace {

using test_data::Backlash;
using test_data::Square;
using testing::ExpectFailure;
using testing::ValueOf;
using testing::WithoutCommentLines;

// Over S = 100 mm: XY = tan(−500 µrad)·100 = −0.0500000, YZ = tan(−300 µrad)/cos(200 µrad)·100 =
// −0.0300000, ZX = −tan(200 µrad)·100 = −0.0200000 mm; backlash 0.0194 mm.
TEST(ReprapGcode, SkewAndBacklashAsWorkedByHand) {
  const ReprapGcode r =
      ValueOf(BuildReprapGcode(Square(), {Backlash('X'), Backlash('U')}, 100, false));
  EXPECT_EQ(WithoutCommentLines(r.text, ";"),
            "M556 S100.000 X-0.0500000 Y-0.0300000 Z-0.0200000\n"
            "M425 X0.0194 U0.0194\n");
  EXPECT_NE(r.text.find("XY = tan C0Y (M556 X), YZ = tan A0Z / cos B0Z (M556 Y), ZX = -tan B0Z"),
            std::string::npos);
}

// What RRF does with the line: tangent = deviation / S. Over S = 250 mm the same machine gives
// X = −0.125 mm, and −0.125 / 250 = −5.0e-4 = minus Marlin's factor 5.0e-4.
TEST(ReprapGcode, TangentIsDeviationOverSAndMinusTheFactor) {
  HobbySquareness xy;
  xy.xy = PlaneSquareness{-500, "--squareness-xy-urad"};
  const ReprapGcode r = ValueOf(BuildReprapGcode(xy, {}, 250, false));
  EXPECT_EQ(WithoutCommentLines(r.text, ";"), "M556 S250.000 X-0.1250000\n");
  EXPECT_NEAR(-0.1250000 / 250, -*KlipperMarlinFactors(xy, false).xy, 1e-9);
  EXPECT_NE(r.text.find("; XZ, YZ: no squareness given, not written"), std::string::npos);
  const ReprapGcode n = ValueOf(BuildReprapGcode(xy, {}, 250, true));
  EXPECT_EQ(WithoutCommentLines(n.text, ";"), "M556 S250.000 X0.1250000\n");
}

TEST(ReprapGcode, RefusesWhatRrfCannotTake) {
  ExpectFailure(BuildReprapGcode({}, {}, 100, false), Error::kInvalidArgument, {"neither"});
  ExpectFailure(BuildReprapGcode(Square(), {}, 0, false), Error::kInvalidArgument,
                {"M556 S0.000", "> 0 mm"});
  ExpectFailure(BuildReprapGcode({}, {Backlash('A', true)}, 100, false), Error::kInvalidArgument,
                {"A is a rotary axis"});
  ExpectFailure(BuildReprapGcode({}, {Backlash('Y', false, true)}, 100, false),
                Error::kInvalidArgument, {"Y backlash -19.400 um", ">= 0"});
}

}  // namespace
}  // namespace volcomp::exporters
