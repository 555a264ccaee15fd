// The error tables the controller writers share (exporters/error_table.hpp), against numbers
// worked by hand: linear resampling to an equal grid, zeroing at a reference, --negate, the unit
// conversion and the refusals (unequal spacing, too many points, a spacing longer than the travel).
#include "volcomp/exporters/error_table.hpp"

#include <gtest/gtest.h>

namespace volcomp::exporters {
namespace {

model::PositioningData Measured() {
  model::PositioningData d;
  d.position = {0, 40, 100};
  d.dev_forward = {0, 4, 10};
  d.dev_reverse = {-2, 2, 4};
  return d;
}

TEST(ErrorTable, ResamplesLinearlyToAnEqualGrid) {
  ErrorTableOptions o;
  o.spacing = 50;
  const auto t = BuildErrorTable(Measured(), o);
  ASSERT_TRUE(t.ok()) << t.error().message;
  ASSERT_EQ(t->position.size(), 3u);
  EXPECT_DOUBLE_EQ(t->position[1], 50);
  EXPECT_DOUBLE_EQ(t->spacing, 50);
  // At 50: 4 + (50 − 40) / 60 · (10 − 4) = 5 forward, 2 + 10/60 · 2 = 2.3333 reverse.
  EXPECT_NEAR(t->forward_um[1], 5.0, 1e-12);
  EXPECT_NEAR(t->reverse_um[1], 2.0 + 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(t->forward_um[2], 10.0, 1e-12);
  EXPECT_EQ(t->uncovered, 0.0);
}

// An inch machine: the positions in inches (101.6 mm = 4 in exactly), a spacing and a reference
// in inches, the errors still µm; ToMachineUnits gives inches (25.4 µm = 0.001 in).
TEST(ErrorTable, InchMachinePositionsAndValues) {
  model::PositioningData d;
  d.position = {0, 50.8, 101.6};
  d.dev_forward = {0, 2.54, 10.16};
  ErrorTableOptions o;
  o.unit = LengthUnit::kInch;
  o.spacing = 1;
  o.zero_at = 2;
  const auto t = BuildErrorTable(d, o);
  ASSERT_TRUE(t.ok()) << t.error().message;
  EXPECT_EQ(t->unit, LengthUnit::kInch);
  ASSERT_EQ(t->position.size(), 5u);
  EXPECT_EQ(t->position[4], 4.0);
  EXPECT_EQ(t->tested_to, 4.0);
  // At 1 in (halfway to 2 in): 1.27 µm, less the 2.54 µm at the reference.
  EXPECT_NEAR(t->forward_um[1], 1.27 - 2.54, 1e-12);
  EXPECT_NEAR(t->forward_um[4], 10.16 - 2.54, 1e-12);
  EXPECT_NEAR(ToMachineUnits(25.4, false, LengthUnit::kInch), 0.001, 1e-15);
  EXPECT_NEAR(ToMachineUnits(3600, true, LengthUnit::kInch), 1.0, 1e-15);  // deg either way
  o.zero_at = 5;
  const auto outside = BuildErrorTable(d, o);
  ASSERT_FALSE(outside.ok());
  EXPECT_EQ(outside.error().message,
            "reference position 5 in is outside the tested travel 0 to 4 in");
}

TEST(ErrorTable, AGridShortOfTheTravelSaysHowMuch) {
  ErrorTableOptions o;
  o.spacing = 30;  // 0, 30, 60, 90: 10 mm of the 100 tested are past the last node
  const auto t = BuildErrorTable(Measured(), o);
  ASSERT_TRUE(t.ok()) << t.error().message;
  EXPECT_EQ(t->position.size(), 4u);
  EXPECT_NEAR(t->uncovered, 10.0, 1e-9);
}

TEST(ErrorTable, TheTestsOwnPositionsKeepTheirUnequalGaps) {
  const auto t = BuildErrorTable(Measured(), {});
  ASSERT_TRUE(t.ok());
  EXPECT_EQ(t->spacing, 0.0);
  const auto s = RequireEqualSpacing(*t, "the control");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().message,
            "the test positions are not equally spaced (40 mm from 0 to 40, 60 mm from 40 to "
            "100): the control takes equally spaced points only; give --spacing to resample the "
            "test to an equal grid");
}

TEST(ErrorTable, ZeroesAtTheReferenceThenNegates) {
  ErrorTableOptions o;
  o.zero_at = 70;  // forward error there: 4 + 30/60 · 6 = 7
  auto t = BuildErrorTable(Measured(), o);
  ASSERT_TRUE(t.ok());
  EXPECT_NEAR(t->forward_um[0], -7.0, 1e-12);
  EXPECT_NEAR(t->forward_um[2], 3.0, 1e-12);
  EXPECT_NEAR(t->reverse_um[0], -9.0, 1e-12);  // the reversal is kept
  o.negate = true;
  t = BuildErrorTable(Measured(), o);
  ASSERT_TRUE(t.ok());
  EXPECT_NEAR(t->forward_um[0], 7.0, 1e-12);
  EXPECT_NEAR(t->reverse_um[0], 9.0, 1e-12);
  EXPECT_TRUE(t->negated);
}

TEST(ErrorTable, Refusals) {
  ErrorTableOptions o;
  o.spacing = 150;
  auto t = BuildErrorTable(Measured(), o);
  ASSERT_FALSE(t.ok());
  EXPECT_NE(t.error().message.find("spacing 150 mm is longer than the tested travel 100 mm"),
            std::string::npos)
      << t.error().message;
  o.spacing = 0;
  o.zero_at = 120;
  t = BuildErrorTable(Measured(), o);
  ASSERT_FALSE(t.ok());
  EXPECT_NE(t.error().message.find("reference position 120 mm is outside the tested travel"),
            std::string::npos)
      << t.error().message;
  o.zero_at.reset();
  o.spacing = 10;  // 11 points
  t = BuildErrorTable(Measured(), o);
  ASSERT_TRUE(t.ok());
  const auto limit = RequirePointLimit(*t, 5, "the control");
  ASSERT_FALSE(limit.ok());
  // 100 mm over 4 gaps: 25 mm.
  EXPECT_EQ(limit.error().message,
            "11 points, the control takes at most 5: use a --spacing of at least 25 mm");
  EXPECT_TRUE(RequirePointLimit(*t, 11, "the control").ok());
}

TEST(ErrorTable, MachineUnits) {
  EXPECT_DOUBLE_EQ(ToMachineUnits(3.0, false), 0.003);  // µm → mm
  EXPECT_DOUBLE_EQ(ToMachineUnits(36.0, true), 0.01);   // arcsec → deg
}

}  // namespace
}  // namespace volcomp::exporters
