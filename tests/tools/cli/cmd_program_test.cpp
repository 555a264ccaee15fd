// `volcomp program positioning`, `program diagonal` and `program circular` run as main() runs
// them: G-code on standard output, plans the options cannot make are usage failures. (The
// circular program's geometry: tests/tools/metrology/circular_program_test.cpp.)
#include <gtest/gtest.h>

#include <string>

#include "cli_runner.hpp"
#include "file_contents.hpp"
#include "temp_paths.hpp"

namespace volcomp {
namespace {

using testing::RunCli;

TEST(MetrologyCli, ProgramsAreGcode) {
  auto r = RunCli({"program", "positioning", "--end", "1500", "--pitch", "10", "--cycle", "pilgrim",
                   "--runs", "5"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("pseudo-pilgrim"), std::string::npos);
  EXPECT_NE(r.out.find("(P11 down run 5)"), std::string::npos);
  r = RunCli({"program", "diagonal", "--p1", "0,0,0", "--p2", "800,500,400", "--increment-mm",
              "100", "--name", "-X-Y-Z"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("G1 X800.000 Y500.000 Z400.000 (P11 up run 1)"), std::string::npos) << r.out;
  // The increment is rounded to whole steps along the diagonal, with a warning.
  r = RunCli(
      {"program", "diagonal", "--p1", "0,0,0", "--p2", "800,500,400", "--increment-mm", "90"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: increment adjusted from 90 to "), std::string::npos) << r.err;
}

// --units in: G20, the options still in mm (25.4 mm radius = 1 in, 254 mm/min = 10 in/min).
TEST(MetrologyCli, ProgramsInInches) {
  auto r = RunCli({"program", "circular", "--radius", "25.4", "--feed", "254", "--units", "in"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("G20 G90 G94 G17 G64\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nF10.000\nG3 X1.00000 Y0.00000 I0.00000 J1.00000"), std::string::npos)
      << r.out;
  r = RunCli({"program", "positioning", "--start", "25.4", "--end", "279.4", "--pitch", "25.4",
              "--count", "2", "--feed", "254", "--units", "in"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("G20 G90 G94\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nF10.000\n"), std::string::npos) << r.out;
  r = RunCli({"program", "diagonal", "--p1", "0,0,0", "--p2", "76.2,101.6,0", "--increment-mm",
              "127", "--units", "in"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("G1 X3.00000 Y4.00000 Z0.00000 (P2 up run 1)"), std::string::npos) << r.out;
  r = RunCli({"program", "circular", "--radius", "10", "--units", "inch"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--units must be mm or in"), std::string::npos) << r.err;
  r = RunCli({"program", "positioning", "--rotary", "--pitch", "10", "--units", "in"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--units in is for a linear axis: a rotary axis program is in degrees"),
            std::string::npos)
      << r.err;
}

TEST(MetrologyCli, ProgramBadOptions) {
  auto r = RunCli({"program", "positioning", "--end", "100", "--pitch", "50", "--count", "11"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("volcomp program positioning: the travel holds only 2 pitches"),
            std::string::npos)
      << r.err;
  r = RunCli({"program", "positioning", "--end", "100", "--pitch", "5", "--count", "0"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--count must be between 1 and 10000"), std::string::npos) << r.err;
  r = RunCli({"program", "positioning", "--pitch", "5"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("missing required option --end"), std::string::npos) << r.err;
  r = RunCli({"program", "diagonal", "--p1", "0,0", "--p2", "1,1,1", "--increment-mm", "1"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--p1: \"0,0\" is not X,Y,Z in mm"), std::string::npos) << r.err;
  r = RunCli({"program", "diagonal", "--p1", "1,1,1", "--p2", "1,1,1", "--increment-mm", "1"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  r = RunCli({"program", "diagonal", "--box", "0,0,0:1,1,1", "--increment-mm", "1"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--box writes four programs"), std::string::npos) << r.err;
}

TEST(MetrologyCli, ProgramCircular) {
  testing::ScratchDir dir("program_circular");
  auto r = RunCli({"program", "circular", "--radius", "150", "--centre", "100,50,-20", "--plane",
                   "YZ", "--feed", "2000", "--run-in-deg", "60", "-o", dir / "c.ngc"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string text = testing::ReadText(dir / "c.ngc");
  EXPECT_NE(text.find("G21 G90 G94 G19 G64\n"), std::string::npos) << text;
  EXPECT_NE(text.find("F2000\n"), std::string::npos) << text;
  // Start 0° is +Y of the centre in YZ: (100, 200, -20); the CCW run-in starts 60° before it.
  EXPECT_NE(text.find("G3 Y200.0000 Z-20.0000 J-150.0000 K0.0000 (CCW measured 360 deg)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("G2 Y200.0000 Z-20.0000 J-150.0000 K0.0000 (CW measured 360 deg)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("(CW run-out 60 deg)\nM2\n"), std::string::npos) << text;
  r = RunCli({"program", "circular", "--radius", "100", "--plane", "XZ"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("G18"), std::string::npos);
  EXPECT_NE(r.out.find("from +Z towards +X seen from +Y"), std::string::npos) << r.out;
}

TEST(MetrologyCli, ProgramCircularBadOptions) {
  auto r = RunCli({"program", "circular"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("missing required option --radius"), std::string::npos) << r.err;
  r = RunCli({"program", "circular", "--radius", "0"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  r = RunCli({"program", "circular", "--radius", "100", "--plane", "XW"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--plane must be XY, XZ or YZ"), std::string::npos) << r.err;
  r = RunCli({"program", "circular", "--radius", "100", "--run-in-deg", "200"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--run-in-deg must be within (0, 180]"), std::string::npos) << r.err;
  r = RunCli({"program", "circular", "--radius", "100", "--centre", "1,2"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--centre: \"1,2\" is not X,Y,Z in mm"), std::string::npos) << r.err;
  r = RunCli({"program", "circular", "--radius", "100", "--feed", "-5"});
  EXPECT_EQ(r.code, tools::kExitUsage);
}

}  // namespace
}  // namespace volcomp
