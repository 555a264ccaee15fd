// A new image with a new thermal model (image/image_thermal.hpp): it corrects, at every position
// and in both directions, exactly as the image it came from (the firmware's lookup on both), it
// carries the model as given, replaces an earlier one, keeps the INFO lines but the earlier
// model's; and the span an image's tables cover on an axis.
#include "volcomp/image/image_thermal.hpp"

#include <gtest/gtest.h>

#include <string>

#include "expected_value.hpp"
#include "volcomp/image/image_builder.hpp"

namespace volcomp::image {
namespace {

using testing::ExpectFailure;
using testing::ValueOf;

// X, Y at 1 µm and Z at 0.5 µm per step: a 3×2×2 GRID3 and AXIS1D on Y with a reverse table;
// INFO machine=MILL-7.
ImageRequest Request() {
  ImageRequest r;
  r.table_id = 9;
  r.axes = {{'X', table::AxisKind::kLinear, 1000000},
            {'Y', table::AxisKind::kLinear, 1000000},
            {'Z', table::AxisKind::kLinear, 500000}};
  GridCorrections g;
  g.lattice = {Lattice{3, -1000, 1000}, Lattice{2, 0, 5000}, Lattice{2, 0, 4000}};
  for (int i = 0; i < 3 * 2 * 2 * 3; ++i) g.correction_steps.push_back(0.5 * (i % 5) - 1);
  r.grid = g;
  AxisCorrections y;
  y.axis = 1;
  y.lattice = {3, 500, 2500};
  y.forward_steps = {-4, 2, 0.5};
  y.reverse_steps = {1, -1.25, 7};
  r.axis_tables = {y};
  r.info = {{"machine", "MILL-7"}};
  return r;
}

thermal::ThermalModel Model(float offset) {
  thermal::ThermalModel m;
  m.axis_count = 3;
  m.channel_mask = 0x04;
  m.reference_cC[2] = 2000;
  m.calibrated_low_cC[2] = 1990;
  m.calibrated_high_cC[2] = 2500;
  m.axis[0].offset_um_per_K[2] = offset;
  m.axis[0].slope_um_per_K_m[2] = -11.5f;
  m.axis[0].p0_mm = 0.5f;
  m.axis[0].reach_mm = 1.5f;
  return m;
}

TEST(ImageThermal, CorrectsAsTheImageItCameFromAndCarriesTheModel) {
  const LoadedImage in = ValueOf(LoadedImage::FromBytes(ValueOf(BuildImage(Request())), "in"));
  const ThermalImage out = ValueOf(WithThermalModel(in, "in.vct", Model(-2.0f), {}));
  EXPECT_FALSE(out.replaced);
  EXPECT_TRUE(out.warnings.empty());
  const LoadedImage img = ValueOf(LoadedImage::FromBytes(out.bytes, "out"));
  const table::TableView& v = img.view();
  EXPECT_EQ(v.table_id, 9u);
  ASSERT_NE(v.thermal, nullptr);
  const thermal::ThermalModel m = table::ReadThermal(v.thermal);
  EXPECT_EQ(m.channel_mask, 0x04);
  EXPECT_EQ(m.reference_cC[2], 2000);
  EXPECT_EQ(m.calibrated_low_cC[2], 1990);
  EXPECT_FLOAT_EQ(m.axis[0].offset_um_per_K[2], -2.0f);
  EXPECT_FLOAT_EQ(m.axis[0].slope_um_per_K_m[2], -11.5f);
  EXPECT_FLOAT_EQ(m.axis[0].p0_mm, 0.5f);
  const std::string info(v.info, v.info_size);
  EXPECT_NE(info.find("thermal.builder=volcomp build thermal\n"), std::string::npos) << info;
  EXPECT_NE(info.find("machine=MILL-7\n"), std::string::npos) << info;

  const ImageEvaluator a = ValueOf(ImageEvaluator::Create(in));
  const ImageEvaluator b = ValueOf(ImageEvaluator::Create(img));
  int checked = 0;
  for (int32_t x = -1500; x <= 1500; x += 370) {
    for (int32_t y = -300; y <= 6000; y += 530) {
      for (int32_t z = -500; z <= 4500; z += 910) {
        for (int dir = 0; dir < 2; ++dir) {
          const int32_t pos[3] = {x, y, z};
          const bool rev[3] = {false, dir != 0, false};
          int32_t qa[3], qb[3];
          a.CorrectionQ8(pos, rev, qa);
          b.CorrectionQ8(pos, rev, qb);
          for (int c = 0; c < 3; ++c) ASSERT_EQ(qa[c], qb[c]) << x << " " << y << " " << z;
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 500);
}

TEST(ImageThermal, ReplacesAnEarlierModelAndItsInfo) {
  const LoadedImage in = ValueOf(LoadedImage::FromBytes(ValueOf(BuildImage(Request())), "in"));
  ThermalImageOptions o;
  o.info = {{"source", "first.csv"}};
  const ThermalImage first = ValueOf(WithThermalModel(in, "in.vct", Model(-2.0f), o));
  const LoadedImage mid = ValueOf(LoadedImage::FromBytes(first.bytes, "mid"));
  o.info = {{"source", "second.csv"}};
  o.table_id = 10;
  const ThermalImage second = ValueOf(WithThermalModel(mid, "mid.vct", Model(3.0f), o));
  EXPECT_TRUE(second.replaced);
  const LoadedImage img = ValueOf(LoadedImage::FromBytes(second.bytes, "out"));
  EXPECT_EQ(img.view().table_id, 10u);
  EXPECT_FLOAT_EQ(table::ReadThermal(img.view().thermal).axis[0].offset_um_per_K[2], 3.0f);
  const std::string info(img.view().info, img.view().info_size);
  EXPECT_NE(info.find("thermal.source=second.csv\n"), std::string::npos) << info;
  EXPECT_EQ(info.find("first.csv"), std::string::npos) << info;
  EXPECT_NE(info.find("machine=MILL-7\n"), std::string::npos) << info;
}

TEST(ImageThermal, RefusesAModelOfOtherAxesOrOnARotaryAxis) {
  const LoadedImage in = ValueOf(LoadedImage::FromBytes(ValueOf(BuildImage(Request())), "in"));
  thermal::ThermalModel two = Model(1.0f);
  two.axis_count = 2;
  ExpectFailure(WithThermalModel(in, "in.vct", two, {}), Error::kInputInvalid,
                {"in.vct", "2 axes, the image 3"});
  ImageRequest r = Request();
  r.axes[0].kind = table::AxisKind::kRotary;
  r.grid.reset();
  const LoadedImage rot = ValueOf(LoadedImage::FromBytes(ValueOf(BuildImage(r)), "rot"));
  ExpectFailure(WithThermalModel(rot, "rot.vct", Model(1.0f), {}), Error::kInputInvalid,
                {"rot.vct with the thermal model"});
}

TEST(ImageThermal, TheSpanOfTheTablesOnAnAxis) {
  const LoadedImage in = ValueOf(LoadedImage::FromBytes(ValueOf(BuildImage(Request())), "in"));
  // X: GRID3 -1000 + 2·1000 steps of 1 µm: -1 .. 1 mm.
  const auto x = TableSpan(in.view(), 0);
  ASSERT_TRUE(x.has_value());
  EXPECT_DOUBLE_EQ(x->first, -1.0);
  EXPECT_DOUBLE_EQ(x->second, 1.0);
  // Y: GRID3 0 .. 5 mm and AXIS1D 0.5 .. 5.5 mm: 0 .. 5.5 mm.
  const auto y = TableSpan(in.view(), 1);
  EXPECT_DOUBLE_EQ(y->first, 0.0);
  EXPECT_DOUBLE_EQ(y->second, 5.5);
  // Z: 0 .. 4000 steps of 0.5 µm: 0 .. 2 mm.
  EXPECT_DOUBLE_EQ(TableSpan(in.view(), 2)->second, 2.0);
}

}  // namespace
}  // namespace volcomp::image
