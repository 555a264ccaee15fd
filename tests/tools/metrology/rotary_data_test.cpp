// Reading ISO 230-7 records (rotary_data.hpp): every malformed file is a failure naming the file,
// the line and the problem.
#include "volcomp/metrology/rotary_data.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace volcomp::metrology {
namespace {

using testing::ExpectFailure;
using testing::ValueOf;

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

Expected<RotaryRecord> Load(const std::string& csv) {
  VOLCOMP_TRY_ASSIGN(const tools::CsvTable table, tools::CsvTable::ReadString(csv, "r.csv"));
  return ReadRotaryCsv(table);
}

std::string Replace(std::string s, const std::string& from, const std::string& to) {
  s.replace(s.find(from), from.size(), to);
  return s;
}

TEST(MetrologyRotaryInput, GoodFile) {
  const RotaryRecord r = ValueOf(Load(Good()));
  EXPECT_EQ(r.revs.size(), 2u);
  EXPECT_EQ(r.angle_deg.size(), 8u);
  EXPECT_TRUE(r.equally_spaced);
  EXPECT_DOUBLE_EQ(r.channels.at("x_um")[1][3], 0.3);
}

TEST(MetrologyRotaryInput, Problems) {
  ExpectFailure(Load("angle_deg,x_um\n0,1\n"), Error::kInputInvalid,
                {"r.csv:1:", "missing column \"rev\""});
  ExpectFailure(Load("rev,angle_deg,x_mm\n1,0,1\n"), Error::kInputInvalid,
                {"r.csv:1:", "no displacement column"});
  // Line 4 is rev 1, angle 90.
  ExpectFailure(Load(Replace(Good(), "1,90,", "1,30,")), Error::kInputInvalid,
                {"r.csv:4:", "30 does not increase within revolution 1"});
  ExpectFailure(Load(Replace(Good(), "1,90,", "1,400,")), Error::kInputInvalid,
                {"r.csv:4:", "400 is outside [0, 360)"});
  // Line 13 is rev 2, angle 135.
  ExpectFailure(Load(Replace(Good(), "2,135,", "2,136,")), Error::kInputInvalid,
                {"r.csv:13:", "angle 136° of revolution 2 differs from 135°"});
  ExpectFailure(Load(Replace(Good(), "2,135,0.3", "x,135,0.3")), Error::kInputInvalid,
                {"r.csv:13:", "\"x\" is not an integer"});
  ExpectFailure(Load(Replace(Good(), "2,135,0.3", "2,135,abc")), Error::kInputInvalid,
                {"r.csv:13:", "x_um", "\"abc\" is not a number"});
  ExpectFailure(Load(Good() + "1,0,0,0\n"), Error::kInputInvalid,
                {"r.csv:18:", "revolution 1 appears again"});
  ExpectFailure(Load(Good() + "3,0,0,0\n"), Error::kInputInvalid,
                {"r.csv:18:", "revolution 3 has 1 angles, the first one 8"});
  ExpectFailure(Load("rev,angle_deg,x_um\n1,0,0\n1,120,0\n1,240,0\n"), Error::kInputInvalid,
                {"r.csv:2:", "3 angles; at least 4"});
  ExpectFailure(Load("rev,angle_deg,x_um\n"), Error::kInputInvalid, {"r.csv:1:", "no data rows"});
}

// The direction column: each revolution's sense; a value that is not one, or a change of sense
// within a revolution, is refused with the line.
TEST(MetrologyRotaryInput, DirectionOfRotation) {
  std::string csv = "rev,angle_deg,direction,x_um\n";
  for (int k = 1; k <= 3; ++k) {
    for (int j = 0; j < 4; ++j) {
      csv +=
          std::to_string(k) + "," + std::to_string(90 * j) + "," + (k == 2 ? "CCW" : "+") + ",0\n";
    }
  }
  const RotaryRecord r = ValueOf(Load(csv));
  ASSERT_EQ(r.rev_sense.size(), 3u);
  EXPECT_EQ(r.rev_sense[0], RotationSense::kCw);
  EXPECT_EQ(r.rev_sense[1], RotationSense::kCcw);
  EXPECT_EQ(r.rev_sense[2], RotationSense::kCw);
  const RotaryRecord cw = RevolutionsTurning(r, RotationSense::kCw);
  EXPECT_EQ(cw.revs, (std::vector<long long>{1, 3}));
  EXPECT_EQ(cw.channels.at("x_um").size(), 2u);
  // Line 7 is revolution 2's second row (header on line 1).
  ExpectFailure(Load(Replace(csv, "2,90,CCW", "2,90,CW")), Error::kInputInvalid,
                {"r.csv:7", "CW within revolution 2, which began CCW"});
  ExpectFailure(Load(Replace(csv, "2,90,CCW", "2,90,left")), Error::kInputInvalid,
                {"r.csv:7", "\"left\" is not CW or CCW"});
  EXPECT_EQ(ValueOf(Load(Good())).rev_sense[0], RotationSense::kUnstated);
}

}  // namespace
}  // namespace volcomp::metrology
