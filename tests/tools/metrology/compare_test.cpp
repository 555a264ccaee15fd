// Before/after comparison (compare.hpp): results are paired by name and every parameter is listed
// with its reduction; what cannot be read or paired is a failure naming the path.
#include "volcomp/metrology/compare.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include "file_contents.hpp"
#include "temp_paths.hpp"
#include "test_support.hpp"

namespace volcomp::metrology {
namespace {

using testing::ExpectFailure;
using testing::ValueOf;
using volcomp::testing::FreshTempPath;
using volcomp::testing::WriteText;

// A diagonal result with E_i and B_i of one diagonal and of the body group.
std::string Diagonal(double e, double b) {
  std::ostringstream s;
  s << "{\"command\": \"evaluate diagonal\", \"source\": \"d.csv\", \"conditions\": {},"
    << " \"diagonals\": [{\"name\": \"+X+Y+Z\", \"E\": {\"value\": " << e
    << "}, \"B\": {\"value\": " << b << "}, \"positions\": []}],"
    << " \"body\": {\"E_d\": " << e << ", \"E_d_from\": \"+X+Y+Z\", \"B_d\": " << b
    << ", \"B_d_from\": \"+X+Y+Z\", \"diagonals\": 1}, \"faces\": {}}";
  return s.str();
}

TEST(MetrologyCompare, PairsByNameAndReportsReductions) {
  const std::string dir = FreshTempPath("compare_test_pairs");
  std::filesystem::create_directories(dir + "/before");
  std::filesystem::create_directories(dir + "/after");
  WriteText(dir + "/before/diagonal_PPP.json", Diagonal(10.0, 4.0));
  WriteText(dir + "/after/diagonal_PPP.json", Diagonal(1.0, 0.0));
  WriteText(dir + "/before/diagonal_NNN.json", Diagonal(2.0, 2.0));
  const Comparison c = ValueOf(
      CompareResults(ValueOf(LoadResults(dir + "/before")), ValueOf(LoadResults(dir + "/after"))));
  ASSERT_EQ(c.results.size(), 1u);
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings[0].find("diagonal_NNN"), std::string::npos);
  std::ostringstream text;
  WriteComparisonText(text, ComparisonJson(c));
  EXPECT_NE(text.str().find("diagonal_PPP (diagonal): before d.csv, after d.csv\n"),
            std::string::npos)
      << text.str();
  EXPECT_NE(text.str().find("    E_d         10.00 ->       1.00      90.0 %\n"), std::string::npos)
      << text.str();
  EXPECT_NE(text.str().find("    B_i          4.00 ->       0.00     100.0 %   +X+Y+Z\n"),
            std::string::npos)
      << text.str();
  std::filesystem::remove_all(dir);
}

TEST(MetrologyCompare, WhatCannotBeReadOrPairedIsAFailure) {
  const std::string dir = FreshTempPath("compare_test_bad");
  std::filesystem::create_directories(dir);
  ExpectFailure(LoadResults(dir + "/none"), Error::kInputInvalid,
                {dir + "/none: no such report directory or result file"});
  ExpectFailure(LoadResults(dir), Error::kInputInvalid,
                {dir + ": no positioning, diagonal or circular results (*.json)"});
  WriteText(dir + "/other.json", "{\"command\": \"evaluate rotary\"}");
  ExpectFailure(LoadResults(dir + "/other.json"), Error::kInputInvalid,
                {dir + "/other.json: not a result of `volcomp evaluate positioning`"});
  WriteText(dir + "/broken.json", "{\"command\": ");
  ExpectFailure(LoadResults(dir + "/broken.json"), Error::kInputInvalid,
                {dir + "/broken.json: line 1: "});
  WriteText(dir + "/a.json", Diagonal(1.0, 1.0));
  WriteText(dir + "/b.json", Diagonal(1.0, 1.0));
  const auto a = ValueOf(LoadResults(dir + "/a.json"));
  EXPECT_TRUE(CompareResults(a, ValueOf(LoadResults(dir + "/b.json"))).ok());  // two files pair
  std::vector<LoadedResult> renamed = a;
  renamed.push_back(renamed[0]);
  renamed[1].name = "z";
  std::vector<LoadedResult> other = ValueOf(LoadResults(dir + "/b.json"));
  other[0].name = "q";
  other.push_back(other[0]);
  other[1].name = "r";
  ExpectFailure(CompareResults(renamed, other), Error::kInputInvalid,
                {"no result appears both before and after"});
  std::filesystem::remove_all(dir);
}

// A circular test result: figures scaled by `k`, readings of a 4 µm ellipse (also scaled) at
// 8 angles per direction about a centre offset (3, −2) µm.
std::string Circular(double k, const std::string& uncertainty = "null") {
  std::ostringstream s;
  s << "{\"command\": \"evaluate circular\", \"source\": \"c.csv\", \"conditions\": {},"
    << " \"uncertainty\": " << uncertainty << ","
    << " \"G_cw_um\": " << 8 * k << ", \"G_ccw_um\": " << 7 * k << ", \"G_b_um\": " << 10 * k
    << ", \"H_um\": " << 4 * k << ", \"F_max_um\": " << 12 * k << ", \"F_min_um\": " << -5 * k
    << ", \"centre_offset_um\": {\"x\": 3, \"y\": -2}, \"mean_radius_deviation_um\": 1,"
    << " \"paths\": {";
  for (const char* d : {"cw", "ccw"}) {
    s << (d[1] == 'w' ? "" : ", ") << "\"" << d << "\": {\"angle_deg\": [";
    for (int j = 0; j < 8; ++j) s << (j ? ", " : "") << 45 * j;
    s << "], \"deviation_um\": [";
    for (int j = 0; j < 8; ++j) {
      const double t = 45 * j * 3.14159265358979323846 / 180;
      s << (j ? ", " : "") << 1 + 3 * std::cos(t) - 2 * std::sin(t) + 4 * k * std::cos(2 * t);
    }
    s << "]}";
  }
  s << "}}";
  return s.str();
}

// Each figure keeps its U: G and H the shape's, F the radial one; none where a test has none.
TEST(MetrologyCompare, CircularFiguresKeepTheirUncertainty) {
  const std::string dir = FreshTempPath("compare_test_circular_u");
  std::filesystem::create_directories(dir);
  WriteText(dir + "/before.json", Circular(1.0, R"({"shape_U_um": 0.8, "F_U_um": 1.3})"));
  WriteText(dir + "/after.json", Circular(0.25));
  const Comparison c = ValueOf(CompareResults(ValueOf(LoadResults(dir + "/before.json")),
                                              ValueOf(LoadResults(dir + "/after.json"))));
  ASSERT_EQ(c.results.size(), 1u);
  int checked = 0;
  for (const ComparedValue& v : c.results[0].tables.at(0).values) {
    ASSERT_TRUE(v.u_before.has_value()) << v.symbol;
    EXPECT_EQ(*v.u_before, v.symbol.rfind("F_", 0) == 0 ? 1.3 : 0.8) << v.symbol;
    EXPECT_FALSE(v.u_after.has_value()) << v.symbol;
    ++checked;
  }
  EXPECT_EQ(checked, 6);
  std::filesystem::remove_all(dir);
}

TEST(MetrologyCompare, CircularTestsBeforeAndAfter) {
  const std::string dir = FreshTempPath("compare_test_circular");
  std::filesystem::create_directories(dir);
  WriteText(dir + "/before.json", Circular(1.0));
  WriteText(dir + "/after.json", Circular(0.25));
  const Comparison c = ValueOf(CompareResults(ValueOf(LoadResults(dir + "/before.json")),
                                              ValueOf(LoadResults(dir + "/after.json"))));
  ASSERT_EQ(c.results.size(), 1u);
  EXPECT_EQ(c.results[0].kind, "circular");
  std::ostringstream text;
  WriteComparisonText(text, ComparisonJson(c));
  EXPECT_NE(text.str().find("  ISO 230-4 circular test, values in µm\n"), std::string::npos)
      << text.str();
  EXPECT_NE(text.str().find("    G(b)        10.00 ->       2.50      75.0 %\n"), std::string::npos)
      << text.str();
  EXPECT_NE(text.str().find("    F_min       -5.00 ->      -1.25      75.0 %\n"), std::string::npos)
      << text.str();
  // The overlay: four paths, each about its own centre with the mean removed, so only the
  // ellipse is left: 4 cos 2θ before (4 at 0°), 1 cos 2θ after.
  ASSERT_EQ(c.results[0].polars.size(), 1u);
  const ComparedPolar& p = c.results[0].polars[0];
  ASSERT_EQ(p.before.size(), 2u);
  ASSERT_EQ(p.after.size(), 2u);
  EXPECT_EQ(p.before[1].label, "before CCW");
  EXPECT_NEAR(p.before[0].value_um[0], 4.0, 1e-9);
  EXPECT_NEAR(p.before[0].value_um[2], -4.0, 1e-9);
  EXPECT_NEAR(p.after[1].value_um[0], 1.0, 1e-9);
  report::HtmlPage page("compare");
  AddComparisonSections(&page, c);
  const std::string html = page.Render();
  EXPECT_NE(html.find("after CCW"), std::string::npos);
  EXPECT_NE(html.find("<svg"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace volcomp::metrology
