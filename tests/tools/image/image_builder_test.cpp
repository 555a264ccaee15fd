// Image building: fraction bits chosen to fit, and requests the format cannot hold refused with
// the node or entry named.
#include "volcomp/image/image_builder.hpp"

#include <gtest/gtest.h>

#include "expected_value.hpp"
#include "volcomp/image/image_reader.hpp"

namespace volcomp::image {
namespace {

using testing::ValueOf;

ImageRequest OneAxis(std::vector<double> forward_steps) {
  ImageRequest r;
  r.axes.resize(1);
  AxisCorrections t;
  t.lattice = {static_cast<uint32_t>(forward_steps.size()), 0, 100};
  t.forward_steps = std::move(forward_steps);
  r.axis_tables.push_back(t);
  return r;
}

void ExpectInvalid(const ImageRequest& r, const std::string& message) {
  const auto image = BuildImage(r);
  ASSERT_FALSE(image.ok()) << message;
  EXPECT_EQ(image.error().code, Error::kInputInvalid);
  EXPECT_EQ(image.error().message, message);
}

TEST(image_builder, FractionBitsFitTheLargestValue) {
  EXPECT_EQ(ValueOf(ChooseFracBits(OneAxis({1.5, -3}))), 8);
  EXPECT_EQ(ValueOf(ChooseFracBits(OneAxis({1000, 0}))), 5);  // 1000·2^5 = 32000 ≤ 32767
  const ImageRequest r = OneAxis({1.25, -0.5, 2});
  const LoadedImage img = ValueOf(LoadedImage::FromBytes(ValueOf(BuildImage(r)), "built"));
  EXPECT_EQ(img.view().axis1d[0].frac_bits, 8);
  EXPECT_EQ(img.view().axis1d[0].dim.nodes, 3u);
}

TEST(image_builder, RefusalsNameWhatCannotBeStored) {
  ImageRequest r = OneAxis({1, 2});
  r.table_id = kNoTableId;
  ExpectInvalid(r,
                "image: table id 0 is reserved (the board reports 0 in 0x2103 when no table is "
                "active); ids start at 1");
  r = OneAxis({1, 2});
  r.frac_bits = 8;
  r.axis_tables[0].forward_steps[1] = 200;
  ExpectInvalid(r,
                "image: AXIS1D axis 0 forward node 1 = 200 steps does not fit the element type "
                "with 8 fraction bits");
  r = OneAxis({1, 2});
  r.info["bad\nkey"] = "x";
  ExpectInvalid(r, "image: INFO entry \"bad\nkey\" contains a control character");
  ImageRequest none;
  none.axes.resize(1);
  ExpectInvalid(none, "image: no GRID3 and no AXIS1D table");
  const auto frac = ChooseFracBits(OneAxis({40000, 0}));
  ASSERT_FALSE(frac.ok());
  EXPECT_EQ(frac.error().message,
            "image: a correction of 40000 steps does not fit int16 even with 0 fraction bits; "
            "use --element int32");
  ExpectInvalid(OneAxis({1e5, 0}),
                "image: AXIS1D axis 0 forward node 0 = 100000 steps exceeds the maximum "
                "correction of 65536 steps");
}

}  // namespace
}  // namespace volcomp::image
