// The metrology commands run in-process on the sample data of samples/metrology/.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "test_support.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::tools {
namespace {

using metrology::testing::RepoPath;

// Runs a command with its option table, std::cout/std::cerr captured; exceptions propagate.
struct CmdResult {
  int code = -1;
  std::string out, err;
};

CmdResult Invoke(int (*cmd)(Args&), std::vector<std::string> argv) {
  CmdResult r;
  std::ostringstream out, err;
  auto* old_out = std::cout.rdbuf(out.rdbuf());
  auto* old_err = std::cerr.rdbuf(err.rdbuf());
  try {
    const cli::Command* c = nullptr;
    for (const cli::Command* k : cli::Commands()) {
      if (k->legacy_run == cmd) c = k;
    }
    if (c == nullptr) throw std::logic_error("command not in the table");
    Args a(std::move(argv), &c->options);
    r.code = cmd(a);
  } catch (...) {
    std::cout.rdbuf(old_out);
    std::cerr.rdbuf(old_err);
    throw;
  }
  std::cout.rdbuf(old_out);
  std::cerr.rdbuf(old_err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

std::string TempDir(const std::string& name) {
  const auto p = std::filesystem::temp_directory_path() / ("volcomp_metrology_cli_" + name);
  std::filesystem::remove_all(p);
  return p.string();
}

TEST(MetrologyCli, CommandsAreRegistered) {
  std::vector<std::string> names;
  for (const cli::Command* c : cli::Commands()) names.push_back(c->name);
  for (const char* n : {"evaluate positioning", "evaluate diagonal", "evaluate rotary",
                        "program positioning", "program diagonal"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
  }
}

TEST(MetrologyCli, EvaluatePositioningGostExampleWithReport) {
  const std::string dir = TempDir("positioning");
  const CmdResult r =
      Invoke(RunEvaluatePositioning,
             {RepoPath("samples/metrology/gost27843_example_long.csv"), "--report", dir});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("A       = 18.00"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("R_max   = 13.49"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir + "/positioning_gost27843_example_long.html"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/positioning_gost27843_example_long.json"));
  std::filesystem::remove_all(dir);
}

TEST(MetrologyCli, EvaluatePositioningJsonBothStandards) {
  const CmdResult r = Invoke(RunEvaluatePositioning,
                             {RepoPath("tests/metrology/data/gost27843_example_reconstructed.csv"),
                              "--json", "--standard", "both"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("\"standard\": \"GOST 27843-88\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"standard\": \"ISO 230-2:2014\""), std::string::npos);
  EXPECT_NE(r.out.find("\"B_max\""), std::string::npos);
  EXPECT_NE(r.out.find("\"M\""), std::string::npos);
}

TEST(MetrologyCli, EvaluateRotaryTablePositioningChecksCardinalAngles) {
  const CmdResult r =
      Invoke(RunEvaluatePositioning, {RepoPath("samples/metrology/rotary_table_positioning.csv")});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("rotary axis, 12 target positions"), std::string::npos) << r.out;
  EXPECT_EQ(r.err.find("§2.8"), std::string::npos) << r.err;  // 0/90/180/270 present
}

TEST(MetrologyCli, EvaluateDiagonalSample) {
  const std::string dir = TempDir("diagonal");
  const CmdResult r =
      Invoke(RunEvaluateDiagonal, {RepoPath("samples/metrology/diagonals.csv"), "--report", dir});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("body diagonals (4):  E_d = "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("face XY Z200 (2)"), std::string::npos) << r.out;
  EXPECT_TRUE(
      std::filesystem::exists(dir + "/diagonal_NPP_PNP_PPN_PPP_XY_PN_Z200_XY_PP_Z200.html"));
  std::filesystem::remove_all(dir);
}

TEST(MetrologyCli, EvaluateRotarySamplesIncludingReversal) {
  CmdResult r = Invoke(RunEvaluateRotary, {RepoPath("samples/metrology/spindle_error_motion.csv"),
                                           "--tilt-distance-mm", "80", "--min-zone", "--json"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("\"tilt\""), std::string::npos);
  EXPECT_NE(r.out.find("\"MZ\""), std::string::npos);
  r = Invoke(RunEvaluateRotary,
             {RepoPath("samples/metrology/reversal_setup1.csv"), "--sensitive", "fixed",
              "--reversal", RepoPath("samples/metrology/reversal_setup2.csv")});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("Donaldson reversal"), std::string::npos) << r.out;
}

TEST(MetrologyCli, ProgramsAreGcode) {
  CmdResult r = Invoke(RunProgramPositioning,
                       {"--end", "1500", "--pitch", "10", "--cycle", "pilgrim", "--runs", "5"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("pseudo-pilgrim"), std::string::npos);
  EXPECT_NE(r.out.find("(P11 down run 5)"), std::string::npos);
  r = Invoke(RunProgramDiagonal,
             {"--p1", "0,0,0", "--p2", "800,500,400", "--increment-mm", "100", "--name", "-X-Y-Z"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("G1 X800.000 Y500.000 Z400.000 (P11 up run 1)"), std::string::npos) << r.out;
}

TEST(MetrologyCli, BadOptionsAndInputs) {
  EXPECT_THROW(Invoke(RunEvaluatePositioning, {"x.csv", "--standard", "nope"}), UsageError);
  EXPECT_THROW(Invoke(RunEvaluatePositioning, {"x.csv", "--bogus"}), UsageError);
  EXPECT_THROW(Invoke(RunEvaluatePositioning, {}), UsageError);
  EXPECT_THROW(Invoke(RunEvaluatePositioning, {"/nonexistent/file.csv"}), InputError);
  EXPECT_THROW(Invoke(RunEvaluateRotary, {"x.csv", "--fsd-angle-deg", "10"}), UsageError);
  EXPECT_THROW(Invoke(RunProgramPositioning, {"--end", "100", "--pitch", "50", "--count", "11"}),
               UsageError);
  EXPECT_THROW(Invoke(RunProgramDiagonal, {"--p1", "0,0", "--p2", "1,1,1", "--increment-mm", "1"}),
               UsageError);
}

}  // namespace
}  // namespace volcomp::tools
