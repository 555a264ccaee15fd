// Plan checks of a positioning test (positioning_checks.hpp): the cardinal angles of GOST 27843
// §2.8 and the target counts of GOST 27843 §2.7 and ISO 230-2.
#include "volcomp/metrology/positioning_checks.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "test_support.hpp"
#include "volcomp/metrology/positioning_csv.hpp"

namespace volcomp::metrology {
namespace {

using testing::Csv;
using testing::ValueOf;

PositioningSet Grouped(const std::string& csv, const std::string& source) {
  return ValueOf(GroupReadings(ValueOf(ReadPositioningCsv(Csv(csv, source))), GroupingOptions{}));
}

std::string RotaryCsv(const std::vector<int>& angles) {
  std::string csv = "target_deg,direction,run,deviation_arcsec\n";
  for (int run = 1; run <= 5; ++run) {
    for (int a : angles) csv += std::to_string(a) + ",up," + std::to_string(run) + ",1\n";
  }
  return csv;
}

TEST(MetrologyPositioningChecks, CardinalAnglesPresentGiveNoWarning) {
  EXPECT_TRUE(CheckCardinalAngles(Grouped(RotaryCsv({0, 90, 180, 270}), "r.csv")).empty());
}

TEST(MetrologyPositioningChecks, CardinalAnglesOfGost27843Section2_8) {
  const auto w = CheckCardinalAngles(Grouped(RotaryCsv({0, 60, 120, 180, 240, 300}), "r.csv"));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("§2.8"), std::string::npos);
  EXPECT_NE(w[0].find("90°, 270°"), std::string::npos);
}

std::string Positions(const std::vector<double>& targets) {
  std::string csv = "target_mm,direction,run,deviation_um\n";
  for (int run = 1; run <= 5; ++run) {
    for (double t : targets) csv += std::to_string(t) + ",+," + std::to_string(run) + ",0\n";
  }
  return csv;
}

TEST(MetrologyPositioningChecks, TooFewPositionsForTheAxisLength) {
  // 6 positions on 1000 mm: GOST §2.7 wants 11 on any 2 m; ISO 230-2 wants 5 per metre (5).
  std::vector<double> six = {0, 200, 400, 600, 800, 1000};
  auto set = Grouped(Positions(six), "a");
  auto w = CheckPositionCount(set, Standard::kGost27843, std::nullopt);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("§2.7"), std::string::npos);
  EXPECT_TRUE(CheckPositionCount(set, Standard::kIso230_2, std::nullopt).empty());
  // The same 6 targets on a declared 2000 mm axis: ISO needs 10.
  w = CheckPositionCount(set, Standard::kIso230_2, 2000.0);
  ASSERT_FALSE(w.empty());
  EXPECT_NE(w[0].find("at least 10"), std::string::npos);
  // A 4 m axis with 11 evenly spread targets has only ~6 in any 2 m window.
  std::vector<double> eleven;
  for (int i = 0; i <= 10; ++i) eleven.push_back(400.0 * i);
  set = Grouped(Positions(eleven), "b");
  w = CheckPositionCount(set, Standard::kGost27843, std::nullopt);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("any 2 m"), std::string::npos);
  // 21 targets every 100 mm on 2 m: fine for both.
  std::vector<double> many;
  for (int i = 0; i <= 20; ++i) many.push_back(100.0 * i);
  set = Grouped(Positions(many), "c");
  EXPECT_TRUE(CheckPositionCount(set, Standard::kGost27843, std::nullopt).empty());
  EXPECT_TRUE(CheckPositionCount(set, Standard::kIso230_2, std::nullopt).empty());
}

}  // namespace
}  // namespace volcomp::metrology
