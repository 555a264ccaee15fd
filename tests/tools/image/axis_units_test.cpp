// Axis options: assignments, lists and step sizes; a bad option value is a usage failure naming
// the option.
#include "volcomp/image/axis_units.hpp"

#include <gtest/gtest.h>

#include "expected_value.hpp"

namespace volcomp::image {
namespace {

using testing::ValueOf;

template <typename T>
void ExpectUsage(const Expected<T>& r, const std::string& message) {
  ASSERT_FALSE(r.ok()) << message;
  EXPECT_EQ(r.error().code, Error::kUsage);
  EXPECT_EQ(r.error().message, message);
}

TEST(image_axis_units, Assignments) {
  const auto a = ValueOf(ParseAxisAssignments("x=1000,A=2.5", "--resolution-nm"));
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a.at('X'), "1000");
  EXPECT_EQ(a.at('A'), "2.5");
  ExpectUsage(ParseAxisAssignments("X=1,Q=2", "--spacing"),
              "--spacing: \"Q\" is not an axis name (XYZABCUVW)");
  ExpectUsage(ParseAxisAssignments("X=1,X=2", "--spacing"), "--spacing: axis X twice");
  ExpectUsage(ParseAxisAssignments("X1", "--spacing"),
              "--spacing: expected AXIS=VALUE items like X=1000, got \"X1\"");
}

TEST(image_axis_units, Lists) {
  EXPECT_EQ(ValueOf(ParseAxisList("x,Y,c", "--axes")), (std::vector<char>{'X', 'Y', 'C'}));
  ExpectUsage(ParseAxisList("X,,Y", "--axes"), "--axes: expected a list like X,Y,Z");
  ExpectUsage(ParseAxisList("X,Y,y", "--axes"), "--axes: axis Y twice");
}

TEST(image_axis_units, StepSizes) {
  const auto defs = ValueOf(MakeAxisDefs({'X', 'B'}, "X=500,B=1000", ""));
  EXPECT_EQ(defs[0].resolution_e9, 500000u);  // 0.5 µm per step in pm
  EXPECT_EQ(defs[1].kind, table::AxisKind::kRotary);
  EXPECT_EQ(defs[1].resolution_e9, 1000000u);  // 1 m° per step in n°
  EXPECT_EQ(ValueOf(MakeAxisDefs({'Z'}, "", "Z=800"))[0].resolution_e9, 1250000u);
  ExpectUsage(MakeAxisDefs({'X'}, "X=1", "X=1"),
              "give either --resolution-nm or --steps-per-unit, not both (they state the same "
              "step size twice and could disagree)");
  ExpectUsage(MakeAxisDefs({'X', 'Y'}, "X=1", ""),
              "axis Y needs --resolution-nm or --steps-per-unit");
  ExpectUsage(MakeAxisDefs({'X'}, "X=-1", ""), "--resolution-nm: axis X needs a positive number");
  ExpectUsage(MakeAxisDefs({'X'}, "X=0.0005", ""),
              "axis X: the step size must be a whole number of 1e-9 units (pm or nano-degrees) "
              "between 1 and 2^32-1");
}

// Hand-worked: 400 steps/mm is 1/400 mm = 2.5 µm = 2500 nm per step (0x2012 = 2500000); 1000
// steps per degree is 0.001° = 1000 µ° per step; 3 steps/mm is 333333.333 nm (0x2012 rounds
// 1/3 mm to 333333333 pm, which is 3.000000003 steps/mm, shown to 9 digits as 3).
TEST(image_axis_units, ResolutionAsTheShopSaysIt) {
  EXPECT_EQ(ResolutionText(2500000, false), "400 steps/mm (2500 nm/step)");
  EXPECT_EQ(ResolutionText(1000000, true), "1000 steps/deg (1000 µ°/step)");
  EXPECT_EQ(ResolutionText(333333333, false), "3 steps/mm (333333.333 nm/step)");
  EXPECT_EQ(ResolutionText(0, false), "0 nm/step");
}

}  // namespace
}  // namespace volcomp::image
