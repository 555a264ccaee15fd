// Reading positioning CSV (positioning_csv.hpp), both layouts: every malformed file gives a
// failure (kInputInvalid) naming the file, the line and the problem.
#include "volcomp/metrology/positioning_csv.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"
#include "volcomp/metrology/positioning_csv.hpp"

namespace volcomp::metrology {
namespace {

using testing::ExpectFailure;
using testing::Must;

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

// Reads `csv` (named p.csv) and its positioning readings, grouped and checked.
Expected<PositioningSet> Load(const std::string& csv, GroupingOptions o = {}) {
  VOLCOMP_TRY_ASSIGN(const tools::CsvTable table, tools::CsvTable::ReadString(csv, "p.csv"));
  VOLCOMP_TRY_ASSIGN(const PositioningData data, ReadPositioningCsv(table));
  return GroupReadings(data, o);
}

TEST(MetrologyPositioningInput, BadNumber) {
  ExpectFailure(Load(WithLine(Good(), 3, "100,up,1,abc")), Error::kInputInvalid,
                {"p.csv:3:", "deviation_um", "\"abc\" is not a number"});
}

TEST(MetrologyPositioningInput, BadTarget) {
  ExpectFailure(Load(WithLine(Good(), 4, "2OO,up,1,1.5")), Error::kInputInvalid,
                {"p.csv:4:", "target_mm", "not a number"});
}

TEST(MetrologyPositioningInput, BadDirection) {
  ExpectFailure(Load(WithLine(Good(), 2, "0,sideways,1,1.5")), Error::kInputInvalid,
                {"p.csv:2:", "\"sideways\" is not a direction"});
}

TEST(MetrologyPositioningInput, BadRunIndex) {
  ExpectFailure(Load(WithLine(Good(), 2, "0,up,0,1.5")), Error::kInputInvalid,
                {"p.csv:2:", "run index \"0\""});
  ExpectFailure(Load(WithLine(Good(), 2, "0,up,1.5,1.5")), Error::kInputInvalid,
                {"p.csv:2:", "run index \"1.5\""});
}

TEST(MetrologyPositioningInput, WrongFieldCount) {
  ExpectFailure(Load(WithLine(Good(), 5, "200,down,1")), Error::kInputInvalid,
                {"p.csv:5:", "expected 4 fields, found 3"});
}

TEST(MetrologyPositioningInput, HeaderProblems) {
  ExpectFailure(Load("target_mm,direction,run\n0,up,1\n"), Error::kInputInvalid,
                {"p.csv:1:", "missing measurement column"});
  ExpectFailure(Load("target_mm,direction,run,deviation_um,measured_mm\n0,up,1,1,0.001\n"),
                Error::kInputInvalid, {"p.csv:1:", "two measurement columns"});
  ExpectFailure(Load("target_mm,direction,run,deviation_arcsec\n0,up,1,1\n"), Error::kInputInvalid,
                {"p.csv:1:", "does not fit \"target_mm\""});
  ExpectFailure(Load("target_mm,run,deviation_um\n0,1,1\n"), Error::kInputInvalid,
                {"p.csv:1:", "missing column \"direction\""});
  ExpectFailure(Load("position,dir,value\n0,up,1\n"), Error::kInputInvalid,
                {"p.csv:1:", "unrecognised header"});
  ExpectFailure(Load("# only a comment\n"), Error::kInputInvalid, {"p.csv", "no header line"});
  ExpectFailure(Load("target_mm,direction,run,deviation_um\n"), Error::kInputInvalid,
                {"p.csv:1:", "no data rows"});
}

const char* const kWide =
    "deviation_um,1+,1-,2+,2-\n"
    "target_mm,0,0,150,150\n"
    "1,1,2,3,4\n2,1,2,3,4\n3,1,2,3,4\n4,1,2,3,4\n5,1,2,3,5\n";

TEST(MetrologyPositioningInput, WideLayout) {
  const PositioningSet s = Must(Load(kWide));
  ASSERT_EQ(s.positions.size(), 2u);
  EXPECT_EQ(s.positions[1].down.size(), 5u);
  EXPECT_DOUBLE_EQ(s.positions[1].target, 150.0);
}

TEST(MetrologyPositioningInput, WideLayoutProblems) {
  ExpectFailure(Load(std::string(kWide).replace(std::string(kWide).find("2-"), 2, "2x")),
                Error::kInputInvalid,
                {"p.csv:1:", "column \"2x\" is not a position and direction"});
  ExpectFailure(Load(WithLine(kWide, 2, "target,0,0,150,150")), Error::kInputInvalid,
                {"p.csv:2:", "expected the row \"target_mm\""});
  ExpectFailure(Load(WithLine(kWide, 2, "target_mm,0,0,150,151")), Error::kInputInvalid,
                {"p.csv:2:", "position 2 has target 151", "150"});
  ExpectFailure(Load(WithLine(kWide, 4, "2,1,2,x,4")), Error::kInputInvalid,
                {"p.csv:4:", "column \"2+\": \"x\" is not a number"});
  ExpectFailure(Load(WithLine(kWide, 5, "three,1,2,3,4")), Error::kInputInvalid,
                {"p.csv:5:", "run index \"three\""});
}

}  // namespace
}  // namespace volcomp::metrology
