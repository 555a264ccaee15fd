// Reading checks (reading_checks.hpp): implausible magnitudes and Grubbs outliers are warned about
// with their line; values that cannot be readings are refused by the reader with their line.
#include "volcomp/metrology/reading_checks.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "file_contents.hpp"
#include "test_support.hpp"
#include "volcomp/metrology/positioning_csv.hpp"

namespace volcomp::metrology {
namespace {

using testing::ExpectFailure;
using testing::SamplePath;
using testing::ValueOf;
using volcomp::testing::ReadText;

std::string ReadingsCsv(const std::string& column,
                        const std::function<double(int, int, bool)>& value) {
  std::ostringstream s;
  s << "target_mm,direction,run," << column << "\n";
  for (int run = 1; run <= 5; ++run) {
    for (int t = 0; t <= 10; ++t)
      s << t * 100 << ",up," << run << "," << value(t, run, true) << "\n";
    for (int t = 10; t >= 0; --t) {
      s << t * 100 << ",down," << run << "," << value(t, run, false) << "\n";
    }
  }
  return s.str();
}

std::vector<std::string> Warnings(const std::string& csv) {
  const PositioningData d = ValueOf(ReadPositioningCsv(testing::Csv(csv, "w.csv")));
  return CheckReadings(d, ValueOf(GroupReadings(d, {})), {});
}

// Smooth readings with small run-to-run variation (no outliers): 2 µm per 100 mm, ±0.3 µm.
double Smooth(int t, int run, bool up) {
  const double scatter[] = {0.1, -0.3, 0.2, 0.0, -0.1};
  return 2.0 * t + (up ? 1.0 : -1.0) + scatter[(run + t) % 5];
}

TEST(MetrologyReadingChecks, CleanDataGivesNoWarning) {
  EXPECT_TRUE(Warnings(ReadingsCsv("deviation_um", Smooth)).empty());
}

// The case: µm readings written under deviation_mm give a 1000× error (A = 18 004 µm for
// the GOST example); now the column, the line and the likely unit are named.
TEST(MetrologyReadingChecks, MicrometresInAMillimetreColumnAreNamed) {
  const auto w = Warnings(ReadingsCsv("deviation_mm", Smooth));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("w.csv:"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("column \"deviation_mm\""), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("beyond the plausible 1000 µm"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("name the column deviation_um"), std::string::npos) << w[0];
  // The first reading above the bound is 2·1 + 1 + scatter ≥ 1 mm at target 100 mm (line 3).
  EXPECT_NE(w[0].find("w.csv:3:"), std::string::npos) << w[0];

  // The GOST worked example in a deviation_mm column, as in the issue.
  std::string csv = ReadText(SamplePath("metrology/gost27843_example_long.csv"));
  csv.replace(csv.find("deviation_um"), 12, "deviation_mm");
  const auto g = Warnings(csv);
  bool named = false;
  for (const auto& s : g) named = named || s.find("column \"deviation_mm\"") != std::string::npos;
  EXPECT_TRUE(named);
}

TEST(MetrologyReadingChecks, MillimetresInAMicrometreColumnAreNamed) {
  const auto w = Warnings(ReadingsCsv("deviation_um", [](int t, int run, bool up) {
    return Smooth(t, run, up) * 1e-4;  // µm written as 0.1 nm units: all below 0.01
  }));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("every reading is below 0.01 µm"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("deviation_mm"), std::string::npos) << w[0];
}

TEST(MetrologyReadingChecks, GrubbsOutlierIsNamedWithItsLine) {
  // Target 500 mm ↓ run 3 reads 25 µm instead of about 9: line of that row.
  const std::string csv = ReadingsCsv("deviation_um", [](int t, int run, bool up) {
    return (t == 5 && run == 3 && !up) ? 25.0 : Smooth(t, run, up);
  });
  const auto w = Warnings(csv);
  ASSERT_EQ(w.size(), 1u);
  // Rows: header line 1; each run has 22 rows; run 3 starts at line 2 + 44; ↓ 500 is the 17th.
  EXPECT_NE(w[0].find("w.csv:" + std::to_string(2 + 44 + 16) + ":"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("reading 25 µm at target 500 mm ↓ run 3"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("Grubbs' test at 99 %"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("> 1.764 for n = 5"), std::string::npos) << w[0];
}

// The case: a reading of 1e300 gave exit 0 and "n/a". Values that cannot be readings
// are refused, naming the line, in every measurement column.
TEST(MetrologyReadingChecks, ValuesThatCannotBeReadingsAreRefused) {
  const auto with = [](const std::string& column, const std::string& value) {
    std::string csv = ReadingsCsv(column, Smooth);
    const std::size_t line3 = csv.find('\n', csv.find('\n') + 1) + 1;
    const std::size_t end = csv.find('\n', line3);
    csv.replace(line3, end - line3, "100,up,1," + value);
    return csv;
  };
  for (const auto& [column, value] :
       std::vector<std::pair<std::string, std::string>>{{"deviation_um", "1e300"},
                                                        {"deviation_mm", "1e300"},
                                                        {"measured_mm", "1e300"},
                                                        {"deviation_um", "-2e9"}}) {
    ExpectFailure(ReadPositioningCsv(testing::Csv(with(column, value), "n.csv")),
                  Error::kInputInvalid,
                  {"n.csv:3:", "column \"" + column + "\"", "cannot be a reading", "refused"});
  }
  for (const std::string value : {"inf", "nan", "1e400"}) {
    ExpectFailure(ReadPositioningCsv(testing::Csv(with("deviation_um", value), "n.csv")),
                  Error::kInputInvalid, {"n.csv:3:", "is not a number"});
  }
}

}  // namespace
}  // namespace volcomp::metrology
