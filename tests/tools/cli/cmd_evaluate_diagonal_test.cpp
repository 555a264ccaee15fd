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

// E_d carries the U of the diagonal it comes from: the body diagonals are 1024.695 mm long; with
// a 0.3 µm calibration U, the material at 20.5 °C and a 1 µm drift test: instrument 0.3,
// thermometer 0.6·11.5·1.024695·0.2 = 1.41408, expansion 0.6·1.024695·0.5·2 = 0.61482,
// environment 0.6: U = sqrt(0.09 + 1.99962 + 0.37800 + 0.36) = 1.68; U(B) = sqrt(0.09 + 0.36)
// = 0.67.
TEST(MetrologyCli, EvaluateDiagonalWithUncertainty) {
  const auto r =
      RunCli({"evaluate", "diagonal", SamplePath("metrology/diagonals.csv"), "--instrument-u-um",
              "0.3", "--material-temperature-c", "20.5", "--drift-range-um", "1"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("E_d = 19.99 ± 1.68 µm (+X+Y-Z),  B_d = 5.89 ± 0.67 µm"), std::string::npos)
      << r.out;
  EXPECT_EQ(r.err.find("no measurement uncertainty"), std::string::npos) << r.err;
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
