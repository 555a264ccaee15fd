// Polar charts (polar_chart.hpp): traces, centres and zones.
#include "volcomp/report/polar_chart.hpp"

#include <gtest/gtest.h>

#include <string>

namespace volcomp::report {
namespace {

std::size_t Count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
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

}  // namespace
}  // namespace volcomp::report
