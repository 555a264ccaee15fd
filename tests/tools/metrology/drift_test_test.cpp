// The thermal drift test (metrology/drift_test.hpp): a hand-worked evaluation (drift, largest
// value, range, rate over the last hour, offset and slope components with interpolation in time,
// temperature rise) and every refusal of the reader, each naming its line and column.
#include "volcomp/metrology/drift_test.hpp"

#include <gtest/gtest.h>

#include <string>

#include "expected_value.hpp"

namespace volcomp::metrology {
namespace {

using testing::ExpectFailure;
using testing::ValueOf;

DriftRecord Read(const std::string& text) {
  return ValueOf(ReadDriftCsv(ValueOf(tools::CsvTable::ReadString(text, "d.csv"))));
}

Expected<DriftRecord> TryRead(const std::string& text) {
  return ReadDriftCsv(ValueOf(tools::CsvTable::ReadString(text, "d.csv")));
}

// Two points of X (0 and 100 mm), four readings each, the second point 60 s after the first.
//   X 0:   t 0, 1800, 3600, 5400   deviation 1, 2, 4, 5    drift 0, 1, 3, 4
//   X 100: t 60, 1860, 3660, 5460  deviation -1, -1, 0, 2  drift 0, 0, 1, 3
// one channel "a": 20.0 20.1 21.0 21.1 22.0 21.9 21.5 21.4 in time order.
const char* const kHandCase =
    "# machine: MILL-7\n"
    "time_s,axis,position_mm,deviation_um,T_a_C\n"
    "0,X,0,1,20.0\n"        // line 3
    "60,x,100,-1,20.1\n"    // line 4 (lower case axis)
    "1800,X,0,2,21.0\n"     // line 5
    "1860,X,100,-1,21.1\n"  // line 6
    "3600,X,0,4,22.0\n"
    "3660,X,100,0,21.9\n"
    "5400,X,0,5,21.5\n"
    "5460,X,100,2,21.4\n";

TEST(DriftTest, HandWorkedEvaluation) {
  const DriftRecord rec = Read(kHandCase);
  ASSERT_EQ(rec.axes.size(), 1u);
  ASSERT_EQ(rec.channels.size(), 1u);
  EXPECT_EQ(rec.channels[0].name, "a");
  EXPECT_EQ(rec.conditions.Find("machine").value_or(""), "MILL-7");
  const DriftEvaluation ev = EvaluateDrift(rec);
  EXPECT_EQ(ev.readings, 8u);
  EXPECT_DOUBLE_EQ(ev.start_s, 0);
  EXPECT_DOUBLE_EQ(ev.end_s, 5460);
  const DriftAxisResult& x = ev.axes[0];
  EXPECT_EQ(x.name, 'X');
  EXPECT_DOUBLE_EQ(x.mean_position_mm, 50);
  const DriftPointResult& p0 = x.points[0];
  EXPECT_EQ(p0.drift_um, (std::vector<double>{0, 1, 3, 4}));
  EXPECT_DOUBLE_EQ(p0.max_drift_um, 4);
  EXPECT_DOUBLE_EQ(p0.max_drift_time_s, 5400);
  EXPECT_DOUBLE_EQ(p0.range_um, 4);
  EXPECT_DOUBLE_EQ(p0.final_drift_um, 4);
  // The last hour: t >= 1800: drift 1, 3, 4 at 1800, 3600, 5400: mean t 3600, mean d 8/3,
  // Σ(t-t̄)(d-d̄) = -1800·(-5/3) + 1800·(4/3) = 5400, Σ(t-t̄)² = 2·1800² = 6 480 000:
  // 5400 / 6.48e6 µm/s = 3.0 µm/h.
  EXPECT_NEAR(p0.rate_um_per_h, 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(p0.rate_from_s, 1800);
  EXPECT_EQ(p0.rate_readings, 3u);
  const DriftPointResult& p1 = x.points[1];
  EXPECT_EQ(p1.drift_um, (std::vector<double>{0, 0, 1, 3}));
  EXPECT_DOUBLE_EQ(p1.max_drift_um, 3);
  EXPECT_DOUBLE_EQ(p1.range_um, 3);

  // Components at the first point's times within [60, 5400]: 1800, 3600, 5400. X 100's drift
  // interpolated: at 1800 between (60, 0) and (1860, 0): 0; at 3600 between (1860, 0) and
  // (3660, 1): 1740/1800 = 0.96667; at 5400 between (3660, 1) and (5460, 3): 1 + 2·0.96667.
  ASSERT_EQ(x.components.size(), 3u);
  const double f = 1740.0 / 1800.0;
  EXPECT_DOUBLE_EQ(x.components[0].time_s, 1800);
  EXPECT_NEAR(x.components[0].offset_um, 0.5, 1e-12);
  EXPECT_NEAR(x.components[0].slope_um_per_m, (0.0 - 1.0) / 100 * 1000, 1e-9);
  EXPECT_NEAR(x.components[1].offset_um, (3 + f) / 2, 1e-12);
  EXPECT_NEAR(x.components[1].slope_um_per_m, (f - 3) / 100 * 1000, 1e-9);
  ASSERT_TRUE(x.final_components.has_value());
  EXPECT_DOUBLE_EQ(x.final_components->time_s, 5400);
  EXPECT_NEAR(x.final_components->offset_um, (4 + 1 + 2 * f) / 2, 1e-12);
  EXPECT_NEAR(x.final_components->slope_um_per_m, (1 + 2 * f - 4) * 10, 1e-9);
  EXPECT_DOUBLE_EQ(x.max_offset->time_s, 5400);
  EXPECT_DOUBLE_EQ(x.max_slope->time_s, 3600);  // |f - 3|·10 = 20.3 is the largest

  ASSERT_EQ(ev.channels.size(), 1u);
  EXPECT_DOUBLE_EQ(ev.channels[0].first_C, 20.0);
  EXPECT_DOUBLE_EQ(ev.channels[0].last_C, 21.4);
  EXPECT_DOUBLE_EQ(ev.channels[0].min_C, 20.0);
  EXPECT_DOUBLE_EQ(ev.channels[0].max_C, 22.0);
  EXPECT_NEAR(ev.channels[0].rise_K, 1.4, 1e-12);
  EXPECT_TRUE(ev.warnings.empty());
}

TEST(DriftTest, ATestShorterThanAnHourTakesItsRateOverEveryReading) {
  // Drift 0, 1, 4 at 0, 600, 1200 s: slope 4/1200·... = Σ(t-600)(d-5/3) / Σ(t-600)² =
  // (-600·-5/3 + 600·7/3) / 720000 = 2400/720000 µm/s = 12 µm/h.
  const DriftEvaluation ev =
      EvaluateDrift(Read("time_s,axis,position_mm,deviation_um\n"
                         "0,Y,10,0\n1,Y,20,0\n600,Y,10,1\n601,Y,20,0\n1200,Y,10,4\n1201,Y,20,0\n"));
  EXPECT_NEAR(ev.axes[0].points[0].rate_um_per_h, 12.0, 1e-9);
  EXPECT_EQ(ev.axes[0].points[0].rate_readings, 3u);
  EXPECT_TRUE(ev.channels.empty());
}

TEST(DriftTest, ReadingsFarApartStillGiveARateFromTheLastTwo) {
  // Readings every 2 h: the last hour holds one; the rate is over the last two: 2 µm in 2 h.
  const DriftEvaluation ev =
      EvaluateDrift(Read("time_s,axis,position_mm,deviation_um\n"
                         "0,Z,0,0\n1,Z,5,0\n7200,Z,0,1\n7201,Z,5,0\n14400,Z,0,3\n14401,Z,5,0\n"));
  EXPECT_NEAR(ev.axes[0].points[0].rate_um_per_h, 1.0, 1e-12);
  EXPECT_EQ(ev.axes[0].points[0].rate_readings, 2u);
}

TEST(DriftTest, PointsWhoseReadingsNeverOverlapHaveNoComponentsAndAWarning) {
  const DriftEvaluation ev =
      EvaluateDrift(Read("time_s,axis,position_mm,deviation_um\n"
                         "0,X,0,0\n10,X,0,1\n20,X,50,0\n30,X,50,1\n"));
  EXPECT_TRUE(ev.axes[0].components.empty());
  EXPECT_FALSE(ev.axes[0].final_components.has_value());
  ASSERT_EQ(ev.warnings.size(), 1u);
  EXPECT_NE(ev.warnings[0].find("do not overlap"), std::string::npos);
}

TEST(DriftTest, LeastSquaresSlopeOfAHandCase) {
  // y = 2x + 1 with residuals +1, -2, +1 (sum 0, orthogonal to x - x̄): the slope stays 2.
  EXPECT_NEAR(LeastSquaresSlope({0, 1, 2}, {2, 1, 6}), 2.0, 1e-12);
  EXPECT_EQ(LeastSquaresSlope({3, 3}, {1, 2}), 0.0);
}

TEST(DriftTest, AMissingColumnIsNamedAtTheHeader) {
  ExpectFailure(TryRead("# date: today\ntime_s,axis,position_mm\n0,X,0\n"), Error::kInputInvalid,
                {"d.csv:2:", "missing column \"deviation_um\""});
}

TEST(DriftTest, AnUnknownColumnIsNamed) {
  ExpectFailure(TryRead("time_s,axis,position_mm,deviation_um,temp\n0,X,0,0,1\n"),
                Error::kInputInvalid, {"d.csv:1:", "unknown column \"temp\"", "T_<name>_C"});
}

TEST(DriftTest, ChannelNamesMustBeGivenOnceAndBeWords) {
  ExpectFailure(TryRead("time_s,axis,position_mm,deviation_um,T__C\n0,X,0,0,1\n"),
                Error::kInputInvalid, {"d.csv:1:", "column \"T__C\"", "channel name"});
  ExpectFailure(TryRead("time_s,axis,position_mm,deviation_um,T_a-b_C\n0,X,0,0,1\n"),
                Error::kInputInvalid, {"column \"T_a-b_C\""});
  // A channel given twice is a column given twice: the CSV reader refuses it.
  ExpectFailure(tools::CsvTable::ReadString(
                    "time_s,axis,position_mm,deviation_um,T_a_C,T_a_C\n0,X,0,0,1,1\n", "d.csv"),
                Error::kInputInvalid, {"d.csv:1:", "column \"T_a_C\" appears twice"});
}

TEST(DriftTest, NineChannelsAreTooMany) {
  std::string header = "time_s,axis,position_mm,deviation_um";
  std::string row = "0,X,0,0";
  for (int j = 0; j < 9; ++j) {
    header += ",T_c" + std::to_string(j) + "_C";
    row += ",20";
  }
  ExpectFailure(TryRead(header + "\n" + row + "\n"), Error::kInputInvalid,
                {"d.csv:1:", "column \"T_c8_C\"", "too many temperature channels", "8 at most"});
}

TEST(DriftTest, ANonNumericCellIsNamedWithLineAndColumn) {
  ExpectFailure(TryRead("time_s,axis,position_mm,deviation_um,T_a_C\n0,X,0,0,20\n"
                        "1,X,abc,0,20\n"),
                Error::kInputInvalid, {"d.csv:3:", "column \"position_mm\"", "\"abc\""});
  ExpectFailure(TryRead("time_s,axis,position_mm,deviation_um,T_a_C\n0,X,0,0,warm\n"),
                Error::kInputInvalid, {"d.csv:2:", "column \"T_a_C\"", "\"warm\""});
}

TEST(DriftTest, UnknownAndRotaryAxesAreRefused) {
  ExpectFailure(TryRead("time_s,axis,position_mm,deviation_um\n0,Q,0,0\n"), Error::kInputInvalid,
                {"d.csv:2:", "column \"axis\"", "\"Q\" is not an axis"});
  ExpectFailure(TryRead("time_s,axis,position_mm,deviation_um\n0,X,0,0\n1,B,0,0\n"),
                Error::kInputInvalid, {"d.csv:3:", "\"B\" is a rotary axis"});
}

TEST(DriftTest, AnAxisWithOnePointIsRefused) {
  ExpectFailure(TryRead("time_s,axis,position_mm,deviation_um\n0,X,0,0\n1,X,50,0\n2,Y,10,0\n"
                        "3,X,0,1\n4,X,50,1\n5,Y,10,1\n"),
                Error::kInputInvalid, {"d.csv:4:", "axis Y has one point (10 mm)", "2 or more"});
}

TEST(DriftTest, APointReadOnceIsRefused) {
  ExpectFailure(TryRead("time_s,axis,position_mm,deviation_um\n0,X,0,0\n1,X,50,0\n2,X,0,1\n"),
                Error::kInputInvalid, {"d.csv:3:", "point X 50 mm is read only once"});
}

TEST(DriftTest, TimeThatDoesNotIncreaseForAPointIsRefused) {
  ExpectFailure(
      TryRead("time_s,axis,position_mm,deviation_um\n100,X,0,0\n50,X,50,0\n"
              "100,X,0,1\n"),
      Error::kInputInvalid,
      {"d.csv:4:", "column \"time_s\"", "100 s does not follow 100 s", "X 0 mm (line 2)"});
}

}  // namespace
}  // namespace volcomp::metrology
