// The report library: number formatting, escaping, ticks, SVG/HTML output.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "volcomp/report/format.hpp"
#include "volcomp/report/html_page.hpp"
#include "volcomp/report/polar_chart.hpp"
#include "volcomp/report/scale.hpp"
#include "volcomp/report/svg.hpp"
#include "volcomp/report/xy_chart.hpp"

namespace volcomp::report {
namespace {

std::size_t Count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

TEST(ReportFormat, FixedAndSigned) {
  EXPECT_EQ(FormatFixed(18.00395, 2), "18.00");
  EXPECT_EQ(FormatFixed(-0.001, 2), "0.00");
  EXPECT_EQ(FormatFixed(-1.5, 1), "-1.5");
  EXPECT_EQ(FormatFixed(1.0 / 0.0, 2), "n/a");
  EXPECT_EQ(FormatSigned(0.5, 1), "+0.5");
  EXPECT_EQ(FormatSigned(-0.5, 1), "-0.5");
}

TEST(ReportFormat, EscapeXml) {
  EXPECT_EQ(EscapeXml("a<b & \"c\"'"), "a&lt;b &amp; &quot;c&quot;&#39;");
}

TEST(ReportScale, NiceTicks) {
  EXPECT_EQ(NiceTicks(0.0, 10.0, 5), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  EXPECT_EQ(NiceTicks(-11.12, 6.88, 6), (std::vector<double>{-10, -8, -6, -4, -2, 0, 2, 4, 6}));
  double lo = -11.12, hi = 6.88;
  ExpandToNice(&lo, &hi, 6);
  EXPECT_DOUBLE_EQ(lo, -12.0);
  EXPECT_DOUBLE_EQ(hi, 8.0);
  const LinearScale s(0.0, 10.0, 100.0, 0.0);
  EXPECT_DOUBLE_EQ(s(2.5), 75.0);
}

TEST(ReportSvg, ElementsAndEscaping) {
  Svg svg(100, 50);
  svg.Title("t<1>");
  svg.Line({0, 0}, {10, 10}, Style{});
  svg.Text({5, 5}, "A & B", TextStyle{});
  const std::string s = svg.str();
  EXPECT_EQ(s.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_NE(s.find("<title>t&lt;1&gt;</title>"), std::string::npos);
  EXPECT_NE(s.find(">A &amp; B</text>"), std::string::npos);
  EXPECT_EQ(s.substr(s.size() - 7), "</svg>\n");
}

TEST(ReportXyChart, DrawsEveryElement) {
  XyChart c;
  c.title = "GOST fig. 10";
  XySeries up;
  up.label = "X̄↑";
  up.x = {0, 100, 200};
  up.y = {1, -2, 0.5};
  c.series.push_back(up);
  XyIntervals iv;
  iv.x = up.x;
  iv.lower = {-1, -4, -1};
  iv.upper = {3, 0, 2};
  c.intervals.push_back(iv);
  XyBars b;
  b.x = up.x;
  b.y = {0.5, -0.5, 1};
  c.bars.push_back(b);
  c.hlines.push_back({"A = 7", 3.0});
  const std::string s = c.Render();
  EXPECT_EQ(Count(s, "<polyline"), 1u);
  EXPECT_GE(Count(s, "<rect"), 3u + 1u);
  EXPECT_NE(s.find("GOST fig. 10"), std::string::npos);
  EXPECT_NE(s.find("A = 7"), std::string::npos);
  EXPECT_NE(s.find("X̄↑"), std::string::npos);
}

TEST(ReportPolarChart, TracesCentresAndZones) {
  PolarChart p;
  p.title = "radial";
  PolarTrace t;
  for (int a = 0; a < 360; a += 10) {
    t.angle_deg.push_back(a);
    t.value.push_back(0.1 * a / 360.0);
  }
  p.traces.push_back(t);
  p.centres.push_back({"LSC", 0.01, 0.02});
  p.zones.push_back({"zone", 0.01, 0.02, -0.05, 0.05});
  const std::string s = p.Render();
  EXPECT_EQ(Count(s, "<polygon"), 1u);
  EXPECT_NE(s.find("LSC"), std::string::npos);
  EXPECT_NE(s.find("270°"), std::string::npos);
}

TEST(ReportHtmlPage, WritesASelfContainedFile) {
  HtmlPage page("Report <1>");
  page.Heading(2, "Section");
  page.Table({"a", "b"}, {{"1", "x&y"}, {"2"}});
  page.Figure("<svg></svg>", "caption");
  const std::string dir =
      (std::filesystem::temp_directory_path() / "volcomp_report_test" / "sub").string();
  std::filesystem::remove_all(dir);
  const std::string path = PrepareReportPath(dir, "page.html");
  page.WriteFile(path);
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  const std::string s = ss.str();
  EXPECT_NE(s.find("<title>Report &lt;1&gt;</title>"), std::string::npos);
  EXPECT_NE(s.find("<td>x&amp;y</td>"), std::string::npos);
  EXPECT_NE(s.find("<td>2</td><td></td>"), std::string::npos);
  EXPECT_NE(s.find("<figure>\n<svg></svg>"), std::string::npos);
  // A directory that cannot be created (a file is in the way).
  EXPECT_THROW(PrepareReportPath(path + "/x", "page.html"), std::runtime_error);
  std::filesystem::remove_all(std::filesystem::temp_directory_path() / "volcomp_report_test");
}

}  // namespace
}  // namespace volcomp::report
