// Diagonal names (diagonal.hpp, diagonal_name.cpp): the accepted forms, names that follow from the
// geometry of P1 and P2, the check of a given name and the file tokens.
#include <gtest/gtest.h>

#include "volcomp/metrology/diagonal.hpp"

namespace volcomp::metrology {
namespace {

TEST(MetrologyDiagonalName, AcceptedForms) {
  auto d = ParseDiagonalName("+X+Y-Z");
  ASSERT_TRUE(d);
  EXPECT_TRUE(d->body);
  EXPECT_EQ(d->text, "+X+Y-Z");
  d = ParseDiagonalName("PPN");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->text, "+X+Y-Z");
  d = ParseDiagonalName("npp");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->text, "-X+Y+Z");
  d = ParseDiagonalName("+X -Y Z300");
  ASSERT_TRUE(d);
  EXPECT_FALSE(d->body);
  EXPECT_EQ(d->plane, "XY");
  EXPECT_EQ(d->offset, "Z300");
  EXPECT_EQ(d->text, "+X-Y Z300");
  d = ParseDiagonalName("NP300");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->text, "-X+Y Z300");
  d = ParseDiagonalName("-Y+Z");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->plane, "YZ");
  d = ParseDiagonalName("+Z-X");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->text, "-X+Z");
  for (const char* bad :
       {"", "+X", "+X+X", "PPNP", "+X+Y+Z Z3", "+X+Y Z", "+X+Y Y100", "PNPN", "+Q+Y", "X+Y"}) {
    EXPECT_FALSE(ParseDiagonalName(bad)) << bad;
  }
}

TEST(MetrologyDiagonalNames, FollowFromTheGeometry) {
  const auto body = DiagonalNameFor({10, 10, 10}, {390, 270, 190});
  ASSERT_TRUE(body);
  EXPECT_EQ(body->text, "-X-Y-Z");
  EXPECT_EQ(DiagonalFileToken(*body), "NNN");
  EXPECT_EQ(DiagonalNameFor({390, 10, 10}, {10, 270, 190})->text, "+X-Y-Z");
  EXPECT_EQ(DiagonalNameFor({10, 270, 190}, {390, 10, 10})->text, "-X+Y+Z");
  const auto face = DiagonalNameFor({400, 0, 300}, {0, 280, 300});
  ASSERT_TRUE(face);
  EXPECT_EQ(face->text, "+X-Y Z300");
  EXPECT_EQ(DiagonalFileToken(*face), "XY_PN_Z300");
  EXPECT_FALSE(DiagonalNameFor({0, 0, 0}, {100, 0, 0}));

  EXPECT_FALSE(DiagonalNameMismatch(*ParseDiagonalName("NNN"), {10, 10, 10}, {390, 270, 190}));
  const auto why =
      DiagonalNameMismatch(*ParseDiagonalName("+X+Y+Z"), {10, 10, 10}, {390, 270, 190});
  ASSERT_TRUE(why);
  EXPECT_NE(why->find("starts at the -X-Y-Z corner"), std::string::npos) << *why;
  EXPECT_TRUE(DiagonalNameMismatch(*ParseDiagonalName("+X-Y Z200"), {400, 0, 300}, {0, 280, 300}));
  EXPECT_FALSE(DiagonalNameMismatch(*ParseDiagonalName("+X-Y"), {400, 0, 300}, {0, 280, 300}));
}

}  // namespace
}  // namespace volcomp::metrology
