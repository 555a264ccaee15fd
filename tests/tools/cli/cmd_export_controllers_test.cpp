// `volcomp export siemens / heidenhain / fanuc` against files written by hand
// (tests/tools/exporters/data/*.expected) from the syntax of the shared reference
// data-formats.md §B1, B2, B4, B5 and the hand-worked inputs x_forward.csv / x_bidir.csv (the
// numbers are worked out in docs/pc-tool.md "Controller tables"); the refusals name the value,
// the limit and the fix; --negate flips every value.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "sample_path.hpp"
#include "temp_paths.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp {
namespace {

using testing::RunCli;
using testing::ScratchDir;
using testing::SourcePath;

// A file of tests/tools/exporters/data, or of the repository when the name has a folder
// ("samples/metrology/x_bidir_inch.csv", which docs/pc-tool.md also runs).
std::string Data(const std::string& name) {
  if (name.find('/') != std::string::npos) return SourcePath(name);
  return SourcePath("tests/tools/exporters/data/" + name);
}

std::string ReadFile(const std::string& path) {
  std::stringstream s;
  s << std::ifstream(path).rdbuf();
  return s.str();
}

// The expected file with @SOURCE@ replaced by the input's path as given.
std::string Expected(const std::string& name, const std::string& source) {
  std::string text = ReadFile(Data(name));
  for (std::size_t at; (at = text.find("@SOURCE@")) != std::string::npos;) {
    text.replace(at, 8, source);
  }
  return text;
}

// `volcomp export COMMAND --x INPUT OPTIONS... -o FILE --json` writes the file `expected` holds
// (its @SOURCE@ the input's path); the JSON it prints contains each of `json`.
void ExpectFileAsWrittenByHand(const std::string& command,
                               const std::string& input,
                               const std::vector<std::string>& options,
                               const std::string& expected,
                               const std::vector<std::string>& json) {
  ScratchDir dir("export_" + command);
  const std::string in = Data(input), out = dir / "out";
  std::vector<std::string> words = {"export", command, "--x", in, "-o", out, "--json"};
  words.insert(words.end(), options.begin(), options.end());
  const auto r = RunCli(words);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(ReadFile(out), Expected(expected, in));
  for (const std::string& j : json) EXPECT_NE(r.out.find(j), std::string::npos) << j << r.out;
}

// The command fails and its message contains `message`.
void ExpectRefused(const std::vector<std::string>& words, const std::string& message) {
  const auto r = RunCli(words);
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
}

TEST(VolcompExportSiemens, LecMatchesTheHandWrittenProgram) {
  ExpectFileAsWrittenByHand("siemens", "x_forward.csv", {"--reference", "X=0"},
                            "siemens_lec_x.mpf.expected", {"\"mode\": \"LEC\""});
}

TEST(VolcompExportSiemens, CecPerDirectionMatchesTheHandWrittenProgram) {
  ExpectFileAsWrittenByHand(
      "siemens", "x_bidir.csv", {"--names", "X=AX1"}, "siemens_cec_x.mpf.expected",
      {"\"mode\": \"CEC\"", "\"cec_table\": 1", "\"direction\": -1", "\"largest_value\": 0.005"});
}

// An inch machine (samples/metrology/x_bidir_inch.csv, worked by hand in docs/pc-tool.md "Inch
// machines"): the program in inches, 6 decimals, and says the basic system must be inch.
TEST(VolcompExportSiemens, InchMachineMatchesTheHandWrittenProgram) {
  ExpectFileAsWrittenByHand("siemens", "samples/metrology/x_bidir_inch.csv",
                            {"--units", "in", "--mode", "lec", "--reference", "X=0"},
                            "siemens_lec_x_inch.mpf.expected",
                            {"\"unit\": \"in\"", "\"step\": 2,", "\"largest_error_uin\": 200,"});
}

// Column `column` of samples/model/s500_x.csv (the model file's X table), read here line by line,
// not through the model reader.
std::vector<double> S500XColumn(int column) {
  std::ifstream in(SourcePath("samples/model/s500_x.csv"));
  std::vector<double> values;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || line[0] == 'n') continue;
    std::stringstream fields(line);
    std::string f;
    for (int i = 0; i <= column; ++i) std::getline(fields, f, ',');
    values.push_back(std::stod(f));
  }
  return values;
}

// "%.4f" of a µm value in mm, as SINUMERIK's tables are written.
std::string Mm4(double um) {
  char s[32];
  std::snprintf(s, sizeof s, "%.4f", um / 1000.0);
  return std::string(s) == "-0.0000" ? "0.0000" : s;
}

// A 21-parameter model as the tables' source: E_XX (column ex_um) is X's LEC table and E_YX
// (ey_um) the X -> Y cross table, value for value (no reference, no line removed).
TEST(VolcompExportSiemens, TablesFromAModel) {
  ScratchDir dir("export_siemens_model");
  const std::string model = SourcePath("samples/model/s500.conf"), out = dir / "m.mpf";
  const auto r = RunCli({"export", "siemens", "--model", model, "--cross", "X:Y",
                         "--straightness-line", "none", "-o", out});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string text = ReadFile(out);
  const std::vector<double> ex = S500XColumn(2), ey = S500XColumn(3);
  ASSERT_EQ(ex.size(), 21u);
  for (std::size_t i = 0; i < ex.size(); ++i) {
    EXPECT_NE(text.find("$AN_CEC[0," + std::to_string(i) + "]=" + Mm4(ex[i]) + "\n"),
              std::string::npos)
        << i;
    EXPECT_NE(text.find("$AN_CEC[3," + std::to_string(i) + "]=" + Mm4(ey[i]) + "\n"),
              std::string::npos)
        << i;
  }
  EXPECT_NE(text.find("$AN_CEC_INPUT_AXIS[3]=(X1)\n$AN_CEC_OUTPUT_AXIS[3]=(Y1)"),
            std::string::npos);
  // A file for an axis replaces the model's; IN:OUT without a model is refused.
  const auto x_file = RunCli(
      {"export", "siemens", "--model", model, "--x", Data("x_forward.csv"), "-o", out, "--json"});
  ASSERT_EQ(x_file.code, 0) << x_file.err;
  EXPECT_NE(x_file.out.find("x_forward.csv"), std::string::npos);
  ExpectRefused({"export", "siemens", "--x", Data("x_forward.csv"), "--cross", "X:Y", "-o", out},
                "--cross X:Y: IN:OUT without =FILE takes the straightness from --model");
}

TEST(VolcompExportSiemens, NegateFlipsEveryValue) {
  ScratchDir dir("export_siemens_negate");
  const std::string in = Data("x_forward.csv"), out = dir / "x.mpf";
  const auto r =
      RunCli({"export", "siemens", "--x", in, "--reference", "X=0", "--negate", "-o", out});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string text = ReadFile(out);
  EXPECT_NE(text.find("$AA_ENC_COMP[0,1,X1]=-0.0030\n"), std::string::npos) << text;
  EXPECT_NE(text.find("$AA_ENC_COMP[0,4,X1]=0.0020\n"), std::string::npos) << text;
  EXPECT_NE(text.find("$AA_ENC_COMP[0,0,X1]=0.0000\n"), std::string::npos) << text;
  EXPECT_NE(text.find("NEGATED (--negate)"), std::string::npos) << text;
}

TEST(VolcompExportSiemens, LecOfATwoDirectionTestIsTheirMeanAndSaysSo) {
  ScratchDir dir("export_siemens_mean");
  const std::string out = dir / "x.mpf";
  const auto r =
      RunCli({"export", "siemens", "--x", Data("x_bidir.csv"), "--mode", "lec", "-o", out});
  ASSERT_EQ(r.code, 0) << r.err;
  // (0 + −2)/2 = −1 µm at 0; (−2 + −5)/2 = −3.5 µm at 200; mean reversal (2+2+3+2+3)/5 = 2.4.
  const std::string text = ReadFile(out);
  EXPECT_NE(text.find("$AA_ENC_COMP[0,0,X1]=-0.0010\n"), std::string::npos) << text;
  EXPECT_NE(text.find("$AA_ENC_COMP[0,4,X1]=-0.0035\n"), std::string::npos) << text;
  EXPECT_NE(r.err.find("mean reversal (2.40 um)"), std::string::npos) << r.err;
}

// A cross-axis table from straightness_x_in_y.csv (its comment gives the readings as line + bow):
// the least-squares line of 2, 5.5, 7, 6.5, 4 over 0..200 mm is 4 + 0.01 x (the bow's own line is
// flat at its mean 2), leaving −2, 1, 2, 1, −2 µm; the end-point line 2 + 0.01 x leaves the bow
// 0, 3, 4, 3, 0. Both remove 10 µm/m. Input X1, output Y1, one table for both directions.
TEST(VolcompExportSiemens, CrossAxisStraightnessTable) {
  ScratchDir dir("export_siemens_cross");
  const std::string out = dir / "cec.mpf";
  auto r = RunCli({"export", "siemens", "--cross",
                   "X:Y=" + testing::SamplePath("metrology/straightness_x_in_y.csv"), "-o", out,
                   "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  std::string text = ReadFile(out);
  EXPECT_NE(text.find("$AN_CEC_INPUT_AXIS[0]=(X1)\n$AN_CEC_OUTPUT_AXIS[0]=(Y1)\n"
                      "$AN_CEC_STEP[0]=50.0000\n$AN_CEC_MIN[0]=0.0000\n$AN_CEC_MAX[0]=200.0000\n"
                      "$AN_CEC_DIRECTION[0]=0\n$AN_CEC_IS_MODULO[0]=0\n$AN_CEC[0,0]=-0.0020\n"
                      "$AN_CEC[0,1]=0.0010\n$AN_CEC[0,2]=0.0020\n$AN_CEC[0,3]=0.0010\n"
                      "$AN_CEC[0,4]=-0.0020\nM17\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("; straightness E_YX"), std::string::npos) << text;
  const auto doc = tools::ParseJson(r.out, "stdout");
  ASSERT_TRUE(doc.ok()) << r.out;
  EXPECT_EQ(doc->get("mode")->string, "CEC");
  EXPECT_NEAR(doc->get("cross")->array.at(0).get("slope_removed_um_per_m")->number, 10.0, 1e-9);
  r = RunCli({"export", "siemens", "--cross",
              "X:Y=" + testing::SamplePath("metrology/straightness_x_in_y.csv"),
              "--straightness-line", "ends", "--names", "X=AX1,Y=AX2", "-o", out});
  ASSERT_EQ(r.code, 0) << r.err;
  text = ReadFile(out);
  EXPECT_NE(text.find("$AN_CEC_OUTPUT_AXIS[0]=(AX2)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("$AN_CEC[0,0]=0.0000\n$AN_CEC[0,1]=0.0030\n$AN_CEC[0,2]=0.0040\n"
                      "$AN_CEC[0,3]=0.0030\n$AN_CEC[0,4]=0.0000\n"),
            std::string::npos)
      << text;
  EXPECT_NE(
      r.out.find("X1 -> Y1") == std::string::npos ? r.out.find("AX1 -> AX2") : std::string::npos,
      std::string::npos)
      << r.out;
  ExpectRefused({"export", "siemens", "--cross",
                 "X:X=" + testing::SamplePath("metrology/straightness_x_in_y.csv"), "-o", out},
                "two different linear axes");
  ExpectRefused({"export", "siemens", "--cross",
                 "X:Y=" + testing::SamplePath("metrology/straightness_x_in_y.csv"), "--mode", "lec",
                 "-o", out},
                "--cross writes CEC tables");
  ExpectRefused({"export", "siemens", "--cross",
                 "X:Y=" + testing::SamplePath("metrology/straightness_x_in_y.csv"),
                 "--straightness-line", "best", "-o", out},
                "--straightness-line best: lsq, ends or none");
}

TEST(VolcompExportSiemens, Refusals) {
  ScratchDir dir("export_siemens_refusals");
  const std::string out = dir / "x.mpf";
  // 5 points, the machine takes 4: 200 mm over 3 gaps = 66.6667 mm.
  ExpectRefused(
      {"export", "siemens", "--x", Data("x_forward.csv"), "--max-points", "4", "-o", out},
      "5 points, SINUMERIK LEC ($AA_ENC_COMP) with MD38000 MM_ENC_COMP_MAX_POINTS = 4 takes at "
      "most 4: use a --spacing of at least 66.6667 mm");
  // The GOST example's targets are 0, 150.71, 300.85, ...: not equally spaced.
  const std::string gost = SourcePath("samples/metrology/gost27843_example_long.csv");
  ExpectRefused({"export", "siemens", "--x", gost, "-o", out},
                "not equally spaced (150.71 mm from 0 to 150.71, 150.14 mm from 150.71 to "
                "300.85): SINUMERIK CEC ($AN_CEC) takes equally spaced points only; give "
                "--spacing");
  ExpectRefused({"export", "siemens", "--x", gost, "--encoder", "2", "-o", out},
                "--encoder 2: 0 (first measuring system) or 1 (second)");
  // Resampled to 150 mm: 0..1500, the last 0.41 mm of the test said.
  const auto r = RunCli({"export", "siemens", "--x", gost, "--spacing", "X=150", "-o", out});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("the last 0.41 mm tested are not in it"), std::string::npos) << r.err;
}

TEST(VolcompExportHeidenhain, ComAndCmaMatchTheHandWrittenTables) {
  ScratchDir dir("export_heidenhain");
  const auto r = RunCli({"export", "heidenhain", "--x", Data("x_bidir.csv"), "--reference", "X=50",
                         "-o", dir.path()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(ReadFile(dir / "AXIS_X.COM"), ReadFile(Data("AXIS_X.COM.expected")));
  EXPECT_EQ(ReadFile(dir / "CONFIG.CMA"), ReadFile(Data("CONFIG.CMA.expected")));
  const std::string notes = ReadFile(dir / "NOTES.TXT");
  EXPECT_NE(notes.find("actual - nominal"), std::string::npos) << notes;
  EXPECT_NE(notes.find("Paolico/AxisCorection"), std::string::npos) << notes;
}

TEST(VolcompExportHeidenhain, NegateFlipsValuesAndBacklash) {
  ScratchDir dir("export_heidenhain_negate");
  const auto r = RunCli({"export", "heidenhain", "--x", Data("x_bidir.csv"), "--reference", "X=50",
                         "--negate", "-o", dir.path()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string com = ReadFile(dir / "AXIS_X.COM");
  EXPECT_NE(com.find("0    +0.000000     +0.0020       +0.0030\n"), std::string::npos) << com;
  EXPECT_NE(com.find("4    +200.000000   +0.0030       +0.0050\n"), std::string::npos) << com;
}

TEST(VolcompExportHeidenhain, LegacyTncRefusesASpacingThatIsNotAPowerOfTwo) {
  ScratchDir dir("export_heidenhain_tnc4xx");
  const std::string in = Data("x_bidir.csv");
  // 50 mm = 500000 × 0.1 µm; 2^18 × 0.1 µm = 26.2144 mm, 2^19 × 0.1 µm = 52.4288 mm.
  ExpectRefused({"export", "heidenhain", "--x", in, "--control", "tnc4xx", "-o", dir.path()},
                "spacing 50 mm is not a power of two times 0.1 um, which the TNC 4xx needs: give "
                "--spacing X=26.2144 or X=52.4288");
  // 2^12 × 0.1 µm = 0.4096 mm: 489 points, more than 256.
  ExpectRefused({"export", "heidenhain", "--x", in, "--control", "tnc4xx", "--spacing", "X=0.4096",
                 "-o", dir.path()},
                "489 points, the TNC 4xx (.COM) takes at most 256");
  // 2^16 × 0.1 µm = 6.5536 mm: 31 points over 0..196.608, the 3.392 mm left said.
  const auto r = RunCli({"export", "heidenhain", "--x", in, "--control", "tnc4xx", "--spacing",
                         "X=6.5536", "-o", dir.path()});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("the last 3.392 mm tested"), std::string::npos) << r.err;
}

TEST(VolcompExportFanuc, EntrySheetMatchesTheHandWorkedOne) {
  ExpectFileAsWrittenByHand("fanuc", "x_bidir.csv", {"--reference", "X=100"},
                            "fanuc_x.txt.expected", {"\"p3620\": 1", "\"p3627\": 3"});
}

// An inch machine: detection unit 0.0001 in (IS-B), 3624 in inches, the reference at 4 in.
TEST(VolcompExportFanuc, InchMachineMatchesTheHandWorkedSheet) {
  ExpectFileAsWrittenByHand("fanuc", "samples/metrology/x_bidir_inch.csv",
                            {"--units", "in", "--reference", "X=4"}, "fanuc_x_inch.txt.expected",
                            {"\"unit\": \"in\"", "\"p3624_in\": 2,", "\"count_in\": 0.0001,",
                             "\"detection_unit_in\": 0.0001,", "\"from_in\"", "\"p3627\": 1"});
}

// HEIDENHAIN's and ISG's tables are metric whatever the machine: --units in is refused with why.
TEST(VolcompExportMetricOnly, InchIsRefusedWithTheReason) {
  ScratchDir dir("export_metric_only");
  const std::string in = Data("samples/metrology/x_bidir_inch.csv");
  auto r = RunCli({"export", "heidenhain", "--x", in, "--units", "in", "-o", dir / "h"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--units must be mm (a TNC's .COM compensation tables are in mm on an "
                       "inch machine too"),
            std::string::npos)
      << r.err;
  r = RunCli({"export", "isg", "--x", in, "--units", "in", "-o", dir / "i"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--units must be mm (an ISG LSEC list is in 0.1 um"), std::string::npos)
      << r.err;
  // The inch file itself is read into mm for them: 2 in = 50.8 mm, 120 uin = 3.048 um.
  r = RunCli({"export", "heidenhain", "--x", in, "-o", dir / "h", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"spacing\": 50.8"), std::string::npos) << r.out;
}

TEST(VolcompExportFanuc, NegateFlipsTheIncrements) {
  ScratchDir dir("export_fanuc_negate");
  const std::string out = dir / "x.txt";
  const auto r = RunCli({"export", "fanuc", "--x", Data("x_bidir.csv"), "--reference", "X=100",
                         "--negate", "-o", out});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string text = ReadFile(out);
  EXPECT_NE(text.find("  0      0.0000 .. 50.0000              +3         -2\n"), std::string::npos)
      << text;
  EXPECT_NE(text.find("  3627 X = -3 "), std::string::npos) << text;
}

TEST(VolcompExportFanuc, Refusals) {
  ScratchDir dir("export_fanuc_refusals");
  const std::string in = Data("x_bidir.csv"), out = dir / "x.txt";
  ExpectRefused({"export", "fanuc", "--x", in, "--reference", "X=60", "-o", out},
                "reference position 60.0000 mm is not a compensation point (the nearest are "
                "50.0000 and 100.0000 mm");
  // 0.01 µm counts, reference at 0: the corrections −E are 0, −3, −5, −4, +2 µm forward and
  // +2, −1, −2, −2, +5 µm reverse; the largest step, +7 µm over 150..200 reverse (point 9: the
  // forward block is 0..4, point 0 below the travel), is 700 counts, 5.51 × 127: ×6 fits.
  ExpectRefused({"export", "fanuc", "--x", in, "--detection-unit", "0.00001", "-o", out},
                "point 9 (150.0000 to 200.0000 mm) needs an increment of 700 counts, FANUC takes "
                "-128..127 per point: give --magnification 6 or more");
  ExpectRefused({"export", "fanuc", "--x", in, "--detection-unit", "0.00001", "--magnification",
                 "5", "-o", out},
                "needs an increment of 140 counts");
  EXPECT_EQ(RunCli({"export", "fanuc", "--x", in, "--detection-unit", "0.00001", "--magnification",
                    "6", "-o", out})
                .code,
            0);
  // 1 mm spacing: 201 points per direction, 402 data numbers; the third axis ends at 1205.
  ExpectRefused(
      {"export", "fanuc", "--x", in, "--y", in, "--z", in, "--spacing", "X=1,Y=1,Z=1", "-o", out},
      "Z: the points run to data number 1205, past 1023");
  ExpectRefused({"export", "fanuc", "--x",
                 SourcePath("samples/metrology/gost27843_example_long.csv"), "-o", out},
                "FANUC pitch error compensation (3624) takes equally spaced points only");
}

}  // namespace
}  // namespace volcomp
