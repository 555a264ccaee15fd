// Before/after comparison (compare.hpp): results are paired by name and every parameter is listed
// with its reduction; what cannot be read or paired is a failure naming the path.
#include "volcomp/metrology/compare.hpp"

#include <gtest/gtest.h>

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
                {dir + ": no positioning or diagonal results (*.json)"});
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

}  // namespace
}  // namespace volcomp::metrology
