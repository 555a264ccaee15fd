// Negative numbers reach the commands as values: option values and positionals that start with a
// minus (`sdo write 2018:1 -5000`, coordinates of build and program options).
#include <gtest/gtest.h>

#include <filesystem>

#include "cli_runner.hpp"

namespace volcomp::tools {
namespace {

using volcomp::testing::RunCli;

// The case: `sdo write 2018:1 -5000` stopped at the option parser with exit 2. Now the
// value reaches the command, which fails later only because there is no bus.
TEST(VolcompCli, SdoWriteTakesANegativeValue) {
  for (const auto& words : std::vector<std::vector<std::string>>{
           {"sdo", "write", "2018:1", "-5000", "--can", "slcan-tcp:127.0.0.1:1"},
           {"sdo", "write", "2018:1", "--can", "slcan-tcp:127.0.0.1:1", "--", "-5000"}}) {
    const auto r = RunCli(words);
    EXPECT_NE(r.code, kExitUsage) << r.err;
    EXPECT_EQ(r.err.find("unexpected argument"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("127.0.0.1"), std::string::npos) << r.err;  // it tried the bus
  }
  const auto bad = RunCli({"sdo", "write", "2018:1", "-5x", "--can", "slcan-tcp:127.0.0.1:1"});
  EXPECT_EQ(bad.code, kExitUsage);
  EXPECT_NE(bad.err.find("unknown option \"-5x\""), std::string::npos) << bad.err;
}

TEST(VolcompCli, NegativeCoordinatesInBuildAndProgramOptions) {
  const std::string img =
      (std::filesystem::temp_directory_path() / "volcomp_args_neg.vct").string();
  auto r = RunCli({"build", "model", "--model", "s500", "--tool-offset-mm", "-1,2,3", "--range",
                   "X=-100:100,Y=0:40,Z=0:40", "--spacing-mm", "20", "--resolution-nm",
                   "X=1000,Y=1000,Z=1000", "-o", img});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("lattice X: -100 .. 100 mm"), std::string::npos) << r.out;
  std::filesystem::remove(img);
  r = RunCli({"program", "diagonal", "--p1", "-10,-20,-30", "--p2", "90,80,70", "--increment-mm",
              "20", "--name", "-X-Y-Z"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("G1 X-10.000 Y-20.000 Z-30.000 (P1 up run 1)"), std::string::npos) << r.out;
  r = RunCli({"program", "positioning", "--start", "-200", "--end", "-20", "--pitch", "5"});
  EXPECT_EQ(r.code, 0) << r.err;
}

}  // namespace
}  // namespace volcomp::tools
