// Malformed positioning CSV: every case gives an InputError naming the file, the line and the
// problem.
#include <gtest/gtest.h>

#include "test_support.hpp"
#include "volcomp/metrology/positioning_csv.hpp"
#include "volcomp/metrology/positioning_eval.hpp"

namespace volcomp::metrology {
namespace {

using testing::ExpectThrowWith;
using tools::InputError;

// Five full runs over targets 0, 100, 200 in both directions (rows: header + 30).
std::string Good() {
  std::string csv = "target_mm,direction,run,deviation_um\n";
  for (int run = 1; run <= 5; ++run) {
    for (int t : {0, 100, 200}) csv += std::to_string(t) + ",up," + std::to_string(run) + ",1.5\n";
    for (int t : {200, 100, 0}) csv += std::to_string(t) + ",down," + std::to_string(run) + ",-1\n";
  }
  return csv;
}

// Replaces line `line` (1-based) of `csv`.
std::string WithLine(const std::string& csv, int line, const std::string& text) {
  std::string out;
  int n = 0;
  std::size_t pos = 0;
  while (pos < csv.size()) {
    const std::size_t end = csv.find('\n', pos);
    ++n;
    out += (n == line ? text : csv.substr(pos, end - pos)) + "\n";
    pos = end + 1;
  }
  return out;
}

PositioningSet Load(const std::string& csv, GroupingOptions o = {}) {
  return GroupReadings(ReadPositioningCsv(tools::CsvTable::ParseString(csv, "p.csv")), o);
}

TEST(MetrologyPositioningInput, GoodDataLoad) {
  const PositioningSet s = Load(Good());
  EXPECT_EQ(s.positions.size(), 3u);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(MetrologyPositioningInput, BadNumber) {
  ExpectThrowWith<InputError>([] { Load(WithLine(Good(), 3, "100,up,1,abc")); },
                              {"p.csv:3:", "deviation_um", "\"abc\" is not a number"});
}

TEST(MetrologyPositioningInput, BadTarget) {
  ExpectThrowWith<InputError>([] { Load(WithLine(Good(), 4, "2OO,up,1,1.5")); },
                              {"p.csv:4:", "target_mm", "not a number"});
}

TEST(MetrologyPositioningInput, BadDirection) {
  ExpectThrowWith<InputError>([] { Load(WithLine(Good(), 2, "0,sideways,1,1.5")); },
                              {"p.csv:2:", "\"sideways\" is not a direction"});
}

TEST(MetrologyPositioningInput, BadRunIndex) {
  ExpectThrowWith<InputError>([] { Load(WithLine(Good(), 2, "0,up,0,1.5")); },
                              {"p.csv:2:", "run index \"0\""});
  ExpectThrowWith<InputError>([] { Load(WithLine(Good(), 2, "0,up,1.5,1.5")); },
                              {"p.csv:2:", "run index \"1.5\""});
}

TEST(MetrologyPositioningInput, WrongFieldCount) {
  ExpectThrowWith<InputError>([] { Load(WithLine(Good(), 5, "200,down,1")); },
                              {"p.csv:5:", "expected 4 fields, found 3"});
}

TEST(MetrologyPositioningInput, DuplicateReading) {
  // Line 8 repeats target 0 ↑ run 1 of line 2 (instead of run 2).
  ExpectThrowWith<InputError>([] { Load(WithLine(Good(), 8, "0,up,1,1.5")); },
                              {"p.csv:8:", "run 1 is given twice (also on line 2)"});
}

TEST(MetrologyPositioningInput, PositionsDifferBetweenRuns) {
  // Run 3 ↑ goes to 100.2 instead of 100 (line 15).
  ExpectThrowWith<InputError>(
      [] { Load(WithLine(Good(), 15, "100.2,up,3,1.5")); },
      {"p.csv:15:", "run 3 ↑ has target 100.2 mm where the other runs have 100 mm",
       "same in every run"});
}

TEST(MetrologyPositioningInput, MissingDirectionAtOneTarget) {
  std::string csv = "target_mm,direction,run,deviation_um\n";
  for (int run = 1; run <= 5; ++run) {
    for (int t : {0, 100, 200}) csv += std::to_string(t) + ",up," + std::to_string(run) + ",1\n";
    for (int t : {200, 100}) csv += std::to_string(t) + ",down," + std::to_string(run) + ",1\n";
  }
  ExpectThrowWith<InputError>([&] { Load(csv); },
                              {"p.csv:2:", "missing direction", "target 0 mm has no ↓"});
}

TEST(MetrologyPositioningInput, FewerThanFiveApproaches) {
  std::string csv = Good();
  // Drop run 5 entirely (its 6 lines are the last ones).
  for (int i = 0; i < 6; ++i) csv.erase(csv.rfind('\n', csv.size() - 2) + 1);
  ExpectThrowWith<InputError>(
      [&] { Load(csv); },
      {"p.csv:2:", "target 0 mm ↑ has 4 approaches (runs 1, 2, 3, 4)", "at least 5"});
  GroupingOptions allow;
  allow.allow_few_approaches = true;
  const PositioningSet s = Load(csv, allow);
  ASSERT_FALSE(s.warnings.empty());
  EXPECT_NE(s.warnings[0].find("has 4 approaches"), std::string::npos);
}

TEST(MetrologyPositioningInput, SingleApproachIsAlwaysAnError) {
  const std::string csv = "target_mm,direction,run,deviation_um\n0,up,1,1\n100,up,1,2\n";
  GroupingOptions allow;
  allow.allow_few_approaches = true;
  ExpectThrowWith<InputError>([&] { Load(csv, allow); }, {"p.csv:2:", "1 approach", "at least 2"});
}

TEST(MetrologyPositioningInput, MissingReadingOfOneRunIsAWarning) {
  std::string csv = Good();
  for (int run = 6; run <= 6; ++run) {
    for (int t : {0, 100, 200}) csv += std::to_string(t) + ",up,6,1.5\n";
    for (int t : {200, 0}) csv += std::to_string(t) + ",down,6,-1\n";
  }
  const PositioningSet s = Load(csv);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("target 100 mm ↓: no reading for run 6"), std::string::npos);
}

TEST(MetrologyPositioningInput, HeaderProblems) {
  ExpectThrowWith<InputError>([] { Load("target_mm,direction,run\n0,up,1\n"); },
                              {"p.csv:1:", "missing measurement column"});
  ExpectThrowWith<InputError>(
      [] { Load("target_mm,direction,run,deviation_um,measured_mm\n0,up,1,1,0.001\n"); },
      {"p.csv:1:", "two measurement columns"});
  ExpectThrowWith<InputError>([] { Load("target_mm,direction,run,deviation_arcsec\n0,up,1,1\n"); },
                              {"p.csv:1:", "does not fit \"target_mm\""});
  ExpectThrowWith<InputError>([] { Load("target_mm,run,deviation_um\n0,1,1\n"); },
                              {"p.csv:1:", "missing column \"direction\""});
  ExpectThrowWith<InputError>([] { Load("position,dir,value\n0,up,1\n"); },
                              {"p.csv:1:", "unrecognised header"});
  ExpectThrowWith<InputError>([] { Load("# only a comment\n"); }, {"p.csv", "no header line"});
  ExpectThrowWith<InputError>([] { Load("target_mm,direction,run,deviation_um\n"); },
                              {"p.csv:1:", "no data rows"});
}

const char* const kWide =
    "deviation_um,1+,1-,2+,2-\n"
    "target_mm,0,0,150,150\n"
    "1,1,2,3,4\n2,1,2,3,4\n3,1,2,3,4\n4,1,2,3,4\n5,1,2,3,5\n";

TEST(MetrologyPositioningInput, WideLayout) {
  const PositioningSet s = Load(kWide);
  ASSERT_EQ(s.positions.size(), 2u);
  EXPECT_EQ(s.positions[1].down.size(), 5u);
  EXPECT_DOUBLE_EQ(s.positions[1].target, 150.0);
}

TEST(MetrologyPositioningInput, WideLayoutProblems) {
  ExpectThrowWith<InputError>(
      [] { Load(std::string(kWide).replace(std::string(kWide).find("2-"), 2, "2x")); },
      {"p.csv:1:", "column \"2x\" is not a position and direction"});
  ExpectThrowWith<InputError>([] { Load(WithLine(kWide, 2, "target,0,0,150,150")); },
                              {"p.csv:2:", "expected the row \"target_mm\""});
  ExpectThrowWith<InputError>([] { Load(WithLine(kWide, 2, "target_mm,0,0,150,151")); },
                              {"p.csv:2:", "position 2 has target 151", "150"});
  ExpectThrowWith<InputError>([] { Load(WithLine(kWide, 4, "2,1,2,x,4")); },
                              {"p.csv:4:", "column \"2+\": \"x\" is not a number"});
  ExpectThrowWith<InputError>([] { Load(WithLine(kWide, 5, "three,1,2,3,4")); },
                              {"p.csv:5:", "run index \"three\""});
}

TEST(MetrologyPositioningInput, RangeMethodNeedsFiveToTenApproaches) {
  std::string csv = "target_mm,direction,run,deviation_um\n";
  for (int run = 1; run <= 11; ++run) {
    for (int t : {0, 100}) csv += std::to_string(t) + ",up," + std::to_string(run) + ",1\n";
  }
  const PositioningSet s = Load(csv);
  EvaluationOptions o;
  o.sigma = SigmaMethod::kRange;
  ExpectThrowWith<InputError>([&] { EvaluatePositioning(s, o); },
                              {"p.csv:2:", "range method", "has 11"});
}

}  // namespace
}  // namespace volcomp::metrology
