// Klipper skew correction against lines written by hand from Klipper's documented syntax
// (docs/Skew_Correction.md: SET_SKEW XY=AC,BD,AD, SKEW_PROFILE; configfile.py: the SAVE_CONFIG
// block) and numbers worked by hand; SET_SKEW's lengths go back through Klipper's own formula
// (calc_skew_factor, written out below from skew_correction.py's law of cosines) to the factor.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "comment_lines.hpp"
#include "expected_value.hpp"
#include "volcomp/exporters/klipper_skew.hpp"

namespace volcomp::exporters {
namespace {

using testing::ExpectFailure;
using testing::ValueOf;
using testing::WithoutCommentLines;

// Klipper's calc_skew_factor(AC, BD, AD): the parallelogram's other side from AC² + BD² =
// 2(AB² + AD²), the angle at A from the law of cosines, factor = tan(π/2 − α).
double KlipperFactor(double ac, double bd, double ad) {
  const double side = std::sqrt(2 * ac * ac + 2 * bd * bd - 4 * ad * ad) / 2;
  const double alpha = std::acos((ac * ac - side * side - ad * ad) / (2 * side * ad));
  return std::tan(std::acos(0.0) - alpha);
}

HobbySquareness Square(double c0y, double b0z, double a0z) {
  HobbySquareness s;
  s.xy = PlaneSquareness{c0y, "--squareness-xy-urad"};
  s.xz = PlaneSquareness{b0z, "--squareness-xz-urad"};
  s.yz = PlaneSquareness{a0z, "--squareness-yz-urad"};
  return s;
}

// C0Y = −500, B0Z = 200, A0Z = −300 µrad. Factors: xy = −tan C0Y = 5.0000004e-4, xz = tan B0Z =
// 2.0000000e-4, yz = −tan A0Z / cos B0Z = 3.0000002e-4 (9 decimals: 0.000500000 ...).
// Lengths of the 100 mm square, α = π/2 − atan f, cos α = sin(atan f) ≈ f − f³/2:
// AC = 100·√(2 + 2 cos α) = 141.421356·(1 + f/2 − f²/8), BD = 141.421356·(1 − f/2 − f²/8):
//   f = 5e-4: 141.421356 ± 0.035355 − 0.0000044 → 141.456707, 141.385996;
//   f = 2e-4: ± 0.014142 − 0.0000007 → 141.435498, 141.407213;
//   f = 3e-4: ± 0.021213 − 0.0000016 → 141.442568, 141.400141.
TEST(KlipperSkew, ProfileAndSetSkewAsWorkedByHand) {
  const KlipperSkew k = ValueOf(BuildKlipperSkew(Square(-500, 200, -300), {}));
  EXPECT_EQ(WithoutCommentLines(k.text, "# "),
            "#*# <---------------------- SAVE_CONFIG ---------------------->\n"
            "#*# DO NOT EDIT THIS BLOCK OR BELOW. The contents are auto-generated.\n"
            "#*#\n"
            "#*# [skew_correction volcomp]\n"
            "#*# xy_skew = 0.000500000\n"
            "#*# xz_skew = 0.000200000\n"
            "#*# yz_skew = 0.000300000\n");
  EXPECT_NE(k.text.find("#   SET_SKEW XY=141.456707,141.385996,100.000000 "
                        "XZ=141.435498,141.407213,100.000000 YZ=141.442568,141.400141,100.000000\n"
                        "#   SKEW_PROFILE SAVE=volcomp\n#   SAVE_CONFIG\n"),
            std::string::npos)
      << k.text;
  EXPECT_NE(k.text.find("xy = -tan C0Y, xz = tan B0Z, yz = -tan A0Z / cos B0Z"), std::string::npos);
}

// Round trip: Klipper's formula on the lengths written gives the factor in the profile.
TEST(KlipperSkew, CalcSkewFactorOfTheLengthsIsTheFactor) {
  const KlipperSkew k = ValueOf(BuildKlipperSkew(Square(-1108.5, 455.0, -520.9), {}));
  EXPECT_NEAR(KlipperFactor(k.xy->ac, k.xy->bd, k.xy->ad), *k.factors.xy, 1e-12);
  EXPECT_NEAR(KlipperFactor(k.xz->ac, k.xz->bd, k.xz->ad), *k.factors.xz, 1e-12);
  EXPECT_NEAR(KlipperFactor(k.yz->ac, k.yz->bd, k.yz->ad), *k.factors.yz, 1e-12);
  EXPECT_NEAR(*k.factors.xy, 1108.5e-6, 1e-9);  // −tan(−1108.5 µrad) ≈ +1108.5e-6
}

// Klipper's own example (docs/Skew_Correction.md): AC = 140.4, BD = 142.8, AD = 99.8. By hand:
// AB = √(2·19712.16 + 2·20391.84 − 4·9960.04)/2 = √40367.84/2 = 100.45875; cos α = (19712.16 −
// 10091.96 − 9960.04)/(2·100.45875·99.8) = −339.84/20051.57 = −0.0169481; α = 90.9711°; factor
// tan(−0.9711°) = −0.0169507. A machine with that skew has C0Y = −atan(factor) = +16949.1 µrad;
// the square of the same side written back gives the same factor.
TEST(KlipperSkew, TheDocumentationsExampleSquare) {
  EXPECT_NEAR(KlipperFactor(140.4, 142.8, 99.8), -0.0169507, 1e-7);
  const double c0y = -std::atan(KlipperFactor(140.4, 142.8, 99.8)) * 1e6;
  EXPECT_NEAR(c0y, 16949.1, 0.1);
  HobbySquareness s;
  s.xy = PlaneSquareness{c0y, "Klipper's example"};
  KlipperOptions o;
  o.square_mm = 100.45875;
  const KlipperSkew k = ValueOf(BuildKlipperSkew(s, o));
  EXPECT_NEAR(*k.factors.xy, -0.0169507, 1e-7);
  EXPECT_NEAR(KlipperFactor(k.xy->ac, k.xy->bd, k.xy->ad), *k.factors.xy, 1e-12);
  EXPECT_FALSE(k.xz.has_value());
  // A plane not given: 0 in the profile (Klipper reads all three) and out of SET_SKEW.
  EXPECT_NE(k.text.find("#*# xz_skew = 0.000000000\n#*# yz_skew = 0.000000000\n"),
            std::string::npos);
  EXPECT_NE(k.text.find("# XZ: no squareness given, written as 0.\n"), std::string::npos);
  EXPECT_EQ(k.text.find("XZ="), std::string::npos);
}

TEST(KlipperSkew, NegateFlipsEveryFactor) {
  KlipperOptions o;
  o.negate = true;
  o.profile = "shop";
  const KlipperSkew k = ValueOf(BuildKlipperSkew(Square(-500, 200, -300), o));
  EXPECT_NE(k.text.find("#*# [skew_correction shop]\n#*# xy_skew = -0.000500000\n"
                        "#*# xz_skew = -0.000200000\n#*# yz_skew = -0.000300000\n"),
            std::string::npos)
      << k.text;
  EXPECT_NE(k.text.find("NEGATED"), std::string::npos);
}

TEST(KlipperSkew, RefusesWhatKlipperCannotTake) {
  ExpectFailure(BuildKlipperSkew({}, {}), Error::kInvalidArgument, {"no squareness"});
  KlipperOptions blank;
  blank.profile = "my skew";
  ExpectFailure(BuildKlipperSkew(Square(1, 1, 1), blank), Error::kInvalidArgument,
                {"\"my skew\"", "one word"});
  KlipperOptions side;
  side.square_mm = 0;
  ExpectFailure(BuildKlipperSkew(Square(1, 1, 1), side), Error::kInvalidArgument,
                {"0.000 mm", "> 0"});
}

}  // namespace
}  // namespace volcomp::exporters
