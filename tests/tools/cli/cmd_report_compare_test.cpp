// `volcomp report compare` run as main() runs it: results of `evaluate ... --report` paired by
// name, every value before and after with its reduction as text or JSON, and the HTML page.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_runner.hpp"
#include "sample_path.hpp"
#include "temp_paths.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp {
namespace {

using testing::FreshTempPath;
using testing::RunCli;
using testing::SamplePath;

TEST(MetrologyCli, ReportCompareOfTheSameResultsShowsNoReduction) {
  const std::string dir = FreshTempPath("report_compare");
  for (const char* when : {"/before", "/after"}) {
    ASSERT_EQ(RunCli({"evaluate", "diagonal", SamplePath("metrology/diagonals.csv"), "--report",
                      dir + when})
                  .code,
              0);
  }
  auto r = RunCli({"report", "compare", dir + "/before", dir + "/after", "-o", dir + "/cmp"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("diagonal_NPP_PNP_PPN_PPP_XY_PN_Z200_XY_PP_Z200 (diagonal): before "),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("  body diagonals, values in µm\n    E_d   "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("0.0 %"), std::string::npos);
  EXPECT_NE(r.err.find("report written to " + dir + "/cmp/compare.html\n"), std::string::npos)
      << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/cmp/compare.html"));

  r = RunCli({"report", "compare", dir + "/before", dir + "/after", "-o", dir + "/cmp", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto doc = tools::ParseJson(r.out, "stdout");
  ASSERT_TRUE(doc.ok()) << doc.error().message;
  const auto& tables = doc->get("results")->array.at(0).get("tables")->array;
  ASSERT_FALSE(tables.empty());
  EXPECT_EQ(tables[0].get("title")->string, "body diagonals");
  EXPECT_EQ(tables[0].get("values")->array[0].get("reduction_pct")->number, 0.0);
  std::filesystem::remove_all(dir);
}

// Values stated with U keep it on the compare page: the diagonals' E_d with the U that
// cmd_evaluate_diagonal_test.cpp works by hand (1.68 µm) before, none after.
TEST(MetrologyCli, ReportCompareShowsEachValuesUncertainty) {
  const std::string dir = FreshTempPath("report_compare_u");
  ASSERT_EQ(RunCli({"evaluate", "diagonal", SamplePath("metrology/diagonals.csv"), "--report",
                    dir + "/before", "--instrument-u-um", "0.3", "--material-temperature-c", "20.5",
                    "--drift-range-um", "1"})
                .code,
            0);
  ASSERT_EQ(RunCli({"evaluate", "diagonal", SamplePath("metrology/diagonals.csv"), "--report",
                    dir + "/after"})
                .code,
            0);
  auto r = RunCli({"report", "compare", dir + "/before", dir + "/after", "-o", dir + "/cmp"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("E_d    19.99 ± 1.68 ->      19.99"), std::string::npos) << r.out;
  r = RunCli({"report", "compare", dir + "/before", dir + "/after", "-o", dir + "/cmp", "--json"});
  const auto doc = tools::ParseJson(r.out, "stdout");
  ASSERT_TRUE(doc.ok()) << doc.error().message;
  const auto& v = doc->get("results")->array.at(0).get("tables")->array.at(0).get("values")->array;
  EXPECT_NEAR(v.at(0).get("before_U")->number, 1.68, 0.005);
  EXPECT_TRUE(v.at(0).get("after_U")->is_null());
  std::filesystem::remove_all(dir);
}

TEST(MetrologyCli, ReportCompareBadArguments) {
  auto r = RunCli({"report", "compare", "a"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("missing required option --output"), std::string::npos) << r.err;
  r = RunCli({"report", "compare", "a", "-o", "x"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("give BEFORE and AFTER"), std::string::npos) << r.err;
  r = RunCli({"report", "compare", "/nonexistent/a", "/nonexistent/b", "-o", "x"});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("volcomp report compare: error: /nonexistent/a: no such report directory "
                       "or result file\n"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace volcomp
