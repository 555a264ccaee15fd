// `volcomp export klipper / marlin / reprap / grblhal`: the lines written against lines worked by
// hand from the firmware's documented syntax (the formulas and the worked inputs are in
// docs/pc-tool.md "Hobby controllers" and tests/tools/exporters/*_test.cpp), the sources of the
// squareness (model file, options replacing its planes), the figures of --json, and the refusals
// (exit 1 naming the value and the limit; exit 2 for an option the command does not take).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "comment_lines.hpp"
#include "sample_path.hpp"
#include "temp_paths.hpp"

namespace volcomp {
namespace {

using testing::RunCli;
using testing::SamplePath;
using testing::ScratchDir;
using testing::WithoutCommentLines;

std::string ReadFile(const std::string& path) {
  std::stringstream s;
  s << std::ifstream(path).rdbuf();
  return s.str();
}

void ExpectContains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "lacks \"" << part << "\" in:\n" << text;
}

// A 100 mm square whose diagonals differ by 0.05 mm: f ≈ (AC − BD)/(√2·100) = 0.05/141.421356 =
// 353.553e-6, i.e. C0Y = −353.553 µrad. Back: AC, BD = 141.421356·(1 ± f/2 − f²/8) =
// 141.421356 ± 0.025000 − 0.0000022 = 141.446354, 141.396354.
TEST(VolcompExportKlipper, ASquareWithDiagonals50umApart) {
  ScratchDir dir("export_klipper_square");
  const std::string out = dir / "skew.cfg";
  const auto r =
      RunCli({"export", "klipper", "--squareness-xy-urad", "-353.553", "-o", out, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string text = ReadFile(out);
  ExpectContains(text, "#   SET_SKEW XY=141.446354,141.396354,100.000000\n");
  ExpectContains(text,
                 "#*# [skew_correction volcomp]\n#*# xy_skew = 0.000353553\n"
                 "#*# xz_skew = 0.000000000\n#*# yz_skew = 0.000000000\n");
  ExpectContains(r.out, "\"factor\": 0.000353553");
  ExpectContains(r.out, "\"set_skew\": \"SET_SKEW XY=141.446354,141.396354,100.000000\"");
}

// The S500 model's C0Y = −1108.5, B0Z = 455.0, A0Z = −520.9 µrad (samples/model/s500.conf):
// xy = −tan C0Y = 0.001108500, xz = tan B0Z = 0.000455000, yz = −tan A0Z / cos B0Z = 0.000520900.
TEST(VolcompExportKlipper, FromAModelFile) {
  ScratchDir dir("export_klipper_model");
  const std::string out = dir / "skew.cfg";
  const auto r = RunCli({"export", "klipper", "--model", SamplePath("model/s500.conf"), "-o", out,
                         "--profile", "s500"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(WithoutCommentLines(ReadFile(out), "# "),
            "#*# <---------------------- SAVE_CONFIG ---------------------->\n"
            "#*# DO NOT EDIT THIS BLOCK OR BELOW. The contents are auto-generated.\n"
            "#*#\n"
            "#*# [skew_correction s500]\n"
            "#*# xy_skew = 0.001108500\n"
            "#*# xz_skew = 0.000455000\n"
            "#*# yz_skew = 0.000520900\n");
  ExpectContains(r.out, "xy: C0Y = -1108.5 urad -> factor 0.001108500");
}

// An option replaces its plane of the model: XY 0, XZ and YZ from S500; the backlash of the
// hand-worked test samples/model/printer_x_lost_motion.csv is 97 / 5 = 19.4 µm = 0.0194 mm.
TEST(VolcompExportMarlin, ModelOptionAndTest) {
  ScratchDir dir("export_marlin");
  const std::string out = dir / "marlin.gcode";
  const auto r = RunCli({"export", "marlin", "--model", "s500", "--squareness-xy-urad", "0", "--x",
                         SamplePath("model/printer_x_lost_motion.csv"), "-o", out, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(WithoutCommentLines(ReadFile(out), ";"),
            "G21 ; millimetres: M852 and M425 read their values as lengths (G20 would scale them)\n"
            "M852 I0.000000000 J0.000455000 K0.000520900\n"
            "M425 F1 X0.0194\n"
            "M500 ; store the settings (EEPROM_SETTINGS)\n");
  ExpectContains(r.out, "\"source\": \"--squareness-xy-urad\"");
  ExpectContains(r.out, "\"source\": \"model s500 (B0Z)\"");
  ExpectContains(r.out, "\"backlash_um\": 19.4");
  ExpectContains(r.out, "\"reversal_max_um\": 21");
}

// Over S = 200 mm: XY = tan(−500 µrad)·200 = −0.1000000 mm; backlash 0.0194 mm.
TEST(VolcompExportReprap, M556AndM425) {
  ScratchDir dir("export_reprap");
  const std::string out = dir / "skew.g";
  const auto r = RunCli({"export", "reprap", "--squareness-xy-urad", "-500", "--length-mm", "200",
                         "--y", SamplePath("model/printer_x_lost_motion.csv"), "-o", out});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(WithoutCommentLines(ReadFile(out), ";"), "M556 S200.000 X-0.1000000\nM425 Y0.0194\n");
}

TEST(VolcompExportGrblhal, BacklashSettings) {
  ScratchDir dir("export_grblhal");
  const std::string out = dir / "grblhal.txt";
  const auto r = RunCli({"export", "grblhal", "--z", SamplePath("model/printer_x_lost_motion.csv"),
                         "-o", out, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(WithoutCommentLines(ReadFile(out), ";"), "$162=0.01940\n");
  ExpectContains(r.out, "\"number\": 162");
}

// samples/model/positioning_x.csv has its reverse deviations 4 µm below the forward ones: no lost
// motion to add. Refused, nothing written; --negate-tests takes the instrument's sign as reversed.
TEST(VolcompExportGrblhal, ReverseBelowForwardIsRefused) {
  ScratchDir dir("export_grblhal_refused");
  const std::string out = dir / "grblhal.txt";
  const std::string test = SamplePath("model/positioning_x.csv");
  const auto r = RunCli({"export", "grblhal", "--x", test, "-o", out});
  EXPECT_EQ(r.code, 1);
  ExpectContains(r.err, "X backlash -4.010 um");
  ExpectContains(r.err, "grblHAL takes a backlash >= 0");
  EXPECT_FALSE(std::ifstream(out).good());
  const auto n = RunCli({"export", "grblhal", "--x", test, "--negate-tests", "-o", out});
  EXPECT_EQ(n.code, 0) << n.err;
  ExpectContains(ReadFile(out), "$160=0.00401\n");
}

TEST(VolcompExportHobby, Refusals) {
  ScratchDir dir("export_hobby_refusals");
  const std::string out = dir / "out";
  const std::string test = SamplePath("model/printer_x_lost_motion.csv");
  // Nothing to export, or an option the firmware has no use for: usage (2).
  EXPECT_EQ(RunCli({"export", "klipper", "-o", out}).code, 2);
  EXPECT_EQ(RunCli({"export", "marlin", "-o", out}).code, 2);
  EXPECT_EQ(RunCli({"export", "klipper", "--squareness-xy-urad", "1", "--x", test, "-o", out}).code,
            2);
  EXPECT_EQ(RunCli({"export", "grblhal", "--squareness-xy-urad", "1", "--x", test, "-o", out}).code,
            2);
  // Values and limits: refused (1), naming them.
  auto r = RunCli({"export", "klipper", "--squareness-xy-urad", "200000", "-o", out});
  EXPECT_EQ(r.code, 1);
  ExpectContains(r.err, "C0Y = 200000.0 urad (--squareness-xy-urad) is beyond the plausible");
  r = RunCli({"export", "reprap", "--squareness-xy-urad", "1", "--length-mm", "0", "-o", out});
  EXPECT_EQ(r.code, 1);
  ExpectContains(r.err, "M556 S0.000: the length must be > 0 mm");
  r = RunCli({"export", "grblhal", "--w", test, "-o", out});
  EXPECT_EQ(r.code, 1);
  ExpectContains(r.err, "axis W: grblHAL takes the backlash of XYZABCUV");
  r = RunCli({"export", "marlin", "--a", test, "-o", out});
  EXPECT_EQ(r.code, 1);
  ExpectContains(r.err, "Marlin's M425 takes the backlash of XYZ");
  EXPECT_FALSE(std::ifstream(out).good());
}

}  // namespace
}  // namespace volcomp
