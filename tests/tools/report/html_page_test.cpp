// HTML report pages (html_page.hpp): a self-contained file; failures name the path.
#include "volcomp/report/html_page.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace volcomp::report {
namespace {

TEST(ReportHtmlPage, WritesASelfContainedFile) {
  HtmlPage page("Report <1>");
  page.Heading(2, "Section");
  page.Table({"a", "b"}, {{"1", "x&y"}, {"2"}});
  page.Figure("<svg></svg>", "caption");
  const std::string dir =
      (std::filesystem::temp_directory_path() / "volcomp_report_test" / "sub").string();
  std::filesystem::remove_all(dir);
  const auto prepared = PrepareReportPath(dir, "page.html");
  ASSERT_TRUE(prepared.ok()) << prepared.error().message;
  const std::string path = *prepared;
  ASSERT_TRUE(page.WriteFile(path).ok());
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  const std::string s = ss.str();
  EXPECT_NE(s.find("<title>Report &lt;1&gt;</title>"), std::string::npos);
  EXPECT_NE(s.find("<td>x&amp;y</td>"), std::string::npos);
  EXPECT_NE(s.find("<td>2</td><td></td>"), std::string::npos);
  EXPECT_NE(s.find("<figure>\n<svg></svg>"), std::string::npos);
  // A directory that cannot be created (a file is in the way), a file that cannot be written.
  const auto blocked = PrepareReportPath(path + "/x", "page.html");
  ASSERT_FALSE(blocked.ok());
  EXPECT_EQ(blocked.error().code, Error::kIoError);
  EXPECT_EQ(blocked.error().message.rfind(path + "/x: cannot create report directory", 0), 0u)
      << blocked.error().message;
  const Outcome unwritable = page.WriteFile(dir + "/no/such/dir/page.html");
  ASSERT_FALSE(unwritable.ok());
  EXPECT_EQ(unwritable.error().code, Error::kIoError);
  EXPECT_EQ(unwritable.error().message, dir + "/no/such/dir/page.html: cannot open for writing");
  std::filesystem::remove_all(std::filesystem::temp_directory_path() / "volcomp_report_test");
}

}  // namespace
}  // namespace volcomp::report
