// XY charts (xy_chart.hpp): every element is drawn.
#include "volcomp/report/xy_chart.hpp"

#include <gtest/gtest.h>

#include <string>

#include "occurrences.hpp"

namespace volcomp::report {
namespace {

using volcomp::testing::Occurrences;

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
  EXPECT_EQ(Occurrences(s, "<polyline"), 1u);
  EXPECT_GE(Occurrences(s, "<rect"), 3u + 1u);
  EXPECT_NE(s.find("GOST fig. 10"), std::string::npos);
  EXPECT_NE(s.find("A = 7"), std::string::npos);
  EXPECT_NE(s.find("X̄↑"), std::string::npos);
}

}  // namespace
}  // namespace volcomp::report
