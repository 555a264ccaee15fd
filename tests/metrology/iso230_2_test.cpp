// ISO 230-2:2014 and GOST 27843 parameters on a small data set whose values are worked out by
// hand in the comments (three targets, five runs).
#include <gtest/gtest.h>

#include <cmath>

#include "volcomp/metrology/positioning_checks.hpp"
#include "volcomp/metrology/positioning_csv.hpp"
#include "volcomp/metrology/positioning_eval.hpp"

namespace volcomp::metrology {
namespace {

// P=0:   ↑ 1 2 3 4 5 (x̄ 3, s √2.5)   ↓ -1 ×5 (x̄ -1, s 0)          B = 4
// P=100: ↑ 0 ×5      (x̄ 0, s 0)       ↓ 2 ×5  (x̄ 2, s 0)           B = -2
// P=200: ↑ -2 ×5     (x̄ -2, s 0)      ↓ -3 -1 -3 -1 -2 (x̄ -2, s 1)  B = 0
std::string HandData() {
  const double up[3][5] = {{1, 2, 3, 4, 5}, {0, 0, 0, 0, 0}, {-2, -2, -2, -2, -2}};
  const double down[3][5] = {{-1, -1, -1, -1, -1}, {2, 2, 2, 2, 2}, {-3, -1, -3, -1, -2}};
  std::string csv = "target_mm,direction,run,deviation_um\n";
  for (int run = 0; run < 5; ++run) {
    for (int j = 0; j < 3; ++j) {
      csv += std::to_string(100 * j) + ",+," + std::to_string(run + 1) + "," +
             std::to_string(up[j][run]) + "\n";
    }
    for (int j = 2; j >= 0; --j) {
      csv += std::to_string(100 * j) + ",-," + std::to_string(run + 1) + "," +
             std::to_string(down[j][run]) + "\n";
    }
  }
  return csv;
}

PositioningResult Evaluate(const std::string& csv, Standard s) {
  const auto set = GroupReadings(ReadPositioningCsv(tools::CsvTable::ParseString(csv, "hand.csv")),
                                 GroupingOptions{});
  EvaluationOptions o;
  o.standard = s;
  return EvaluatePositioning(set, o);
}

TEST(MetrologyIso230_2, HandComputedParameters) {
  const PositioningResult r = Evaluate(HandData(), Standard::kIso230_2);
  const double s1 = std::sqrt(2.5);
  EXPECT_DOUBLE_EQ(r.k, 2.0);
  EXPECT_NEAR(r.systematic_up->value, 5.0, 1e-12);             // 3 - (-2)
  EXPECT_NEAR(r.systematic_down->value, 4.0, 1e-12);           // 2 - (-2)
  EXPECT_NEAR(r.systematic->value, 5.0, 1e-12);                // max(3, 2) - min(-2, -2)
  EXPECT_NEAR(r.mean_bidirectional_range->value, 3.0, 1e-12);  // x̄_j = 1, 1, -2
  EXPECT_NEAR(r.accuracy_up->value, 3 + 2 * s1 + 2, 1e-12);
  EXPECT_NEAR(r.accuracy_down->value, 2 + 4, 1e-12);  // max 2 (P100), min -2 - 2·1 (P200)
  EXPECT_NEAR(r.accuracy->value, 3 + 2 * s1 + 4, 1e-12);
  EXPECT_NEAR(r.repeatability_up->value, 4 * s1, 1e-12);
  EXPECT_NEAR(r.repeatability_down->value, 4.0, 1e-12);
  // R_1 = max(2s↑ + 2s↓ + |B|, 4s↑, 4s↓) = max(2√2.5 + 4, 4√2.5) = 2√2.5 + 4.
  EXPECT_NEAR(r.repeatability->value, 2 * s1 + 4, 1e-12);
  EXPECT_EQ(r.repeatability->position, 0u);
  EXPECT_NEAR(r.reversal_max->value, 4.0, 1e-12);
  EXPECT_NEAR(*r.reversal_mean, 2.0 / 3.0, 1e-12);
  EXPECT_EQ(r.systematic->min.position, 2u);
  EXPECT_EQ(r.accuracy->min.direction, Direction::kDown);
}

TEST(MetrologyGost27843, SameDataWithThreeSigma) {
  const PositioningResult r = Evaluate(HandData(), Standard::kGost27843);
  const double s1 = std::sqrt(2.5);
  EXPECT_NEAR(r.accuracy->value, 3 + 3 * s1 + 5, 1e-12);  // min is -2 - 3·1 at P200↓
  // Formula (8): 6S↑ = 6√2.5 = 9.49 exceeds 3S↑ + 3S↓ + |B| = 8.74 at P0.
  EXPECT_NEAR(r.repeatability->value, 6 * s1, 1e-12);
  // Formula (9): (ΣR↑ + ΣR↓)/2m = (6√2.5 + 6)/6.
  EXPECT_NEAR(*r.mean_repeatability, (6 * s1 + 6) / 6.0, 1e-12);
}

TEST(MetrologyPositioning, UnidirectionalDataGiveUnidirectionalValuesOnly) {
  const std::string csv =
      "target_mm,direction,run,deviation_um\n"
      "0,up,1,1\n0,up,2,2\n0,up,3,3\n0,up,4,4\n0,up,5,5\n"
      "50,up,1,0\n50,up,2,0\n50,up,3,0\n50,up,4,0\n50,up,5,0\n";
  const PositioningResult r = Evaluate(csv, Standard::kIso230_2);
  EXPECT_FALSE(r.bidirectional);
  EXPECT_FALSE(r.accuracy.has_value());
  EXPECT_FALSE(r.repeatability.has_value());
  EXPECT_FALSE(r.accuracy_down.has_value());
  ASSERT_TRUE(r.accuracy_up.has_value());
  EXPECT_NEAR(r.accuracy_up->value, 4 * std::sqrt(2.5), 1e-12);  // (3 + 2s) - (3 - 2s)
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings[0].find("unidirectional"), std::string::npos);
}

TEST(MetrologyPositioning, RotaryMeasuredAnglesWrapAndConvertToArcSeconds) {
  std::string csv = "target_deg,direction,run,measured_deg\n";
  for (int run = 1; run <= 5; ++run) {
    for (int a : {0, 90, 180, 270}) {
      const double measured = a == 0 ? 359.999 : a + 0.001;  // -3.6″ and +3.6″
      csv +=
          std::to_string(a) + ",up," + std::to_string(run) + "," + std::to_string(measured) + "\n";
    }
  }
  const auto data = ReadPositioningCsv(tools::CsvTable::ParseString(csv, "rot.csv"));
  EXPECT_EQ(data.kind, AxisKind::kRotary);
  const auto set = GroupReadings(data, GroupingOptions{});
  const PositioningResult r = EvaluatePositioning(set, EvaluationOptions{});
  EXPECT_NEAR(r.positions[0].up->mean, -3.6, 1e-6);
  EXPECT_NEAR(r.positions[1].up->mean, 3.6, 1e-6);
  EXPECT_TRUE(CheckCardinalAngles(set).empty());
}

TEST(MetrologyPositioningChecks, CardinalAnglesOfGost27843Section2_8) {
  std::string csv = "target_deg,direction,run,deviation_arcsec\n";
  for (int run = 1; run <= 5; ++run) {
    for (int a : {0, 60, 120, 180, 240, 300}) {
      csv += std::to_string(a) + ",up," + std::to_string(run) + ",1\n";
    }
  }
  const auto set = GroupReadings(ReadPositioningCsv(tools::CsvTable::ParseString(csv, "r.csv")),
                                 GroupingOptions{});
  const auto w = CheckCardinalAngles(set);
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
  auto set = GroupReadings(ReadPositioningCsv(tools::CsvTable::ParseString(Positions(six), "a")),
                           GroupingOptions{});
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
  set = GroupReadings(ReadPositioningCsv(tools::CsvTable::ParseString(Positions(eleven), "b")),
                      GroupingOptions{});
  w = CheckPositionCount(set, Standard::kGost27843, std::nullopt);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("any 2 m"), std::string::npos);
  // 21 targets every 100 mm on 2 m: fine for both.
  std::vector<double> many;
  for (int i = 0; i <= 20; ++i) many.push_back(100.0 * i);
  set = GroupReadings(ReadPositioningCsv(tools::CsvTable::ParseString(Positions(many), "c")),
                      GroupingOptions{});
  EXPECT_TRUE(CheckPositionCount(set, Standard::kGost27843, std::nullopt).empty());
  EXPECT_TRUE(CheckPositionCount(set, Standard::kIso230_2, std::nullopt).empty());
}

}  // namespace
}  // namespace volcomp::metrology
