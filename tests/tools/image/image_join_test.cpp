// Joining a GRID3 image and an AXIS1D image: the joined image corrects, at every position and in
// both directions, exactly as the sum of its parts (the firmware adds the GRID3 and the AXIS1D
// corrections), evaluated by the firmware's own lookup on each image; parts that do not belong
// together are refused naming the mismatch.
#include "volcomp/image/image_join.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "expected_value.hpp"
#include "volcomp/image/image_builder.hpp"

namespace volcomp::image {
namespace {

using testing::ExpectFailure;
using testing::ValueOf;

AxisDef Linear(char name, uint32_t pm_per_step) {
  return {name, table::AxisKind::kLinear, pm_per_step};
}

// X, Y, Z at 1, 1, 0.5 µm per step; a 3×3×2 lattice with distinct values; int16 Q.8.
ImageRequest GridRequest() {
  ImageRequest r;
  r.table_id = 7;
  r.axes = {Linear('X', 1000000), Linear('Y', 1000000), Linear('Z', 500000)};
  GridCorrections g;
  g.lattice = {Lattice{3, -1000, 1000}, Lattice{3, 0, 2000}, Lattice{2, 0, 4000}};
  for (int i = 0; i < 3 * 3 * 2 * 3; ++i) g.correction_steps.push_back(0.25 * (i % 7) - 1.5);
  r.grid = g;
  r.info = {{"machine", "MILL-7"}};
  return r;
}

// The AXIS1D image of axes Z and Y only (in that order, so the join must re-index by name): Z
// forward only with backlash, Y forward and reverse; int32 with 4 fraction bits.
ImageRequest AxisRequest() {
  ImageRequest r;
  r.table_id = 7;
  r.axes = {Linear('Z', 500000), Linear('Y', 1000000)};
  AxisCorrections z;
  z.axis = 0;
  z.lattice = {4, -2000, 3000};
  z.forward_steps = {3, -2.5, 1.0625, 0};
  z.backlash_steps = 1.5;
  AxisCorrections y;
  y.axis = 1;
  y.lattice = {3, 500, 2500};
  y.forward_steps = {-4, 2, 0.5};
  y.reverse_steps = {1, -1.25, 7};
  r.axis_tables = {z, y};
  r.element = table::ElementType::kInt32;
  r.frac_bits = 4;
  return r;
}

LoadedImage Load(const ImageRequest& r, const std::string& name) {
  return ValueOf(LoadedImage::FromBytes(ValueOf(BuildImage(r)), name));
}

TEST(ImageJoin, CorrectsExactlyAsItsParts) {
  const LoadedImage grid = Load(GridRequest(), "g.vct");
  const LoadedImage axis = Load(AxisRequest(), "a.vct");
  const JoinedImage joined = ValueOf(JoinImages({"g.vct", &grid}, {"a.vct", &axis}, {}));
  EXPECT_TRUE(joined.warnings.empty());
  const LoadedImage c = ValueOf(LoadedImage::FromBytes(joined.bytes, "c.vct"));
  const table::TableView& v = c.view();
  EXPECT_EQ(v.table_id, 7u);
  ASSERT_EQ(v.axis_count, 3);
  EXPECT_EQ(v.axes[0].name, 'X');
  EXPECT_EQ(v.axes[2].resolution_e9, 500000u);
  ASSERT_TRUE(v.grid.present);
  ASSERT_EQ(v.axis1d_count, 2);
  const std::string info(v.info, v.info_size);
  EXPECT_NE(info.find("grid_image=g.vct\n"), std::string::npos) << info;
  EXPECT_NE(info.find("axis_image=a.vct\n"), std::string::npos) << info;
  EXPECT_NE(info.find("grid.machine=MILL-7\n"), std::string::npos) << info;

  const ImageEvaluator joined_eval = ValueOf(ImageEvaluator::Create(c));
  const ImageEvaluator grid_eval = ValueOf(ImageEvaluator::Create(grid));
  const ImageEvaluator axis_eval = ValueOf(ImageEvaluator::Create(axis));
  int checked = 0;
  for (int32_t x = -1500; x <= 1500; x += 370) {
    for (int32_t y = -300; y <= 6000; y += 530) {
      for (int32_t z = -2500; z <= 8000; z += 910) {
        for (int dir = 0; dir < 4; ++dir) {
          const int32_t pos[3] = {x, y, z};
          const bool rev[3] = {false, (dir & 1) != 0, (dir & 2) != 0};
          int32_t joined_q8[3], grid_q8[3], axis_q8[2];
          joined_eval.CorrectionQ8(pos, rev, joined_q8);
          grid_eval.CorrectionQ8(pos, rev, grid_q8);
          const int32_t axis_pos[2] = {z, y};
          const bool axis_rev[2] = {rev[2], rev[1]};
          axis_eval.CorrectionQ8(axis_pos, axis_rev, axis_q8);
          ASSERT_EQ(joined_q8[0], grid_q8[0]);
          ASSERT_EQ(joined_q8[1], grid_q8[1] + axis_q8[1]) << x << " " << y << " " << z;
          ASSERT_EQ(joined_q8[2], grid_q8[2] + axis_q8[0]) << x << " " << y << " " << z;
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(ImageJoin, NewTableIdAndExtraInfo) {
  ImageRequest a = AxisRequest();
  a.table_id = 8;
  const LoadedImage grid = Load(GridRequest(), "g.vct");
  const LoadedImage axis = Load(a, "a.vct");
  ExpectFailure(
      JoinImages({"g.vct", &grid}, {"a.vct", &axis}, {}), Error::kInputInvalid,
      {"the images do not belong together: table id 7 in g.vct but 8 in a.vct", "--table-id"});
  JoinOptions o;
  o.table_id = 12;
  o.info = {{"operator", "QA"}};
  const JoinedImage joined = ValueOf(JoinImages({"g.vct", &grid}, {"a.vct", &axis}, o));
  const LoadedImage c = ValueOf(LoadedImage::FromBytes(joined.bytes, "c.vct"));
  EXPECT_EQ(c.view().table_id, 12u);
  EXPECT_NE(std::string(c.view().info, c.view().info_size).find("operator=QA\n"),
            std::string::npos);
}

TEST(ImageJoin, PartsThatDoNotBelongTogetherAreRefused) {
  const LoadedImage grid = Load(GridRequest(), "g.vct");
  const LoadedImage axis = Load(AxisRequest(), "a.vct");
  {  // Units per step of Z differ.
    ImageRequest a = AxisRequest();
    a.axes[0].resolution_e9 = 1000000;
    const LoadedImage other = Load(a, "a.vct");
    ExpectFailure(
        JoinImages({"g.vct", &grid}, {"a.vct", &other}, {}), Error::kInputInvalid,
        {"the images do not belong together: axis Z is 2000 steps/mm (500 nm/step) in g.vct "
         "but 1000 steps/mm (1000 nm/step) in a.vct"});
  }
  {  // An axis the grid image does not have.
    ImageRequest a = AxisRequest();
    a.axes[0].name = 'U';
    const LoadedImage other = Load(a, "a.vct");
    ExpectFailure(JoinImages({"g.vct", &grid}, {"a.vct", &other}, {}), Error::kInputInvalid,
                  {"axis U of a.vct is not an axis of g.vct (X, Y, Z)"});
  }
  {  // Rotary against linear.
    ImageRequest a = AxisRequest();
    a.axes[1].kind = table::AxisKind::kRotary;
    const LoadedImage other = Load(a, "a.vct");
    ExpectFailure(
        JoinImages({"g.vct", &grid}, {"a.vct", &other}, {}), Error::kInputInvalid,
        {"axis Y is 1000 steps/mm (1000 nm/step) in g.vct but 1000 steps/deg (1000 µ°/step) "
         "in a.vct"});
  }
  // The parts the wrong way round.
  ExpectFailure(JoinImages({"a.vct", &axis}, {"g.vct", &grid}, {}), Error::kInputInvalid,
                {"a.vct: no GRID3 section"});
  ExpectFailure(JoinImages({"g.vct", &grid}, {"g2.vct", &grid}, {}), Error::kInputInvalid,
                {"g2.vct: has a GRID3 section"});
  {  // Both have an AXIS1D for Y.
    ImageRequest g = GridRequest();
    AxisCorrections y;
    y.axis = 1;
    y.lattice = {2, 0, 1000};
    y.forward_steps = {1, 1};
    g.axis_tables = {y};
    const LoadedImage both = Load(g, "gy.vct");
    ExpectFailure(JoinImages({"gy.vct", &both}, {"a.vct", &axis}, {}), Error::kInputInvalid,
                  {"both gy.vct and a.vct have an AXIS1D table for axis Y"});
  }
}

// A thermal model with a distinct offset per axis of `axes` (channel 0), in that axis order.
thermal::ThermalModel ModelFor(const std::vector<AxisDef>& axes) {
  thermal::ThermalModel m;
  m.axis_count = static_cast<uint8_t>(axes.size());
  m.channel_mask = 0x01;
  m.calibrated_high_cC[0] = 4000;
  for (size_t a = 0; a < axes.size(); ++a) {
    m.axis[a].offset_um_per_K[0] = static_cast<float>(axes[a].name - 'W');  // X 1, Y 2, Z 3
  }
  return m;
}

TEST(ImageJoin, TheThermalModelOfEitherPartIsCarriedByAxisName) {
  {  // From the GRID3 part: as it is.
    ImageRequest g = GridRequest();
    g.thermal = ModelFor(g.axes);
    const LoadedImage grid = Load(g, "g.vct");
    const LoadedImage axis = Load(AxisRequest(), "a.vct");
    const JoinedImage joined = ValueOf(JoinImages({"g.vct", &grid}, {"a.vct", &axis}, {}));
    const LoadedImage c = ValueOf(LoadedImage::FromBytes(joined.bytes, "c.vct"));
    ASSERT_NE(c.view().thermal, nullptr);
    const thermal::ThermalModel m = table::ReadThermal(c.view().thermal);
    EXPECT_EQ(m.axis_count, 3);
    EXPECT_EQ(m.axis[0].offset_um_per_K[0], 1.0f);
    EXPECT_EQ(m.axis[2].offset_um_per_K[0], 3.0f);
  }
  {  // From the AXIS1D part (axes Z, Y): re-indexed into the joined image's X, Y, Z.
    ImageRequest a = AxisRequest();
    a.thermal = ModelFor(a.axes);
    const LoadedImage grid = Load(GridRequest(), "g.vct");
    const LoadedImage axis = Load(a, "a.vct");
    const JoinedImage joined = ValueOf(JoinImages({"g.vct", &grid}, {"a.vct", &axis}, {}));
    const LoadedImage c = ValueOf(LoadedImage::FromBytes(joined.bytes, "c.vct"));
    ASSERT_NE(c.view().thermal, nullptr);
    const thermal::ThermalModel m = table::ReadThermal(c.view().thermal);
    EXPECT_EQ(m.axis_count, 3);
    EXPECT_EQ(m.axis[0].offset_um_per_K[0], 0.0f);  // X: not in the part
    EXPECT_EQ(m.axis[1].offset_um_per_K[0], 2.0f);  // Y
    EXPECT_EQ(m.axis[2].offset_um_per_K[0], 3.0f);  // Z
  }
  {  // Both: one model is kept, so the join refuses to choose.
    ImageRequest g = GridRequest();
    g.thermal = ModelFor(g.axes);
    ImageRequest a = AxisRequest();
    a.thermal = ModelFor(a.axes);
    const LoadedImage grid = Load(g, "g.vct");
    const LoadedImage axis = Load(a, "a.vct");
    ExpectFailure(JoinImages({"g.vct", &grid}, {"a.vct", &axis}, {}), Error::kInputInvalid,
                  {"both g.vct and a.vct have a THERMAL section"});
  }
}

}  // namespace
}  // namespace volcomp::image
