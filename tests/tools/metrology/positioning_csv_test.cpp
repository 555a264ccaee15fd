// Reading positioning CSV (positioning_csv.hpp), both layouts: every malformed file gives a
// failure (kInputInvalid) naming the file, the line and the problem.
#include "volcomp/metrology/positioning_csv.hpp"

#include <gtest/gtest.h>

#include "positioning_fixtures.hpp"
#include "test_support.hpp"
#include "volcomp/metrology/positioning_csv.hpp"

namespace volcomp::metrology {
namespace {

using testing::ExpectFailure;
using testing::GoodPositioningCsv;
using testing::LoadPositioning;
using testing::WithLine;

TEST(MetrologyPositioningInput, BadNumber) {
  ExpectFailure(LoadPositioning(WithLine(GoodPositioningCsv(), 3, "100,up,1,abc")),
                Error::kInputInvalid, {"p.csv:3:", "deviation_um", "\"abc\" is not a number"});
}

TEST(MetrologyPositioningInput, BadTarget) {
  ExpectFailure(LoadPositioning(WithLine(GoodPositioningCsv(), 4, "2OO,up,1,1.5")),
                Error::kInputInvalid, {"p.csv:4:", "target_mm", "not a number"});
}

TEST(MetrologyPositioningInput, BadDirection) {
  ExpectFailure(LoadPositioning(WithLine(GoodPositioningCsv(), 2, "0,sideways,1,1.5")),
                Error::kInputInvalid, {"p.csv:2:", "\"sideways\" is not a direction"});
}

TEST(MetrologyPositioningInput, BadRunIndex) {
  ExpectFailure(LoadPositioning(WithLine(GoodPositioningCsv(), 2, "0,up,0,1.5")),
                Error::kInputInvalid, {"p.csv:2:", "run index \"0\""});
  ExpectFailure(LoadPositioning(WithLine(GoodPositioningCsv(), 2, "0,up,1.5,1.5")),
                Error::kInputInvalid, {"p.csv:2:", "run index \"1.5\""});
}

TEST(MetrologyPositioningInput, WrongFieldCount) {
  ExpectFailure(LoadPositioning(WithLine(GoodPositioningCsv(), 5, "200,down,1")),
                Error::kInputInvalid, {"p.csv:5:", "expected 4 fields, found 3"});
}

TEST(MetrologyPositioningInput, HeaderProblems) {
  ExpectFailure(LoadPositioning("target_mm,direction,run\n0,up,1\n"), Error::kInputInvalid,
                {"p.csv:1:", "missing measurement column"});
  ExpectFailure(
      LoadPositioning("target_mm,direction,run,deviation_um,measured_mm\n0,up,1,1,0.001\n"),
      Error::kInputInvalid, {"p.csv:1:", "two measurement columns"});
  ExpectFailure(LoadPositioning("target_mm,direction,run,deviation_arcsec\n0,up,1,1\n"),
                Error::kInputInvalid, {"p.csv:1:", "does not fit \"target_mm\""});
  ExpectFailure(LoadPositioning("target_mm,run,deviation_um\n0,1,1\n"), Error::kInputInvalid,
                {"p.csv:1:", "missing column \"direction\""});
  ExpectFailure(LoadPositioning("position,dir,value\n0,up,1\n"), Error::kInputInvalid,
                {"p.csv:1:", "unrecognised header"});
  ExpectFailure(LoadPositioning("# only a comment\n"), Error::kInputInvalid,
                {"p.csv", "no header line"});
  ExpectFailure(LoadPositioning("target_mm,direction,run,deviation_um\n"), Error::kInputInvalid,
                {"p.csv:1:", "no data rows"});
}

const char* const kWide =
    "deviation_um,1+,1-,2+,2-\n"
    "target_mm,0,0,150,150\n"
    "1,1,2,3,4\n2,1,2,3,4\n3,1,2,3,4\n4,1,2,3,4\n5,1,2,3,5\n";

TEST(MetrologyPositioningInput, WideLayout) {
  const PositioningSet s = testing::ValueOf(LoadPositioning(kWide));
  ASSERT_EQ(s.positions.size(), 2u);
  EXPECT_EQ(s.positions[1].down.size(), 5u);
  EXPECT_DOUBLE_EQ(s.positions[1].target, 150.0);
}

TEST(MetrologyPositioningInput, WideLayoutProblems) {
  ExpectFailure(LoadPositioning(std::string(kWide).replace(std::string(kWide).find("2-"), 2, "2x")),
                Error::kInputInvalid,
                {"p.csv:1:", "column \"2x\" is not a position and direction"});
  ExpectFailure(LoadPositioning(WithLine(kWide, 2, "target,0,0,150,150")), Error::kInputInvalid,
                {"p.csv:2:", "expected the row \"target_mm\""});
  ExpectFailure(LoadPositioning(WithLine(kWide, 2, "target_mm,0,0,150,151")), Error::kInputInvalid,
                {"p.csv:2:", "position 2 has target 151", "150"});
  ExpectFailure(LoadPositioning(WithLine(kWide, 4, "2,1,2,x,4")), Error::kInputInvalid,
                {"p.csv:4:", "column \"2+\": \"x\" is not a number"});
  ExpectFailure(LoadPositioning(WithLine(kWide, 5, "three,1,2,3,4")), Error::kInputInvalid,
                {"p.csv:5:", "run index \"three\""});
}

}  // namespace
}  // namespace volcomp::metrology
