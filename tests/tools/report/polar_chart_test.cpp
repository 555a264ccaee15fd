// Polar charts (polar_chart.hpp): traces, centres and zones.
#include "volcomp/report/polar_chart.hpp"

#include <gtest/gtest.h>

#include <string>

#include "occurrences.hpp"

namespace volcomp::report {
namespace {

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
  EXPECT_EQ(volcomp::testing::Occurrences(s, "<polygon"), 1u);
  EXPECT_NE(s.find("LSC"), std::string::npos);
  EXPECT_NE(s.find("270°"), std::string::npos);
}

}  // namespace
}  // namespace volcomp::report
