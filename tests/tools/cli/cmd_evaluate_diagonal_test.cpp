// `volcomp evaluate diagonal` run as main() runs it, on samples/metrology/diagonals.csv.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "cli_runner.hpp"

namespace volcomp {
namespace {

using testing::RunCli;

std::string RepoPath(const std::string& relative) {
  const char* root = std::getenv("VOLCOMP_SOURCE_DIR");
  return std::string(root ? root : ".") + "/" + relative;
}

TEST(MetrologyCli, EvaluateDiagonalSample) {
  const auto dir = (std::filesystem::temp_directory_path() / "volcomp_evaluate_diagonal").string();
  std::filesystem::remove_all(dir);
  const auto r = RunCli(
      {"evaluate", "diagonal", RepoPath("samples/metrology/diagonals.csv"), "--report", dir});
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
  auto r = RunCli({"evaluate", "diagonal", RepoPath("samples/metrology/diagonals.csv"), "--json"});
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
