// Positioning tests from CSV: the mean-deviation layouts, and bad input named by line.
#include "volcomp/datasets/positioning_csv.hpp"

#include <gtest/gtest.h>

#include <string>

#include "expected_value.hpp"

namespace volcomp::datasets {
namespace {

using testing::ValueOf;

Expected<model::PositioningData> Read(const std::string& text) {
  return PositioningFromCsv(ValueOf(tools::CsvTable::ReadString(text, "p.csv")));
}

TEST(datasets_positioning_csv, ErrorsNameLine) {
  const auto error_of = [](const std::string& text) -> std::string {
    const auto r = Read(text);
    if (r.ok()) return "";
    EXPECT_EQ(r.error().code, Error::kInputInvalid) << r.error().message;
    return r.error().message;
  };
  EXPECT_EQ(error_of("position_mm,dev_forward_um\n0,1\n0,2\n"),
            "p.csv:3: positions must increase from row to row");
  EXPECT_EQ(error_of("position_mm,dev_forward_um\n0,1\n"),
            "p.csv:1: a positioning test needs at least 2 target positions");
  EXPECT_EQ(error_of("position_mm,dev_reverse_um\n0,1\n"),
            "p.csv:1: missing column \"dev_forward_um\"");
}

TEST(datasets_positioning_csv, RotaryMeansWithReverse) {
  const model::PositioningData r =
      ValueOf(Read("position_deg,dev_forward_arcsec,dev_reverse_arcsec\n0,1,2\n90,3,4\n"));
  EXPECT_TRUE(r.rotary);
  EXPECT_EQ(r.position.size(), 2u);
  EXPECT_EQ(r.dev_forward[1], 3);
  EXPECT_EQ(r.dev_reverse[1], 4);
}

TEST(datasets_positioning_csv, RawReadingsAreAveragedWithTheEvaluationsChecks) {
  // Two runs of +10 µm up, −6 µm down: fewer than the 5 approaches the standards ask for.
  const std::string raw =
      "target_mm,direction,run,deviation_um\n0,up,1,10\n100,up,1,10\n100,down,1,-6\n"
      "0,down,1,-6\n0,up,2,10\n100,up,2,10\n100,down,2,-6\n0,down,2,-6\n";
  const auto strict = Read(raw);
  ASSERT_FALSE(strict.ok());
  EXPECT_EQ(strict.error().code, Error::kInputInvalid);
  EXPECT_NE(strict.error().message.find("require at least 5"), std::string::npos)
      << strict.error().message;
  metrology::GroupingOptions few;
  few.allow_few_approaches = true;
  const model::PositioningData d =
      ValueOf(PositioningFromCsv(ValueOf(tools::CsvTable::ReadString(raw, "p.csv")), few));
  ASSERT_EQ(d.position.size(), 2u);
  EXPECT_EQ(d.dev_forward[0], 10);
  EXPECT_EQ(d.dev_reverse[1], -6);
  EXPECT_FALSE(d.warnings.empty());
}

}  // namespace
}  // namespace volcomp::datasets
