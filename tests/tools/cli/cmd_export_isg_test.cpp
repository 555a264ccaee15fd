// `volcomp export isg`, run as main() runs it: the leadscrew error compensation list of raw
// readings compared with a list written by hand from the Beckhoff manual's syntax and units
// (data-formats.md B6: 0.1 µm, actual − setpoint), a one-direction test, --negate, the point limit.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.hpp"
#include "comment_lines.hpp"
#include "expected_value.hpp"
#include "temp_paths.hpp"
#include "volcomp/tools/file_io.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp {
namespace {

using testing::RunCli;
using testing::TempPath;
using testing::ValueOf;
using testing::WithoutCommentLines;

// dev = +10.2 µm moving up, −6 µm moving down, at 0, 50, 100 mm; five runs each.
std::string RawReadings() {
  const std::string csv = TempPath("export_isg_raw.csv");
  std::ofstream f(csv);
  f << "target_mm,direction,run,deviation_um\n";
  for (int run = 1; run <= 5; ++run) {
    for (const char* t : {"0", "50", "100"}) f << t << ",up," << run << ",10.2\n";
    for (const char* t : {"100", "50", "0"}) f << t << ",down," << run << ",-6\n";
  }
  return csv;
}

std::string Collapsed(const std::string& text) {  // one space between the fields
  std::string out;
  for (char c : text) {
    if (c == ' ' && !out.empty() && out.back() == ' ') continue;
    out += c;
  }
  return out;
}

TEST(VolcompExportIsg, ListOfRawReadings) {
  const std::string dir = TempPath("export_isg_out");
  const auto r =
      RunCli({"export", "isg", "--y", RawReadings(), "-o", dir, "--axis-numbers", "Y=2", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string file = (std::filesystem::path(dir) / "achskw_y.lis").string();
  const std::string text = ValueOf(tools::ReadTextFile(file));
  // Written by hand: positions 0, 50, 100 mm = 0, 500000, 1000000 × 0.1 µm; +10.2 µm = 102,
  // −6 µm = −60 (× 0.1 µm), actual − setpoint as measured.
  EXPECT_EQ(Collapsed(WithoutCommentLines(text, "#")),
            "kopf.achs_nr 2\nkopf.log_achs_name Y\nkw.ssfk.unit 1\nkw.ssfk.interval 0\n"
            "kw.ssfk.kw_startpos 0\nkw.ssfk.kw_nr_max 3\nkw.ssfk.bilateral 1\n"
            "kw.ssfk.table[0].setpoint 0\nkw.ssfk.table[1].setpoint 500000\n"
            "kw.ssfk.table[2].setpoint 1000000\n"
            "kw.ssfk.table[0].pos 102\nkw.ssfk.table[1].pos 102\nkw.ssfk.table[2].pos 102\n"
            "kw.ssfk.table[0].neg -60\nkw.ssfk.table[1].neg -60\nkw.ssfk.table[2].neg -60\n");
  EXPECT_NE(text.find("# sign: the values are the error, actual - setpoint, no sign changed"),
            std::string::npos)
      << text;
  const tools::JsonValue j = ValueOf(tools::ParseJson(r.out, "stdout"));
  const tools::JsonValue& a = j.get("axes")->array.at(0);
  EXPECT_EQ(a.get("points")->integer, 3);
  EXPECT_EQ(a.get("max_abs_value")->integer, 102);
  EXPECT_TRUE(a.get("bilateral")->boolean);
}

TEST(VolcompExportIsg, OneDirectionAndNegate) {
  const std::string csv = TempPath("export_isg_means.csv");
  ASSERT_TRUE(
      tools::WriteTextFile(csv, "position_mm,dev_forward_um\n-20,1.5\n0,0\n20,-2.34\n").ok());
  const std::string dir = TempPath("export_isg_negated");
  const auto r = RunCli({"export", "isg", "--x", csv, "-o", dir, "--negate"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("one table for both directions, negated"), std::string::npos) << r.out;
  const std::string text =
      ValueOf(tools::ReadTextFile((std::filesystem::path(dir) / "achskw_x.lis").string()));
  // −(1.5 µm) = −15, −(−2.34 µm) = +23.4 → 23 (× 0.1 µm); .neg repeats .pos, bilateral 0.
  EXPECT_EQ(Collapsed(WithoutCommentLines(text, "#")),
            "kopf.achs_nr 1\nkopf.log_achs_name X\nkw.ssfk.unit 1\nkw.ssfk.interval 0\n"
            "kw.ssfk.kw_startpos -200000\nkw.ssfk.kw_nr_max 3\nkw.ssfk.bilateral 0\n"
            "kw.ssfk.table[0].setpoint -200000\nkw.ssfk.table[1].setpoint 0\n"
            "kw.ssfk.table[2].setpoint 200000\n"
            "kw.ssfk.table[0].pos -15\nkw.ssfk.table[1].pos 0\nkw.ssfk.table[2].pos 23\n"
            "kw.ssfk.table[0].neg -15\nkw.ssfk.table[1].neg 0\nkw.ssfk.table[2].neg 23\n");
  EXPECT_NE(text.find("NEGATED on request (--negate)"), std::string::npos);
}

TEST(VolcompExportIsg, Refusals) {
  const std::string csv = TempPath("export_isg_means3.csv");
  ASSERT_TRUE(tools::WriteTextFile(csv, "position_mm,dev_forward_um\n0,1\n10,2\n20,3\n").ok());
  auto r =
      RunCli({"export", "isg", "--x", csv, "-o", TempPath("export_isg_r"), "--max-points", "3"});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("axis X: 3 positions: kw.ssfk.kw_nr_max must be smaller than "
                       "kw.ssfk.max_points (P-COMP-00059), 3 here"),
            std::string::npos)
      << r.err;
  r = RunCli(
      {"export", "isg", "--x", csv, "-o", TempPath("export_isg_r"), "--axis-numbers", "X=0"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--axis-numbers: logical axis number of X must be 1..65535"),
            std::string::npos)
      << r.err;
  r = RunCli({"export", "isg", "--x", csv, "--y", csv, "-o", TempPath("export_isg_r"),
              "--axis-numbers", "Y=1"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--axis-numbers: X and Y both have the logical axis number 1"),
            std::string::npos)
      << r.err;
  r = RunCli({"export", "isg", "-o", TempPath("export_isg_r")});
  EXPECT_EQ(r.code, tools::kExitUsage);
}

}  // namespace
}  // namespace volcomp
