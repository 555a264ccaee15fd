// The G-code subset of the simulated CNC.
#include "volcomp/sim/gcode.hpp"

#include <gtest/gtest.h>

#include <string>

namespace volcomp::sim {
namespace {

using Kind = ProgramBlock::Kind;

TEST(SimGcode, ModalMotionFeedAndCoordinates) {
  const Expected<Program> parsed = ParseGcode(
      "%\n(title)\nN10 G21 G90 G94\nG0 X1 Y2 Z3 ; rapid\nG1 X4 F1200 (feed 20 mm/s)\nY5\n"
      "G4 P0.25\nG0\nZ-7.5\nM2\nG1 X99\n",
      "t.ngc");
  ASSERT_TRUE(parsed.ok()) << parsed.error().message;
  const Program& p = *parsed;
  ASSERT_EQ(p.size(), 5u);
  EXPECT_EQ(p[0].kind, Kind::kRapid);
  EXPECT_TRUE(p[0].has[0] && p[0].has[1] && p[0].has[2]);
  EXPECT_DOUBLE_EQ(p[0].value_mm[2], 3);
  EXPECT_EQ(p[0].line, 4);
  EXPECT_EQ(p[1].kind, Kind::kLinear);
  EXPECT_DOUBLE_EQ(p[1].feed_mm_s, 20);
  EXPECT_TRUE(p[1].has[0]);
  EXPECT_FALSE(p[1].has[1]);
  EXPECT_EQ(p[2].kind, Kind::kLinear);  // modal G1, modal F
  EXPECT_DOUBLE_EQ(p[2].feed_mm_s, 20);
  EXPECT_DOUBLE_EQ(p[2].value_mm[1], 5);
  EXPECT_EQ(p[3].kind, Kind::kDwell);
  EXPECT_DOUBLE_EQ(p[3].dwell_s, 0.25);
  EXPECT_EQ(p[4].kind, Kind::kRapid);  // G0 alone on its line, then Z
  EXPECT_DOUBLE_EQ(p[4].value_mm[2], -7.5);
  EXPECT_FALSE(p[4].incremental);  // and nothing after M2
}

TEST(SimGcode, IncrementalMode) {
  const Expected<Program> parsed = ParseGcode("G91 G0 X1\nG90 X2\n");
  ASSERT_TRUE(parsed.ok()) << parsed.error().message;
  const Program& p = *parsed;
  ASSERT_EQ(p.size(), 2u);
  EXPECT_TRUE(p[0].incremental);
  EXPECT_FALSE(p[1].incremental);
}

TEST(SimGcode, RefusesWhatItDoesNotModelWithTheLine) {
  const struct {
    const char* text;
    const char* message;
  } cases[] = {
      {"G20\n", "prog:1: G20"},
      {"G21\nG2 X1 Y1 I1\n", "prog:2: G2 without a feed (F)"},
      {"G33 X1\n", "prog:1: G33 is not supported"},
      {"G1 X1\n", "prog:1: G1 without a feed"},
      {"\n\nX1\n", "prog:3: coordinates without G0, G1, G2 or G3"},
      {"G4\n", "prog:1: G4 needs P"},
      {"G0 X1 (open\n", "prog:1: unclosed comment"},
      {"G0 Xabc\n", "prog:1: word X needs a number"},
      {"T1 M6\n", "prog:1: word T is not supported"},
      {"M7\n", "prog:1: M7 is not supported"},
      {"G0 X1 P2\n", "prog:1: P without G4"},
  };
  for (const auto& c : cases) {
    const Expected<Program> p = ParseGcode(c.text, "prog");
    ASSERT_FALSE(p.ok()) << "accepted: " << c.text;
    EXPECT_EQ(p.error().code, Error::kInputInvalid) << c.text;
    EXPECT_NE(p.error().message.find(c.message), std::string::npos)
        << c.text << " -> " << p.error().message;
  }
}

}  // namespace
}  // namespace volcomp::sim
