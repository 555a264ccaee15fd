// Reading checks: values that cannot be readings are refused with their line; implausible
// magnitudes and Grubbs outliers are warned about with their line. Student's t and Grubbs'
// critical values against published tables.
#include "volcomp/metrology/reading_checks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "test_support.hpp"
#include "volcomp/metrology/diagonal.hpp"
#include "volcomp/metrology/positioning_csv.hpp"
#include "volcomp/metrology/positioning_eval.hpp"
#include "volcomp/metrology/statistics.hpp"

namespace volcomp::metrology {
namespace {

using testing::ExpectThrowWith;
using testing::RepoPath;

// Two-sided Student t quantiles t_{p, ν} from the standard table (e.g. NIST/SEMATECH
// e-Handbook §1.3.6.7.2; Abramowitz & Stegun table 26.10).
TEST(MetrologyStatistics, StudentTQuantilesMatchTheTable) {
  struct Row {
    double p;
    int dof;
    double t;
  };
  for (const Row& r : {Row{0.95, 1, 6.314}, Row{0.975, 1, 12.706}, Row{0.975, 10, 2.228},
                       Row{0.995, 8, 3.355}, Row{0.999, 3, 10.215}, Row{0.9995, 3, 12.924},
                       Row{0.975, 30, 2.042}, Row{0.995, 120, 2.617}}) {
    EXPECT_NEAR(StudentTQuantile(r.p, r.dof), r.t, 0.0015) << r.p << " " << r.dof;
    EXPECT_NEAR(StudentTCdf(r.t, r.dof), r.p, 5e-5);
    EXPECT_NEAR(StudentTQuantile(1.0 - r.p, r.dof), -r.t, 0.0015);
  }
}

// Critical values of Grubbs' test (G_10, two-sided) as tabulated in Grubbs (1969) and ASTM
// E178, as reproduced e.g. in the LibreTexts "Critical Values for Grubb's Test" appendix (whose
// α = 0.05 entry for n = 7 prints 2.202, a transposition of 2.020, and whose n = 15 row repeats
// the n = 14 value at α = 0.01; the true values are used here).
TEST(MetrologyStatistics, GrubbsCriticalValuesMatchThePublishedTable) {
  const double at_001[] = {1.155, 1.496, 1.764, 1.973, 2.139, 2.274,
                           2.387, 2.482, 2.564, 2.636, 2.699, 2.755};
  const double at_005[] = {1.155, 1.481, 1.715, 1.887, 2.020, 2.126,
                           2.215, 2.290, 2.355, 2.412, 2.462, 2.507};
  for (int n = 3; n <= 14; ++n) {
    EXPECT_NEAR(GrubbsCritical(n, 0.01), at_001[n - 3], 1e-3) << n;
    EXPECT_NEAR(GrubbsCritical(n, 0.05), at_005[n - 3], 1e-3) << n;
  }
  // No sample of n can exceed (n − 1)/√n; the critical value stays below it.
  for (int n = 3; n <= 30; ++n) EXPECT_LT(GrubbsCritical(n, 0.01), (n - 1) / std::sqrt(n));
}

std::string Csv(const std::string& column, const std::function<double(int, int, bool)>& value) {
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
  const PositioningData d = ReadPositioningCsv(tools::CsvTable::ParseString(csv, "w.csv"));
  return CheckReadings(d, GroupReadings(d, {}), {});
}

// Smooth readings with small run-to-run variation (no outliers): 2 µm per 100 mm, ±0.3 µm.
double Smooth(int t, int run, bool up) {
  const double scatter[] = {0.1, -0.3, 0.2, 0.0, -0.1};
  return 2.0 * t + (up ? 1.0 : -1.0) + scatter[(run + t) % 5];
}

TEST(MetrologyReadingChecks, CleanDataGivesNoWarning) {
  EXPECT_TRUE(Warnings(Csv("deviation_um", Smooth)).empty());
}

// The case: µm readings written under deviation_mm give a 1000× error (A = 18 004 µm for
// the GOST example); now the column, the line and the likely unit are named.
TEST(MetrologyReadingChecks, MicrometresInAMillimetreColumnAreNamed) {
  const auto w = Warnings(Csv("deviation_mm", Smooth));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("w.csv:"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("column \"deviation_mm\""), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("beyond the plausible 1000 µm"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("name the column deviation_um"), std::string::npos) << w[0];
  // The first reading above the bound is 2·1 + 1 + scatter ≥ 1 mm at target 100 mm (line 3).
  EXPECT_NE(w[0].find("w.csv:3:"), std::string::npos) << w[0];

  // The GOST worked example in a deviation_mm column, as in the issue.
  std::ifstream f(RepoPath("samples/metrology/gost27843_example_long.csv"));
  std::stringstream text;
  text << f.rdbuf();
  std::string csv = text.str();
  csv.replace(csv.find("deviation_um"), 12, "deviation_mm");
  const auto g = Warnings(csv);
  bool named = false;
  for (const auto& s : g) named = named || s.find("column \"deviation_mm\"") != std::string::npos;
  EXPECT_TRUE(named);
}

TEST(MetrologyReadingChecks, MillimetresInAMicrometreColumnAreNamed) {
  const auto w = Warnings(Csv("deviation_um", [](int t, int run, bool up) {
    return Smooth(t, run, up) * 1e-4;  // µm written as 0.1 nm units: all below 0.01
  }));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("every reading is below 0.01 µm"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("deviation_mm"), std::string::npos) << w[0];
}

TEST(MetrologyReadingChecks, GrubbsOutlierIsNamedWithItsLine) {
  // Target 500 mm ↓ run 3 reads 25 µm instead of about 9: line of that row.
  const std::string csv = Csv("deviation_um", [](int t, int run, bool up) {
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
    std::string csv = Csv(column, Smooth);
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
    ExpectThrowWith<tools::InputError>(
        [&] { ReadPositioningCsv(tools::CsvTable::ParseString(with(column, value), "n.csv")); },
        {"n.csv:3:", "column \"" + column + "\"", "cannot be a reading", "refused"});
  }
  for (const std::string value : {"inf", "nan", "1e400"}) {
    ExpectThrowWith<tools::InputError>(
        [&] {
          ReadPositioningCsv(tools::CsvTable::ParseString(with("deviation_um", value), "n.csv"));
        },
        {"n.csv:3:", "is not a number"});
  }
}

TEST(MetrologyDiagonalNames, FollowFromTheGeometry) {
  const auto body = DiagonalNameFor({10, 10, 10}, {390, 270, 190});
  ASSERT_TRUE(body);
  EXPECT_EQ(body->text, "-X-Y-Z");
  EXPECT_EQ(DiagonalFileToken(*body), "NNN");
  EXPECT_EQ(DiagonalNameFor({390, 10, 10}, {10, 270, 190})->text, "+X-Y-Z");
  EXPECT_EQ(DiagonalNameFor({10, 270, 190}, {390, 10, 10})->text, "-X+Y+Z");
  const auto face = DiagonalNameFor({400, 0, 300}, {0, 280, 300});
  ASSERT_TRUE(face);
  EXPECT_EQ(face->text, "+X-Y Z300");
  EXPECT_EQ(DiagonalFileToken(*face), "XY_PN_Z300");
  EXPECT_FALSE(DiagonalNameFor({0, 0, 0}, {100, 0, 0}));

  EXPECT_FALSE(DiagonalNameMismatch(*ParseDiagonalName("NNN"), {10, 10, 10}, {390, 270, 190}));
  const auto why =
      DiagonalNameMismatch(*ParseDiagonalName("+X+Y+Z"), {10, 10, 10}, {390, 270, 190});
  ASSERT_TRUE(why);
  EXPECT_NE(why->find("starts at the -X-Y-Z corner"), std::string::npos) << *why;
  EXPECT_TRUE(DiagonalNameMismatch(*ParseDiagonalName("+X-Y Z200"), {400, 0, 300}, {0, 280, 300}));
  EXPECT_FALSE(DiagonalNameMismatch(*ParseDiagonalName("+X-Y"), {400, 0, 300}, {0, 280, 300}));
}

}  // namespace
}  // namespace volcomp::metrology
