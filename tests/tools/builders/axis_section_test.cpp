// The AXIS1D section of one axis: in steps of the axis, its kind checked.
#include "volcomp/builders/axis_section.hpp"

#include <gtest/gtest.h>

#include "expected_value.hpp"

namespace volcomp::builders {
namespace {

using testing::ValueOf;

TEST(builders_axis_section, StepsOfTheAxisAndTheKindChecked) {
  // Forward deviation +5 µm everywhere, reverse −3 µm: corrections −5 and +3 µm, i.e. −10 and
  // +6 steps of 0.5 µm.
  model::PositioningData d;
  d.position = {0, 10, 20};
  d.dev_forward = {5, 5, 5};
  d.dev_reverse = {-3, -3, -3};
  image::AxisDef x;
  x.name = 'X';
  x.resolution_e9 = 500000;
  const AxisSection s = ValueOf(BuildAxisSection(d, Axis1dOptions{}, x, 0, false));
  ASSERT_EQ(s.section.forward_steps.size(), 3u);
  EXPECT_NEAR(s.section.forward_steps[1], -10, 1e-6);
  EXPECT_NEAR(s.section.reverse_steps[2], 6, 1e-6);
  EXPECT_EQ(s.section.lattice.spacing_steps, 20000u);
  image::AxisDef b = x;
  b.name = 'B';
  b.kind = table::AxisKind::kRotary;
  const auto refused = BuildAxisSection(d, Axis1dOptions{}, b, 1, false);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, Error::kInvalidArgument);
  EXPECT_EQ(refused.error().message, "axis B is rotary: give position_deg and *_arcsec columns");
}

TEST(builders_axis_section, WrapNeedsAFullTurn) {
  model::PositioningData d;
  d.rotary = true;
  d.position = {0, 90, 180};
  d.dev_forward = {0, 0, 0};
  image::AxisDef c;
  c.name = 'C';
  c.kind = table::AxisKind::kRotary;
  c.resolution_e9 = 1000000;  // 1 millidegree per step
  const auto refused = BuildAxisSection(d, Axis1dOptions{}, c, 0, true);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, Error::kInputInvalid);
  EXPECT_EQ(refused.error().message,
            "axis C: wrap-around needs a rotary table spanning exactly 360°");
  d.position = {0, 90, 180, 270, 360};
  d.dev_forward = {0, 0, 0, 0, 0};
  const AxisSection s = ValueOf(BuildAxisSection(d, Axis1dOptions{}, c, 0, true));
  EXPECT_EQ(s.section.wrap_period_steps, 360000u);
}

}  // namespace
}  // namespace volcomp::builders
