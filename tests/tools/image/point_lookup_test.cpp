// Corrections at points read from a CSV: positions in steps or units, directions, and refusals
// naming the line.
#include "volcomp/image/point_lookup.hpp"

#include <gtest/gtest.h>

#include "expected_value.hpp"
#include "volcomp/image/image_builder.hpp"

namespace volcomp::image {
namespace {

using testing::ValueOf;

// One axis X of 1 µm per step: forward +2 steps everywhere, reverse −1 step.
LoadedImage AxisImage() {
  ImageRequest r;
  r.axes.resize(1);
  AxisCorrections t;
  t.lattice = {2, 0, 1000};
  t.forward_steps = {2, 2};
  t.reverse_steps = {-1, -1};
  r.axis_tables.push_back(t);
  return ValueOf(LoadedImage::FromBytes(ValueOf(BuildImage(r)), "x.vct"));
}

TEST(image_point_lookup, StepsOrUnitsAndDirections) {
  const LoadedImage img = AxisImage();
  const tools::CsvTable points =
      ValueOf(tools::CsvTable::ReadString("x_mm,dir_x\n0.5,1\n0.5004,-1\n", "p.csv"));
  const PointLookup lookup = ValueOf(PointLookup::Create(img, points));
  EXPECT_EQ(lookup.Header(), "x_steps,dx_steps,dx_um\n");
  EXPECT_EQ(ValueOf(lookup.Row(points.rows()[0])), "500,2.00000000,2.000000\n");
  EXPECT_EQ(ValueOf(lookup.Row(points.rows()[1])), "500,-1.00000000,-1.000000\n");
}

TEST(image_point_lookup, RefusalsNameTheLine) {
  const LoadedImage img = AxisImage();
  const auto missing =
      PointLookup::Create(img, ValueOf(tools::CsvTable::ReadString("y_mm\n1\n", "p.csv")));
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().code, Error::kInputInvalid);
  EXPECT_EQ(missing.error().message, "p.csv:1: missing column \"x_steps\" or \"x_mm\" for axis X");
  const tools::CsvTable points =
      ValueOf(tools::CsvTable::ReadString("x_steps,dir_x\n1,0\n9999999999,1\n", "p.csv"));
  const PointLookup lookup = ValueOf(PointLookup::Create(img, points));
  const auto direction = lookup.Row(points.rows()[0]);
  ASSERT_FALSE(direction.ok());
  EXPECT_EQ(direction.error().message, "p.csv:2: column \"dir_x\": use +1 or -1");
  const auto range = lookup.Row(points.rows()[1]);
  ASSERT_FALSE(range.ok());
  EXPECT_EQ(range.error().message, "p.csv:3: column \"x_steps\": position outside int32 steps");
}

}  // namespace
}  // namespace volcomp::image
