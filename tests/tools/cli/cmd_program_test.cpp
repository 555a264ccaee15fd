// `volcomp program positioning` and `program diagonal` run as main() runs them: G-code on standard
// output, plans the options cannot make are usage failures.
#include <gtest/gtest.h>

#include <string>

#include "cli_runner.hpp"

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

}  // namespace
}  // namespace volcomp
