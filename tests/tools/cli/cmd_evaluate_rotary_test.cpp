// `volcomp evaluate rotary` run as main() runs it, on the ISO 230-7 samples of samples/metrology/.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "cli_runner.hpp"
#include "sample_path.hpp"

namespace volcomp {
namespace {

using testing::RunCli;
using testing::SamplePath;

TEST(MetrologyCli, EvaluateRotarySamplesIncludingReversal) {
  auto r = RunCli({"evaluate", "rotary", SamplePath("metrology/spindle_error_motion.csv"),
                   "--tilt-distance-mm", "80", "--min-zone", "--json"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"tilt\""), std::string::npos);
  EXPECT_NE(r.out.find("\"MRS\""), std::string::npos);
  r = RunCli({"evaluate", "rotary", SamplePath("metrology/spindle_error_motion.csv"),
              "--tilt-distance-mm", "80", "--min-zone"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("values about PC, LSC, MRS;"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("centre offsets from PC [µm]: LSC ("), std::string::npos) << r.out;
  r = RunCli({"evaluate", "rotary", SamplePath("metrology/reversal_setup1.csv"), "--sensitive",
              "fixed", "--reversal", SamplePath("metrology/reversal_setup2.csv")});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("Donaldson reversal"), std::string::npos) << r.out;
}

// E_VE from a drift-test file: the budget names the file in the text, the JSON and the report
// (the sample warm-up test's largest point range, 37.54 µm: U_EVE = 0.6 × 37.54 = 22.52 µm).
TEST(MetrologyCli, EvaluateRotaryNamesItsDriftTest) {
  const std::string drift = SamplePath("metrology/thermal_drift.csv");
  auto r = RunCli({"evaluate", "rotary", SamplePath("metrology/spindle_error_motion.csv"),
                   "--tilt-distance-mm", "80", "--instrument-u-um", "0.1", "--drift-test", drift,
                   "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"drift_source\": \"drift test " + drift + ": "), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\"drift\": 22.52"), std::string::npos) << r.out;
  r = RunCli({"evaluate", "rotary", SamplePath("metrology/spindle_error_motion.csv"),
              "--tilt-distance-mm", "80", "--instrument-u-um", "0.1", "--drift-test", drift});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("(0.6 × E_VE, F.3; drift test " + drift + ": "), std::string::npos) << r.out;
}

TEST(MetrologyCli, EvaluateRotaryAboutEveryCentre) {
  auto r = RunCli({"evaluate", "rotary", SamplePath("metrology/spindle_error_motion.csv"),
                   "--tilt-distance-mm", "80", "--centres", "all"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("values about PC, LSC, MRS, MIC, MCC;"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("; MIC ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("; MCC ("), std::string::npos) << r.out;
  r = RunCli({"evaluate", "rotary", SamplePath("metrology/spindle_error_motion.csv"), "--centres",
              "MIC,MCC", "--json"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"MIC\""), std::string::npos);
  EXPECT_EQ(r.out.find("\"MRS\""), std::string::npos);
  r = RunCli({"evaluate", "rotary", "x.csv", "--centres", "MIC,MZC"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("unknown centre \"MZC\""), std::string::npos) << r.err;
}

TEST(MetrologyCli, EvaluateRotaryBadOptionsAndInputs) {
  auto r = RunCli({"evaluate", "rotary", "x.csv", "--fsd-angle-deg", "10"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--fsd-angle-deg needs --sensitive fixed"), std::string::npos) << r.err;
  r = RunCli({"evaluate", "rotary", "x.csv", "--reversal-procedure", "Q"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  r = RunCli({"evaluate", "rotary", SamplePath("metrology/reversal_setup1.csv"), "--sensitive",
              "fixed", "--reversal", SamplePath("metrology/reversal_setup2.csv"),
              "--reversal-channel", "q_um"});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("reversal_setup1.csv: no column \"q_um\" for the reversal"),
            std::string::npos)
      << r.err;
  r = RunCli({"evaluate", "rotary", "-"}, "rev,angle_deg,x_um\n1,0,0\n1,90,1\n1,180,0\n1,270,1\n");
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("<stdin>: a rotating sensitive direction needs column y_um"),
            std::string::npos)
      << r.err;
}

// The uncertainty inputs from the options or the file's preamble; each value's U in the text and
// the JSON; a preamble value that is not a number is refused naming it.
TEST(MetrologyCli, EvaluateRotaryUncertaintyFromOptionsOrPreamble) {
  const std::string dir = ::testing::TempDir();
  const std::string file = dir + "/rotary_u.csv";
  std::string csv = "# instrument_u_um: 0.1\n# drift_range_um: 0.5\nrev,angle_deg,z_um\n";
  for (int k = 1; k <= 4; ++k) {
    for (int j = 0; j < 8; ++j) csv += std::to_string(k) + "," + std::to_string(45 * j) + ",0\n";
  }
  { std::ofstream(file) << csv; }
  // U_sync value = 1.4·sqrt(0.1² + 0.3²/4) = 0.252389; single = 1.4·sqrt(0.01 + 0.09) = 0.442719.
  auto r = RunCli({"evaluate", "rotary", file});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("U (k = 2, annex F): synchronous values ±0.2524, "
                       "total/inner/outer/asynchronous values ±0.4427 µm"),
            std::string::npos)
      << r.out;
  r = RunCli({"evaluate", "rotary", file, "--report", dir + "/rotary_u_report"});
  EXPECT_EQ(r.code, 0) << r.err;
  std::ifstream html(dir + "/rotary_u_report/rotary_rotary_u.html");
  const std::string page((std::istreambuf_iterator<char>(html)), {});
  EXPECT_NE(page.find("Uncertainty (annex F, k = 2): synchronous values ± 0.2524"),
            std::string::npos);
  std::filesystem::remove_all(dir + "/rotary_u_report");
  r = RunCli({"evaluate", "rotary", file, "--instrument-u-um", "0.2", "--json"});
  EXPECT_EQ(r.code, 0) << r.err;
  // 1.4·sqrt(0.04 + 0.0225) = 0.35
  EXPECT_NE(r.out.find("\"synchronous_value\": 0.35"), std::string::npos) << r.out;
  { std::ofstream(file) << "# drift_range_um: a lot\n" + csv; }
  r = RunCli({"evaluate", "rotary", file});
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("preamble \"drift_range_um: a lot\" is not a number"), std::string::npos)
      << r.err;
  r = RunCli({"evaluate", "rotary", file, "--axis", "lathe"});
  EXPECT_EQ(r.code, tools::kExitUsage);
}

}  // namespace
}  // namespace volcomp
