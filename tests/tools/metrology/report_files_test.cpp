// The files of a metrology report (report_files.hpp): safe names, and the page and its JSON
// written into a directory, with failures that name the path.
#include "volcomp/metrology/report_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "file_contents.hpp"
#include "temp_paths.hpp"
#include "test_support.hpp"

namespace volcomp::metrology {
namespace {

using testing::ValueOf;
using volcomp::testing::FreshTempPath;
using volcomp::testing::ReadText;

TEST(MetrologyReportFiles, SafeNamesAndStems) {
  EXPECT_EQ(SafeName("X"), "X");
  EXPECT_EQ(SafeName("X axis/2"), "X_axis_2");
  EXPECT_EQ(SafeName("+X-Y.1"), "+X-Y.1");
  EXPECT_EQ(SafeName(""), "_");
  EXPECT_EQ(SourceStem("data/x_readings.csv"), "x_readings");
  EXPECT_EQ(SourceStem("-"), "stdin");
  EXPECT_EQ(SourceStem("<stdin>"), "stdin");
}

TEST(MetrologyReportFiles, WritesThePageAndItsJsonAndSaysWhenItReplacesOne) {
  const std::string root = FreshTempPath("report_files_test");
  const std::string dir = root + "/r";
  report::HtmlPage page("P");
  ReportFiles files = ValueOf(WriteReportFiles(page, "{}\n", dir, "positioning_X"));
  EXPECT_EQ(files.html, dir + "/positioning_X.html");
  EXPECT_EQ(files.json, dir + "/positioning_X.json");
  EXPECT_FALSE(files.replaced);
  EXPECT_EQ(ReadText(files.json), "{}\n");
  EXPECT_NE(ReadText(files.html).find("<title>P</title>"), std::string::npos);
  files = ValueOf(WriteReportFiles(page, "", dir, "positioning_X"));
  EXPECT_TRUE(files.replaced);
  EXPECT_TRUE(files.json.empty());

  // A file where the directory should be.
  const auto blocked = WriteReportFiles(page, "{}", files.html + "/sub", "x");
  ASSERT_FALSE(blocked.ok());
  EXPECT_EQ(blocked.error().code, Error::kIoError);
  EXPECT_NE(blocked.error().message.find(files.html + "/sub: cannot create report directory"),
            std::string::npos)
      << blocked.error().message;
  std::filesystem::remove_all(root);
}

}  // namespace
}  // namespace volcomp::metrology
