// A GRID3 image from a grid source: the grid's INFO joins the caller's (which wins), fraction bits
// are chosen, the element LSB is reported, and the image is valid.
#include "volcomp/builders/grid_image.hpp"

#include <gtest/gtest.h>

#include "expected_value.hpp"
#include "volcomp/datasets/s500.hpp"
#include "volcomp/image/axis_units.hpp"
#include "volcomp/image/image_reader.hpp"

namespace volcomp::builders {
namespace {

using testing::ValueOf;

GridBuildOptions SmallS500Grid(const GridSource& source) {
  GridBuildOptions o;
  o.min_mm = source.min_mm;
  o.max_mm = {40, 20, 20};
  o.spacing_mm = {20, 20, 20};
  return o;
}

TEST(builders_grid_image, BuildsAValidImageWithItsInfo) {
  const GridSource source = ModelGridSource(datasets::S500Model());
  image::ImageRequest request;
  request.axes = ValueOf(image::MakeAxisDefs({'X', 'Y', 'Z'}, "X=1000,Y=1000,Z=1000", ""));
  request.table_id = 9;
  request.info["model"] = "mine";  // the caller's entry stays
  const GridImage img = ValueOf(BuildGridImage(SmallS500Grid(source), request, source));
  EXPECT_EQ(img.request.info.at("model"), "mine");
  EXPECT_EQ(img.request.info.at("lattice_mm"), "0:20:40,0:20:20,0:20:20");
  EXPECT_EQ(img.request.info.count("predicted_interp_error_um"), 1u);
  ASSERT_TRUE(img.request.frac_bits.has_value());
  EXPECT_EQ(img.frac_bits, *img.request.frac_bits);
  EXPECT_DOUBLE_EQ(img.lsb_um[0], std::ldexp(1.0, -img.frac_bits));  // 1 µm per step
  const image::LoadedImage loaded = ValueOf(image::LoadedImage::FromBytes(img.bytes, "built"));
  EXPECT_EQ(loaded.view().table_id, 9u);
  EXPECT_EQ(loaded.view().grid.dim[0].nodes, 3u);
}

TEST(builders_grid_image, Float32HasNoFractionBitsAndRefusesThem) {
  const GridSource source = ModelGridSource(datasets::S500Model());
  image::ImageRequest request;
  request.axes = ValueOf(image::MakeAxisDefs({'X', 'Y', 'Z'}, "X=1000,Y=1000,Z=1000", ""));
  request.element = table::ElementType::kFloat32;
  const GridImage img = ValueOf(BuildGridImage(SmallS500Grid(source), request, source));
  EXPECT_EQ(img.frac_bits, 0);
  EXPECT_EQ(img.lsb_um[2], 0.0);
  request.frac_bits = 2;
  const auto refused = BuildGridImage(SmallS500Grid(source), request, source);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, Error::kInputInvalid);
  EXPECT_EQ(refused.error().message, "image: float32 elements take no fraction bits");
}

}  // namespace
}  // namespace volcomp::builders
