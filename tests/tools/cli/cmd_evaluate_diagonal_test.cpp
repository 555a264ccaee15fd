// `volcomp evaluate diagonal` run as main() runs it, on samples/metrology/diagonals.csv.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_runner.hpp"
#include "sample_path.hpp"
#include "temp_paths.hpp"

namespace volcomp {
namespace {

using testing::FreshTempPath;
using testing::RunCli;
using testing::SamplePath;

TEST(MetrologyCli, EvaluateDiagonalSample) {
  const std::string dir = FreshTempPath("evaluate_diagonal");
  const auto r =
      RunCli({"evaluate", "diagonal", SamplePath("metrology/diagonals.csv"), "--report", dir});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("body diagonals (4):  E_d = "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("face XY Z200 (2)"), std::string::npos) << r.out;
  EXPECT_TRUE(
      std::filesystem::exists(dir + "/diagonal_NPP_PNP_PPN_PPP_XY_PN_Z200_XY_PP_Z200.html"));
  EXPECT_TRUE(
      std::filesystem::exists(dir + "/diagonal_NPP_PNP_PPN_PPP_XY_PN_Z200_XY_PP_Z200.json"));
  std::filesystem::remove_all(dir);
}

TEST(MetrologyCli, EvaluateDiagonalJsonAndBadInput) {
  auto r = RunCli({"evaluate", "diagonal", SamplePath("metrology/diagonals.csv"), "--json"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"command\": \"evaluate diagonal\""), std::string::npos);
  EXPECT_NE(r.out.find("\"E_d\""), std::string::npos);
  r = RunCli({"evaluate", "diagonal", "-"}, "target_mm,direction,run,deviation_um\n0,up,1,1\n");
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("volcomp evaluate diagonal: error: <stdin>:1: missing column "
                       "\"diagonal\"\n"),
            std::string::npos)
      << r.err;
  r = RunCli({"evaluate", "diagonal", "a.csv", "b.csv"});
  EXPECT_EQ(r.code, tools::kExitUsage);
}

}  // namespace
}  // namespace volcomp
