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

// Inch columns against their hand-converted mm twins (1 in = 25.4 mm = 25400 µm, 1 µin =
// 0.0254 µm): the same targets in mm and deviations in µm.
void ExpectTwins(const std::string& inch, const std::string& mm) {
  const auto table_in = testing::ValueOf(tools::CsvTable::ReadString(inch, "in.csv"));
  const auto table_mm = testing::ValueOf(tools::CsvTable::ReadString(mm, "mm.csv"));
  const PositioningData a = testing::ValueOf(ReadPositioningCsv(table_in));
  const PositioningData b = testing::ValueOf(ReadPositioningCsv(table_mm));
  EXPECT_TRUE(a.read_in_inches);
  EXPECT_FALSE(b.read_in_inches);
  ASSERT_EQ(a.readings.size(), b.readings.size());
  for (std::size_t i = 0; i < a.readings.size(); ++i) {
    EXPECT_NEAR(a.readings[i].target, b.readings[i].target, 1e-12) << i;
    EXPECT_NEAR(a.readings[i].deviation, b.readings[i].deviation, 1e-9) << i;
    EXPECT_EQ(a.readings[i].direction, b.readings[i].direction) << i;
  }
}

TEST(MetrologyPositioningInput, InchColumnsAreReadAsMillimetres) {
  ExpectTwins("target_in,direction,run,deviation_uin\n0,up,1,100\n1,up,1,-50\n2,down,1,250\n",
              "target_mm,direction,run,deviation_um\n0,up,1,2.54\n25.4,up,1,-1.27\n"
              "50.8,down,1,6.35\n");
  ExpectTwins("target_in,direction,run,deviation_in\n0,up,1,0.0001\n1,up,1,-0.0002\n",
              "target_mm,direction,run,deviation_um\n0,up,1,2.54\n25.4,up,1,-5.08\n");
  // measured_in against inch or mm targets: 1.0002 in at 1 in (25.4 mm) is +0.0002 in = 5.08 µm.
  ExpectTwins("target_in,direction,run,measured_in\n1,up,1,1.0002\n2,up,1,1.9999\n",
              "target_mm,direction,run,deviation_um\n25.4,up,1,5.08\n50.8,up,1,-2.54\n");
  ExpectTwins("target_mm,direction,run,measured_in\n25.4,up,1,1.0002\n",
              "target_mm,direction,run,deviation_um\n25.4,up,1,5.08\n");
  ExpectTwins("deviation_in,1+,1-,2+\ntarget_in,0,0,1\n1,0.0001,-0.0002,0\n",
              "deviation_um,1+,1-,2+\ntarget_mm,0,0,25.4\n1,2.54,-5.08,0\n");
}

TEST(MetrologyPositioningInput, InchColumnProblems) {
  ExpectFailure(LoadPositioning("target_mm,target_in,direction,run,deviation_um\n0,0,up,1,1\n"),
                Error::kInputInvalid, {"p.csv:1:", "both \"target_mm\" and \"target_in\""});
  ExpectFailure(LoadPositioning("target_in,direction,run,deviation_arcsec\n0,up,1,1\n"),
                Error::kInputInvalid, {"p.csv:1:", "does not fit \"target_in\""});
  ExpectFailure(LoadPositioning("deviation_arcsec,1+\ntarget_in,0\n1,1\n"), Error::kInputInvalid,
                {"p.csv:2:", "expected the row \"target_deg\""});
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
