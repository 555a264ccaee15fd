// The SVG writer (svg.hpp): elements and escaping.
#include "volcomp/report/svg.hpp"

#include <gtest/gtest.h>

#include <string>

namespace volcomp::report {
namespace {

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

}  // namespace
}  // namespace volcomp::report
