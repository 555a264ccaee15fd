// A positioning test evaluated as `evaluate positioning` reports it (positioning_evaluation.hpp):
// every standard asked for, the warnings of all of them once each, the report's name.
#include "volcomp/metrology/positioning_evaluation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "test_support.hpp"

namespace volcomp::metrology {
namespace {

using testing::Csv;
using testing::ExpectFailure;
using testing::SamplePath;
using testing::ValueOf;

tools::CsvTable Example() {
  return ValueOf(tools::CsvTable::ReadFile(SamplePath("metrology/gost27843_example_long.csv")));
}

TEST(MetrologyPositioningEvaluation, BothStandardsOfTheGostExample) {
  PositioningTestOptions o;
  o.standards = {Standard::kGost27843, Standard::kIso230_2};
  const PositioningEvaluation ev = ValueOf(EvaluatePositioningTest(Example(), o));
  EXPECT_EQ(ev.kind, AxisKind::kLinear);
  EXPECT_EQ(ev.positions, 11u);
  EXPECT_TRUE(ev.has_up && ev.has_down);
  ASSERT_EQ(ev.results.size(), 2u);
  EXPECT_EQ(ev.results[0].standard, Standard::kGost27843);
  EXPECT_NEAR(ev.results[0].accuracy->value, 18.0039, 1e-4);
  EXPECT_EQ(ev.results[1].standard, Standard::kIso230_2);
  EXPECT_EQ(PositioningReportName(ev), "positioning_gost27843_example_long");
}

TEST(MetrologyPositioningEvaluation, WarningsOfEveryStandardOnceAndTheAxisNamesTheReport) {
  // 6 targets on 1000 mm: GOST §2.7 warns (11 on any 2 m), ISO 230-2 does not; only ↑ approaches
  // (a warning of both standards, listed once).
  std::string csv = "# axis: Z 2\ntarget_mm,direction,run,deviation_um\n";
  for (int run = 1; run <= 5; ++run) {
    for (int t = 0; t <= 1000; t += 200) {
      csv +=
          std::to_string(t) + ",up," + std::to_string(run) + "," + std::to_string(run % 3) + "\n";
    }
  }
  PositioningTestOptions o;
  o.standards = {Standard::kGost27843, Standard::kIso230_2};
  const PositioningEvaluation ev = ValueOf(EvaluatePositioningTest(Csv(csv, "z.csv"), o));
  EXPECT_EQ(PositioningReportName(ev), "positioning_Z_2");
  const auto count = [&](const std::string& part) {
    return std::count_if(ev.warnings.begin(), ev.warnings.end(),
                         [&](const std::string& w) { return w.find(part) != std::string::npos; });
  };
  EXPECT_EQ(count("unidirectional values only"), 1);
  EXPECT_EQ(count("§2.7"), 1);
  EXPECT_EQ(count("no measurement uncertainty"), 1);
  EXPECT_EQ(ev.results[0].warnings.size(), 3u);  // GOST: one direction, §2.7, no instrument
  EXPECT_EQ(ev.results[1].warnings.size(), 2u);  // ISO: one direction, no instrument
}

TEST(MetrologyPositioningEvaluation, InputProblemsAreFailuresNamingTheLine) {
  ExpectFailure(
      EvaluatePositioningTest(Csv("target_mm,direction,run,deviation_um\n0,up,1,x\n", "bad.csv"),
                              PositioningTestOptions{}),
      Error::kInputInvalid, {"bad.csv:2:", "\"x\" is not a number"});
  PositioningTestOptions range;
  range.sigma = SigmaMethod::kRange;
  std::string eleven = "target_mm,direction,run,deviation_um\n";
  for (int run = 1; run <= 11; ++run) {
    for (int t : {0, 100}) eleven += std::to_string(t) + ",up," + std::to_string(run) + ",1\n";
  }
  ExpectFailure(EvaluatePositioningTest(Csv(eleven, "r.csv"), range), Error::kInputInvalid,
                {"r.csv:2:", "range method"});
}

}  // namespace
}  // namespace volcomp::metrology
