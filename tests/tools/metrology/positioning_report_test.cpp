// Output of a positioning evaluation (positioning_report.hpp): the JSON holds every parameter with
// its location, and the text is laid out from that JSON.
#include "volcomp/metrology/positioning_report.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "test_support.hpp"

namespace volcomp::metrology {
namespace {

using testing::SamplePath;
using testing::ValueOf;

PositioningEvaluation Example() {
  PositioningTestOptions o;
  o.standards = {Standard::kGost27843, Standard::kIso230_2};
  return ValueOf(EvaluatePositioningTest(
      ValueOf(tools::CsvTable::ReadFile(SamplePath("metrology/gost27843_example_long.csv"))), o));
}

TEST(MetrologyPositioningReport, JsonHoldsEveryParameterWithItsLocation) {
  const PositioningEvaluation ev = Example();
  const tools::JsonValue j = PositioningJson(ev.results[0]);
  EXPECT_EQ(j.get("standard")->string, "GOST 27843-88");
  const tools::JsonValue* a = j.get("parameters")->get("A");
  ASSERT_NE(a, nullptr);
  EXPECT_NEAR(a->get("value")->number, 18.0039, 1e-4);
  EXPECT_EQ(a->get("max")->get("position")->integer, 2);
  EXPECT_EQ(a->get("max")->get("direction")->string, "down");
  EXPECT_EQ(a->get("min")->get("position")->integer, 9);
  EXPECT_EQ(j.get("positions")->array.size(), 11u);
  EXPECT_TRUE(j.get("positions")->array[0].get("reversal_B")->is_number());
}

TEST(MetrologyPositioningReport, TextIsLaidOutFromTheJson) {
  const PositioningEvaluation ev = Example();
  std::ostringstream text;
  WritePositioningEvaluationText(text, PositioningEvaluationJson(ev));
  const std::string t = text.str();
  EXPECT_EQ(
      t.rfind("positioning test: " + ev.source +
                  "\nlinear axis, 11 target positions, "
                  "directions: ↑↓\n\nGOST 27843-88 (S by formula (5), X̄ ± 3S), values in µm\n",
              0),
      0u)
      << t;
  EXPECT_NE(t.find("  A       = 18.00   max 6.88 at j=2 ↓ (150.71 mm), min -11.12 at j=9 ↑ "
                   "(1201.9 mm)\n"),
            std::string::npos)
      << t;
  EXPECT_NE(t.find("  R_max   = 13.49   at j=11 (1500.41 mm)\n"), std::string::npos) << t;
  EXPECT_NE(t.find("ISO 230-2:2014 (s with the n − 1 divisor, coverage factor 2), values in µm"),
            std::string::npos);
  EXPECT_NE(t.find("   1       0.000    -1.92   0.746     2.12   0.832    -4.04    4.48    4.99    "
                   "8.77    0.32   -4.16    4.62   -0.38\n"),
            std::string::npos)
      << t;
  // The location text of the JSON is the one of the result.
  const Extreme& max = ev.results[0].accuracy->max;
  EXPECT_EQ(
      DescribeLocation(ev.results[0], max),
      DescribeLocation(*PositioningJson(ev.results[0]).get("parameters")->get("A")->get("max"),
                       "target_mm", "mm"));
}

}  // namespace
}  // namespace volcomp::metrology
