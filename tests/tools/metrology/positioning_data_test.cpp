// Grouping and checking positioning readings (positioning_data.hpp): duplicates, targets that
// differ between runs, missing directions and too few approaches are failures naming the line;
// a missing reading of one run is a warning.
#include "volcomp/metrology/positioning_data.hpp"

#include <gtest/gtest.h>

#include "positioning_fixtures.hpp"
#include "test_support.hpp"
#include "volcomp/metrology/positioning_csv.hpp"

namespace volcomp::metrology {
namespace {

using testing::ExpectFailure;
using testing::GoodPositioningCsv;
using testing::LoadPositioning;
using testing::ValueOf;
using testing::WithLine;

TEST(MetrologyPositioningInput, GoodDataLoad) {
  const PositioningSet s = ValueOf(LoadPositioning(GoodPositioningCsv()));
  EXPECT_EQ(s.positions.size(), 3u);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(MetrologyPositioningInput, DuplicateReading) {
  // Line 8 repeats target 0 ↑ run 1 of line 2 (instead of run 2).
  ExpectFailure(LoadPositioning(WithLine(GoodPositioningCsv(), 8, "0,up,1,1.5")),
                Error::kInputInvalid, {"p.csv:8:", "run 1 is given twice (also on line 2)"});
}

TEST(MetrologyPositioningInput, PositionsDifferBetweenRuns) {
  // Run 3 ↑ goes to 100.2 instead of 100 (line 15).
  ExpectFailure(LoadPositioning(WithLine(GoodPositioningCsv(), 15, "100.2,up,3,1.5")),
                Error::kInputInvalid,
                {"p.csv:15:", "run 3 ↑ has target 100.2 mm where the other runs have 100 mm",
                 "same in every run"});
}

TEST(MetrologyPositioningInput, MissingDirectionAtOneTarget) {
  std::string csv = "target_mm,direction,run,deviation_um\n";
  for (int run = 1; run <= 5; ++run) {
    for (int t : {0, 100, 200}) csv += std::to_string(t) + ",up," + std::to_string(run) + ",1\n";
    for (int t : {200, 100}) csv += std::to_string(t) + ",down," + std::to_string(run) + ",1\n";
  }
  ExpectFailure(LoadPositioning(csv), Error::kInputInvalid,
                {"p.csv:2:", "missing direction", "target 0 mm has no ↓"});
}

TEST(MetrologyPositioningInput, FewerThanFiveApproaches) {
  std::string csv = GoodPositioningCsv();
  // Drop run 5 entirely (its 6 lines are the last ones).
  for (int i = 0; i < 6; ++i) csv.erase(csv.rfind('\n', csv.size() - 2) + 1);
  ExpectFailure(LoadPositioning(csv), Error::kInputInvalid,
                {"p.csv:2:", "target 0 mm ↑ has 4 approaches (runs 1, 2, 3, 4)", "at least 5"});
  GroupingOptions allow;
  allow.allow_few_approaches = true;
  const PositioningSet s = ValueOf(LoadPositioning(csv, allow));
  ASSERT_FALSE(s.warnings.empty());
  EXPECT_NE(s.warnings[0].find("has 4 approaches"), std::string::npos);
}

TEST(MetrologyPositioningInput, SingleApproachIsAlwaysAnError) {
  const std::string csv = "target_mm,direction,run,deviation_um\n0,up,1,1\n100,up,1,2\n";
  GroupingOptions allow;
  allow.allow_few_approaches = true;
  ExpectFailure(LoadPositioning(csv, allow), Error::kInputInvalid,
                {"p.csv:2:", "1 approach", "at least 2"});
}

TEST(MetrologyPositioningInput, MissingReadingOfOneRunIsAWarning) {
  std::string csv = GoodPositioningCsv();
  for (int run = 6; run <= 6; ++run) {
    for (int t : {0, 100, 200}) csv += std::to_string(t) + ",up,6,1.5\n";
    for (int t : {200, 0}) csv += std::to_string(t) + ",down,6,-1\n";
  }
  const PositioningSet s = ValueOf(LoadPositioning(csv));
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("target 100 mm ↓: no reading for run 6"), std::string::npos);
}

}  // namespace
}  // namespace volcomp::metrology
