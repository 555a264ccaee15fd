// Renishaw .rtl linear data files, tested against files written by hand from the syntax that
// ../shared/reference/data-formats.md §A1 reconstructs from four public parsers: the sample
// samples/metrology/renishaw_x.rtl (CRLF, as the format is written) and small files here, with
// the expected values read off the files by hand, and each refusal with the line it must name.
#include "volcomp/datasets/rtl_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "expected_value.hpp"
#include "file_contents.hpp"
#include "sample_path.hpp"
#include "volcomp/datasets/positioning_file.hpp"

namespace volcomp::datasets {
namespace {

using metrology::Direction;
using testing::ReadText;
using testing::SamplePath;
using testing::ValueOf;

// A small test: 3 targets, 2 runs (run 2 listed in travel order, last target first). Line n of
// the file is element n − 1.
std::vector<std::string> Small() {
  return {"HEADER::",
          "File type: Linear",
          "TARGET DATA::",
          "Target-count: 3",
          "Targets :",
          "0.0 10.0",
          "20.0",
          "RUNS::",
          "Run-count: 2",
          "DEVIATIONS::",
          "Run Target Data:",
          "1 1 0.5",
          "1 2 1.5",
          "1 3 2.5",
          "2 3 2.0",
          "2 2 1.0",
          "2 1 0.0",
          "ENVIRONMENT::",
          "Air temp : 20.1 20.3 0"};
}

std::string Text(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

std::string ErrorOf(const std::vector<std::string>& lines, const RtlOptions& o = RtlOptions{}) {
  const auto r = ParseRtl(Text(lines), "t.rtl", o);
  if (r.ok()) return "(accepted)";
  EXPECT_EQ(r.error().code, Error::kInputInvalid);
  return r.error().message;
}

// The failure message starts with "t.rtl:LINE: " and holds `what`.
void ExpectRefused(const std::vector<std::string>& lines, int line, const std::string& what) {
  const std::string e = ErrorOf(lines);
  EXPECT_EQ(e.rfind("t.rtl:" + std::to_string(line) + ": ", 0), 0u) << e;
  EXPECT_NE(e.find(what), std::string::npos) << e;
}

TEST(datasets_rtl, SampleFileReadByHand) {
  const std::string path = SamplePath("metrology/renishaw_x.rtl");
  const RtlTest t = ValueOf(ParseRtl(ReadText(path), path));
  EXPECT_TRUE(t.warnings.empty()) << t.warnings.front();
  EXPECT_EQ(t.targets_mm, (std::vector<double>{0, 100, 200, 300, 400}));
  EXPECT_EQ(t.run_count, 10);
  EXPECT_EQ(t.deviations_line, 26u);
  ASSERT_EQ(t.readings.readings.size(), 50u);
  EXPECT_EQ(t.readings.kind, metrology::AxisKind::kLinear);
  // Line 28 "1 1 -0.200": run 1 (odd, ↑), target 1 = 0 mm.
  const auto& first = t.readings.readings[0];
  EXPECT_EQ(first.line, 28u);
  EXPECT_EQ(first.target, 0.0);
  EXPECT_EQ(first.direction, Direction::kUp);
  EXPECT_EQ(first.run, 1);
  EXPECT_DOUBLE_EQ(first.deviation, -0.2);
  // Line 33 "2 5 -0.200": run 2 (even, ↓; the first ↓ run), target 5 = 400 mm.
  const auto& reverse = t.readings.readings[5];
  EXPECT_EQ(reverse.line, 33u);
  EXPECT_EQ(reverse.target, 400.0);
  EXPECT_EQ(reverse.direction, Direction::kDown);
  EXPECT_EQ(reverse.run, 1);
  EXPECT_DOUBLE_EQ(reverse.deviation, -0.2);
  // Line 77, the last row "10 1 -0.800": the fifth ↓ run at 0 mm.
  const auto& last = t.readings.readings.back();
  EXPECT_EQ(last.line, 77u);
  EXPECT_EQ(last.direction, Direction::kDown);
  EXPECT_EQ(last.run, 5);
  EXPECT_DOUBLE_EQ(last.deviation, -0.8);

  const RtlEnvironment& env = t.environment;
  ASSERT_TRUE(env.air_temperature_c && env.air_pressure_kpa && env.humidity_pct);
  EXPECT_DOUBLE_EQ(env.air_temperature_c->start, 20.33728);
  EXPECT_DOUBLE_EQ(env.air_temperature_c->end, 20.384956);
  EXPECT_DOUBLE_EQ(env.air_pressure_kpa->start, 99.039005);
  EXPECT_DOUBLE_EQ(env.humidity_pct->end, 46.893887);
  ASSERT_TRUE(env.material_temperature_c[0]);
  EXPECT_DOUBLE_EQ(env.material_temperature_c[0]->start, 20.203292);
  EXPECT_FALSE(env.material_temperature_c[1]);  // -10.000000: no sensor
  EXPECT_FALSE(env.material_temperature_c[2]);
  ASSERT_TRUE(env.expansion_ppm_per_c);
  EXPECT_DOUBLE_EQ(env.expansion_ppm_per_c->start, 11.7);
  EXPECT_EQ(env.date_time, "10:46 Dec 12 2016 to 11:01 Dec 12 2016");

  const auto& c = t.conditions;
  EXPECT_EQ(c.Find("machine"), "VMC-1");
  EXPECT_EQ(c.Find("axis"), "X");
  EXPECT_EQ(c.Find("date"), "12/12/2016");
  EXPECT_EQ(c.Find("operator"), "A. Operator");
  EXPECT_EQ(c.Find("serial no"), "4711");
  EXPECT_EQ(c.Find("air temperature C"), "20.33728 at start, 20.384956 at end");
  EXPECT_EQ(c.Find("material temperature C"), "20.203292 at start, 20.321342 at end");
  EXPECT_EQ(c.Find("expansion coefficient ppm/C"), "11.7");
  EXPECT_FALSE(c.Find("material temperature 2 C"));
}

// The sample's means, as designed when it was written: ↑ {0, 2, 4, 3, 1} µm and ↓ {−1, 1, 2.5,
// 2, 0} µm, each run offset by −0.2, −0.1, 0, +0.1, +0.2 µm.
TEST(datasets_rtl, SampleMeansPerTargetAndDirection) {
  const PositioningFile f = ValueOf(ReadPositioningFile(SamplePath("metrology/renishaw_x.rtl")));
  EXPECT_EQ(f.format, PositioningFormat::kRtl);
  const model::PositioningData d = ValueOf(PositioningMeans(f));
  EXPECT_FALSE(d.rotary);
  EXPECT_EQ(d.position, (std::vector<double>{0, 100, 200, 300, 400}));
  const std::vector<double> up = {0, 2, 4, 3, 1}, down = {-1, 1, 2.5, 2, 0};
  ASSERT_EQ(d.dev_forward.size(), 5u);
  ASSERT_EQ(d.dev_reverse.size(), 5u);
  for (std::size_t j = 0; j < 5; ++j) {
    EXPECT_NEAR(d.dev_forward[j], up[j], 1e-12) << j;
    EXPECT_NEAR(d.dev_reverse[j], down[j], 1e-12) << j;
  }
}

TEST(datasets_rtl, LfAndCrlfReadAlike) {
  const std::string lf = Text(Small());
  std::string crlf;
  for (char ch : lf) crlf += ch == '\n' ? std::string("\r\n") : std::string(1, ch);
  const RtlTest a = ValueOf(ParseRtl(lf, "a.rtl"));
  const RtlTest b = ValueOf(ParseRtl(crlf, "b.rtl"));
  ASSERT_EQ(a.readings.readings.size(), 6u);
  ASSERT_EQ(b.readings.readings.size(), 6u);
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_EQ(a.readings.readings[k].deviation, b.readings.readings[k].deviation);
    EXPECT_EQ(a.readings.readings[k].target, b.readings.readings[k].target);
  }
  // Targets over two lines (6 and 7), run 2 in travel order: no warning.
  EXPECT_EQ(a.targets_mm, (std::vector<double>{0, 10, 20}));
  EXPECT_TRUE(a.warnings.empty());
  EXPECT_EQ(a.conditions.Find("air temperature C"), "20.1 at start, 20.3 at end");
}

TEST(datasets_rtl, NegateFlipsTheSign) {
  RtlOptions o;
  o.negate = true;
  const RtlTest t = ValueOf(ParseRtl(Text(Small()), "t.rtl", o));
  EXPECT_EQ(t.readings.readings[1].deviation, -1.5);  // line 13 "1 2 1.5"
}

TEST(datasets_rtl, UnidirectionalRuns) {
  // Three runs, all in target order: read by parity, run 2 becomes ↓ and the row order does not
  // confirm it (warned); read forward, every run is ↑ with its own number.
  std::vector<std::string> lines = Small();
  lines[8] = "Run-count: 3";
  lines[14] = "2 1 0.1";
  lines[15] = "2 2 1.1";
  lines[16] = "2 3 2.1";
  lines.insert(lines.begin() + 17, {"3 1 0.2", "3 2 1.2", "3 3 2.2"});
  const RtlTest parity = ValueOf(ParseRtl(Text(lines), "u.rtl"));
  ASSERT_EQ(parity.warnings.size(), 1u);
  EXPECT_EQ(parity.warnings[0].rfind("u.rtl:10: run 2 (read as ↓ by run parity)", 0), 0u)
      << parity.warnings[0];
  EXPECT_NE(parity.warnings[0].find("--rtl-runs forward"), std::string::npos);
  RtlOptions forward;
  forward.runs = RtlRuns::kForward;
  const RtlTest f = ValueOf(ParseRtl(Text(lines), "u.rtl", forward));
  EXPECT_TRUE(f.warnings.empty());
  for (const auto& r : f.readings.readings) EXPECT_EQ(r.direction, Direction::kUp);
  EXPECT_EQ(f.readings.readings[8].run, 3);
  RtlOptions reverse;
  reverse.runs = RtlRuns::kReverse;
  const RtlTest rv = ValueOf(ParseRtl(Text(lines), "u.rtl", reverse));
  EXPECT_EQ(rv.readings.readings[0].direction, Direction::kDown);
}

TEST(datasets_rtl, ForwardRunListedBackwardsIsWarned) {
  std::vector<std::string> lines = Small();
  lines[11] = "1 3 2.5";  // run 1 (↑ by parity) listed from the last target down
  lines[13] = "1 1 0.5";
  const RtlTest t = ValueOf(ParseRtl(Text(lines), "t.rtl"));
  ASSERT_EQ(t.warnings.size(), 1u);
  EXPECT_EQ(t.warnings[0].rfind("t.rtl:10: run 1 (read as ↑) list", 0), 0u) << t.warnings[0];
}

TEST(datasets_rtl, MissingEnvironmentIsWarned) {
  std::vector<std::string> lines = Small();
  lines.resize(17);
  const RtlTest t = ValueOf(ParseRtl(Text(lines), "t.rtl"));
  ASSERT_EQ(t.warnings.size(), 1u);
  EXPECT_EQ(t.warnings[0].rfind("t.rtl:17: no ENVIRONMENT:: section", 0), 0u) << t.warnings[0];
  EXPECT_FALSE(t.conditions.Find("air temperature C"));
  EXPECT_EQ(t.readings.readings.size(), 6u);
}

TEST(datasets_rtl, ValueThatIsNotUtf8IsKeptVisibly) {
  std::vector<std::string> lines = Small();
  lines.insert(lines.begin() + 7, {"USER-TEXT::", "Machine: \xC4\xFA-1"});  // GBK bytes
  const RtlTest t = ValueOf(ParseRtl(Text(lines), "t.rtl"));
  EXPECT_EQ(t.conditions.Find("machine"), "?\?-1");
  ASSERT_EQ(t.warnings.size(), 1u);
  EXPECT_EQ(t.warnings[0].rfind("t.rtl:9: the value of \"machine\" is not UTF-8", 0), 0u)
      << t.warnings[0];
}

TEST(datasets_rtl, RefusalsNameTheLine) {
  std::vector<std::string> l;
  l = Small();
  l.insert(l.begin(), "target_mm,direction,run,deviation_um");
  ExpectRefused(l, 1, "before the first section");
  l = Small();
  l.insert(l.begin() + 17, {"TARGET DATA::"});  // a second axis appended
  ExpectRefused(l, 18, "a second TARGET DATA:: section (the first is on line 3)");
  l = Small();
  l[1] = "Sample rate: 50000";
  ExpectRefused(l, 2, "CARTO dynamic capture (.rtx)");
  l = Small();
  l[6] = "20.0 30.0";
  ExpectRefused(l, 7, "Targets lists more than the 3 targets of Target-count (line 4)");
  l = Small();
  l[6] = "Flags: 0";
  ExpectRefused(l, 5, "Targets lists 2 targets but Target-count (line 4) says 3");
  l = Small();
  l[6] = "20.0 abc";
  ExpectRefused(l, 7, "Targets (line 5): \"abc\" is not a number");
  l = Small();
  l[6] = "10.0";
  ExpectRefused(l, 7, "target 10.0 mm is listed twice (targets 2 and 3)");
  l = Small();
  l[3] = "Target-count: three";
  ExpectRefused(l, 4, "Target-count \"three\" is not a count");
  l = Small();
  l[12] = "1 2";
  ExpectRefused(l, 13, "is not a deviation row");
  l = Small();
  l[12] = "1 2 1,5";
  ExpectRefused(l, 13, "is not a deviation row");
  l = Small();
  l[12] = "3 2 1.5";
  ExpectRefused(l, 13, "run \"3\" is not a run from 1 to Run-count 2 (line 9)");
  l = Small();
  l[12] = "1 4 1.5";
  ExpectRefused(l, 13, "target \"4\" is not a target number from 1 to Target-count 3 (line 4)");
  l = Small();
  l[12] = "1 1 1.5";
  ExpectRefused(l, 13, "run 1 target 1 is given twice (also on line 12)");
  l = Small();
  l[12] = "1 2 2e9";
  ExpectRefused(l, 13, "cannot be a reading");
  l = Small();
  l.resize(15);  // truncated after "2 3 2.0"
  ExpectRefused(l, 15, "after 4 of the 6 that Run-count 2 (line 9) × Target-count 3 (line 4)");
  EXPECT_NE(ErrorOf(l).find("missing: run 2 targets 1, 2"), std::string::npos) << ErrorOf(l);
  l = Small();
  l[8] = "Runs: 2";
  ExpectRefused(l, 12, "deviation rows before the Run-count");
  l = Small();
  l.resize(9);
  ExpectRefused(l, 9, "end of file without a DEVIATIONS:: section");
  l = Small();
  l[18] = "Air temp : 20.1";
  ExpectRefused(l, 19, "an environment line holds a start and an end value");
  l = Small();
  l[18] = "Air temp : warm cold";
  ExpectRefused(l, 19, "an environment line holds a start and an end value");
  l = Small();
  l[1] = "no colon here";
  ExpectRefused(l, 2, "is not a \"Key: value\" line");
}

TEST(datasets_rtl, RecognisedByContent) {
  const std::string rtl = Text(Small());
  EXPECT_TRUE(LooksLikeRtl(rtl));
  EXPECT_TRUE(LooksLikeRtl("\xEF\xBB\xBF\r\n\r\nHEADER::\r\n"));
  EXPECT_FALSE(LooksLikeRtl("target_mm,direction,run,deviation_um\n0,up,1,1\n"));
  EXPECT_FALSE(LooksLikeRtl("# axis: X\nposition_mm,dev_forward_um\n"));
  EXPECT_FALSE(LooksLikeRtl(""));
  // By content, whatever the name says.
  const PositioningFile f = ValueOf(ReadPositioningText(rtl, "named.csv"));
  EXPECT_EQ(f.format, PositioningFormat::kRtl);
  EXPECT_EQ(f.readings_line, 10u);
  const PositioningFile c =
      ValueOf(ReadPositioningText("position_mm,dev_forward_um\n0,1\n10,2\n", "named.rtl"));
  EXPECT_EQ(c.format, PositioningFormat::kCsv);
  ASSERT_TRUE(c.means);
  EXPECT_EQ(c.means->dev_forward[1], 2);
  // Forced: an .rtl read as CSV and CSV read as .rtl are refused, not guessed at.
  PositioningReadOptions as_csv;
  as_csv.format = PositioningFormat::kCsv;
  EXPECT_FALSE(ReadPositioningText(rtl, "x.rtl", as_csv).ok());
  PositioningReadOptions as_rtl;
  as_rtl.format = PositioningFormat::kRtl;
  const auto r = ReadPositioningText("position_mm,dev_forward_um\n0,1\n10,2\n", "x.csv", as_rtl);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message.rfind("x.csv:1: ", 0), 0u) << r.error().message;
}

}  // namespace
}  // namespace volcomp::datasets
