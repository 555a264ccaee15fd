// Malformed ISO 230-7 data files and options: errors name the file, line and problem.
#include <gtest/gtest.h>

#include "test_support.hpp"
#include "volcomp/metrology/rotary_data.hpp"
#include "volcomp/metrology/rotary_eval.hpp"

namespace volcomp::metrology {
namespace {

using testing::ExpectThrowWith;
using tools::InputError;

// Two revolutions of 8 angles; x and y channels.
std::string Good(const std::string& header = "rev,angle_deg,x_um,y_um") {
  std::string csv = header + "\n";
  for (int k = 1; k <= 2; ++k) {
    for (int j = 0; j < 8; ++j) {
      csv += std::to_string(k) + "," + std::to_string(45 * j) + ",0." + std::to_string(j) + ",0\n";
    }
  }
  return csv;
}

RotaryRecord Load(const std::string& csv) {
  return ReadRotaryCsv(tools::CsvTable::ParseString(csv, "r.csv"));
}

std::string Replace(std::string s, const std::string& from, const std::string& to) {
  s.replace(s.find(from), from.size(), to);
  return s;
}

TEST(MetrologyRotaryInput, GoodFile) {
  const RotaryRecord r = Load(Good());
  EXPECT_EQ(r.revs.size(), 2u);
  EXPECT_EQ(r.angle_deg.size(), 8u);
  EXPECT_TRUE(r.equally_spaced);
  EXPECT_DOUBLE_EQ(r.channels.at("x_um")[1][3], 0.3);
}

TEST(MetrologyRotaryInput, Problems) {
  ExpectThrowWith<InputError>([] { Load("angle_deg,x_um\n0,1\n"); },
                              {"r.csv:1:", "missing column \"rev\""});
  ExpectThrowWith<InputError>([] { Load("rev,angle_deg,x_mm\n1,0,1\n"); },
                              {"r.csv:1:", "no displacement column"});
  // Line 4 is rev 1, angle 90.
  ExpectThrowWith<InputError>([] { Load(Replace(Good(), "1,90,", "1,30,")); },
                              {"r.csv:4:", "30 does not increase within revolution 1"});
  ExpectThrowWith<InputError>([] { Load(Replace(Good(), "1,90,", "1,400,")); },
                              {"r.csv:4:", "400 is outside [0, 360)"});
  // Line 13 is rev 2, angle 135.
  ExpectThrowWith<InputError>([] { Load(Replace(Good(), "2,135,", "2,136,")); },
                              {"r.csv:13:", "angle 136° of revolution 2 differs from 135°"});
  ExpectThrowWith<InputError>([] { Load(Replace(Good(), "2,135,0.3", "x,135,0.3")); },
                              {"r.csv:13:", "\"x\" is not an integer"});
  ExpectThrowWith<InputError>([] { Load(Replace(Good(), "2,135,0.3", "2,135,abc")); },
                              {"r.csv:13:", "x_um", "\"abc\" is not a number"});
  ExpectThrowWith<InputError>([] { Load(Good() + "1,0,0,0\n"); },
                              {"r.csv:18:", "revolution 1 appears again"});
  ExpectThrowWith<InputError>([] { Load(Good() + "3,0,0,0\n"); },
                              {"r.csv:18:", "revolution 3 has 1 angles, the first one 8"});
  ExpectThrowWith<InputError>([] { Load("rev,angle_deg,x_um\n1,0,0\n1,120,0\n1,240,0\n"); },
                              {"r.csv:2:", "3 angles; at least 4"});
  ExpectThrowWith<InputError>([] { Load("rev,angle_deg,x_um\n"); }, {"r.csv:1:", "no data rows"});
}

TEST(MetrologyRotaryInput, OptionsThatDoNotFitTheChannels) {
  const RotaryRecord only_x = Load("rev,angle_deg,x_um\n1,0,0\n1,90,1\n1,180,0\n1,270,1\n");
  ExpectThrowWith<InputError>([&] { EvaluateRotary(only_x, RotaryOptions{}); },
                              {"rotating sensitive direction", "y_um"});
  RotaryOptions fixed45;
  fixed45.sensitive = SensitiveDirection::kFixed;
  fixed45.fsd_angle_deg = 45.0;
  ExpectThrowWith<InputError>([&] { EvaluateRotary(only_x, fixed45); }, {"y_um"});
  std::string csv = "rev,angle_deg,x_um,y_um,x2_um,y2_um\n";
  for (int j = 0; j < 8; ++j) csv += "1," + std::to_string(45 * j) + ",0,0,0,0\n";
  const auto ev = EvaluateRotary(Load(csv), RotaryOptions{});
  ASSERT_EQ(ev.measurements.size(), 2u);  // radial at both planes, no tilt
  ASSERT_FALSE(ev.warnings.empty());
  EXPECT_NE(ev.warnings.front().find("--tilt-distance-mm"), std::string::npos);
}

}  // namespace
}  // namespace volcomp::metrology
