// The THERMAL section (docs/table-image-format.md): the model survives the writer and the parser
// value for value, every byte lies at the documented offset, every field out of range has its
// error, and an image of AXES + THERMAL alone is a correction.
#include <gtest/gtest.h>

#include <cmath>

#include "test_tables.hpp"
#include "volcomp/base/byte_order.hpp"
#include "volcomp/table/table_image.hpp"
#include "volcomp/table/table_writer.hpp"

namespace volcomp {
namespace {

using testing::AlignedBytes;
using testing::FixCrc;

thermal::ThermalModel TwoAxisModel() {
  thermal::ThermalModel m;
  m.axis_count = 2;
  m.channel_mask = 0x05;  // channels 0 and 2
  m.slew_um_s = 0.5f;
  m.hold_ms = 120000;
  m.reference_cC[0] = 2000;
  m.reference_cC[2] = 2150;
  m.calibrated_low_cC[0] = 1800;
  m.calibrated_high_cC[0] = 3200;
  m.calibrated_low_cC[2] = 1900;
  m.calibrated_high_cC[2] = 4500;
  m.axis[0].p0_mm = 12.5f;
  m.axis[0].reach_mm = 600.0f;
  m.axis[0].offset_um_per_K[0] = 1.25f;
  m.axis[0].slope_um_per_K_m[2] = -11.5f;
  m.axis[1].reach_mm = 400.0f;
  m.axis[1].offset_um_per_K[2] = -3.0f;
  return m;
}

// X and Y linear axes, one AXIS1D table on X (or none), the model.
AlignedBytes Image(const thermal::ThermalModel& m, bool with_axis_table = true) {
  static const int16_t kValues[2] = {0, 4};
  table::ImageSpec s;
  s.table_id = 7;
  s.axis_count = 2;
  s.axes[0] = testing::LinearAxis('X');
  s.axes[1] = testing::LinearAxis('Y');
  if (with_axis_table) {
    s.axis1d_count = 1;
    s.axis1d[0].dim = {2, 0, 1000};
    s.axis1d[0].forward.i16 = kValues;
  }
  s.thermal = &m;
  return testing::WriteImageBytes(s);
}

// Offset of the THERMAL body in Image(): header 24, AXES 8 + 4 + 2*8, AXIS1D 8 + 24 + 4.
constexpr size_t kBody = 24 + 28 + 36 + 8;

Error ParseError(const AlignedBytes& img) {
  return table::ParseImage(img.data(), img.size()).error();
}

TEST(ThermalSection, TheModelRoundTripsValueForValue) {
  const thermal::ThermalModel m = TwoAxisModel();
  const AlignedBytes img = Image(m);
  ASSERT_NE(img.size(), 0u);
  const auto v = table::ParseImage(img.data(), img.size());
  ASSERT_TRUE(v.ok()) << v.status().name();
  EXPECT_EQ(v->version_minor, table::kVersionMinorThermal);
  ASSERT_NE(v->thermal, nullptr);
  const thermal::ThermalModel r = table::ReadThermal(v->thermal);
  EXPECT_EQ(r.axis_count, 2);
  EXPECT_EQ(r.channel_mask, 0x05);
  EXPECT_EQ(r.slew_um_s, 0.5f);
  EXPECT_EQ(r.hold_ms, 120000u);
  for (int j = 0; j < 8; ++j) {
    EXPECT_EQ(r.reference_cC[j], m.reference_cC[j]);
    EXPECT_EQ(r.calibrated_low_cC[j], m.calibrated_low_cC[j]);
    EXPECT_EQ(r.calibrated_high_cC[j], m.calibrated_high_cC[j]);
    for (int a = 0; a < 2; ++a) {
      EXPECT_EQ(r.axis[a].offset_um_per_K[j], m.axis[a].offset_um_per_K[j]);
      EXPECT_EQ(r.axis[a].slope_um_per_K_m[j], m.axis[a].slope_um_per_K_m[j]);
    }
  }
  EXPECT_EQ(r.axis[0].p0_mm, 12.5f);
  EXPECT_EQ(r.axis[1].reach_mm, 400.0f);
}

TEST(ThermalSection, BytesAtTheDocumentedOffsets) {
  const AlignedBytes img = Image(TwoAxisModel());
  const uint8_t* h = img.data() + kBody - 8;
  EXPECT_EQ(LoadLe16(h), 5);      // type THERMAL
  EXPECT_EQ(LoadLe16(h + 2), 0);  // mandatory
  EXPECT_EQ(LoadLe32(h + 4), 60u + 2 * 72);
  const uint8_t* b = img.data() + kBody;
  EXPECT_EQ(b[0], 1);  // version
  EXPECT_EQ(b[1], 2);  // axes
  EXPECT_EQ(b[2], 0x05);
  EXPECT_EQ(b[3], 0);
  EXPECT_EQ(LoadLeF32(b + 4), 0.5f);
  EXPECT_EQ(LoadLe32(b + 8), 120000u);
  EXPECT_EQ(static_cast<int16_t>(LoadLe16(b + 12 + 2 * 2)), 2150);  // reference, channel 2
  EXPECT_EQ(static_cast<int16_t>(LoadLe16(b + 28 + 0)), 1800);      // calibrated low, channel 0
  EXPECT_EQ(static_cast<int16_t>(LoadLe16(b + 44 + 2 * 2)), 4500);  // calibrated high, channel 2
  EXPECT_EQ(LoadLeF32(b + 60), 12.5f);                              // X p0
  EXPECT_EQ(LoadLeF32(b + 60 + 4), 600.0f);                         // X reach
  EXPECT_EQ(LoadLeF32(b + 60 + 8), 1.25f);                          // X offset, channel 0
  EXPECT_EQ(LoadLeF32(b + 60 + 40 + 2 * 4), -11.5f);                // X slope, channel 2
  EXPECT_EQ(LoadLeF32(b + 60 + 72 + 8 + 2 * 4), -3.0f);             // Y offset, channel 2
}

TEST(ThermalSection, EveryFieldOutOfRangeHasItsError) {
  const AlignedBytes good = Image(TwoAxisModel());
  auto with = [&](auto change) {
    AlignedBytes b(good.data(), good.size());
    change(b.data() + kBody);
    FixCrc(b);
    return ParseError(b);
  };
  EXPECT_EQ(with([](uint8_t* b) { b[0] = 2; }), Error::kThermalBadVersion);
  EXPECT_EQ(with([](uint8_t* b) { b[1] = 1; }), Error::kThermalBadAxisCount);
  EXPECT_EQ(with([](uint8_t* b) { b[3] = 1; }), Error::kImageReservedNotZero);
  EXPECT_EQ(with([](uint8_t* b) { StoreLeF32(b + 4, 0.0f); }), Error::kThermalBadModel);
  EXPECT_EQ(with([](uint8_t* b) { StoreLeF32(b + 4, NAN); }), Error::kThermalBadModel);
  EXPECT_EQ(with([](uint8_t* b) { StoreLe32(b + 8, 3600001); }), Error::kThermalBadModel);
  EXPECT_EQ(with([](uint8_t* b) { StoreLe16(b + 28, 3300); }), Error::kThermalBadModel);  // lo>hi
  EXPECT_EQ(with([](uint8_t* b) { StoreLeF32(b + 60 + 4, -1.0f); }), Error::kThermalBadModel);
  EXPECT_EQ(with([](uint8_t* b) { StoreLeF32(b + 60 + 8, INFINITY); }), Error::kThermalBadModel);
  EXPECT_EQ(with([](uint8_t* b) { StoreLeF32(b + 60 + 8, 1000.5f); }), Error::kThermalBadModel);
  // A coefficient on channel 1, which the mask leaves out.
  EXPECT_EQ(with([](uint8_t* b) { StoreLeF32(b + 60 + 8 + 4, 0.1f); }), Error::kThermalBadModel);
  EXPECT_EQ(with([](uint8_t* b) { b[2] = 0x07; }), Error::kOk);  // channel 1 used, at zero
}

TEST(ThermalSection, LengthAndOccurrenceAreChecked) {
  // A body one axis record short: the section length no longer matches the AXES count.
  AlignedBytes b = Image(TwoAxisModel());
  const uint8_t* h = b.data() + kBody - 8;
  ASSERT_EQ(LoadLe32(h + 4), 204u);
  b.data()[kBody + 1] = 1;  // says one axis, but AXES has two
  FixCrc(b);
  EXPECT_EQ(ParseError(b), Error::kThermalBadAxisCount);
  // The writer refuses a model for another axis count than the image's.
  thermal::ThermalModel one = TwoAxisModel();
  one.axis_count = 1;
  one.axis[1] = thermal::AxisModel();
  table::ImageSpec s;
  s.axis_count = 2;
  s.axes[0] = testing::LinearAxis('X');
  s.axes[1] = testing::LinearAxis('Y');
  s.thermal = &one;
  EXPECT_EQ(table::ImageSize(s).error(), Error::kWriterBadArgument);
}

// The model's terms are micrometres of a linear axis: a coefficient on a rotary axis makes the
// image invalid (a rotary axis with all-zero coefficients is fine). The writer checks what it
// wrote with the parser, so it refuses such an image with the parser's error.
TEST(ThermalSection, ARotaryAxisHasNoThermalTerm) {
  const auto write_error = [](const table::ImageSpec& spec) {
    const Result<uint32_t> size = table::ImageSize(spec);
    EXPECT_TRUE(size.ok());
    AlignedBytes out(*size);
    return table::WriteImage(spec, out.data(), out.size()).error();
  };
  thermal::ThermalModel m = TwoAxisModel();
  table::ImageSpec s;
  s.table_id = 7;
  s.axis_count = 2;
  s.axes[0] = testing::LinearAxis('X');
  s.axes[1] = testing::LinearAxis('A');
  s.axes[1].kind = table::AxisKind::kRotary;
  s.thermal = &m;
  EXPECT_EQ(write_error(s), Error::kThermalOnRotaryAxis);
  m.axis[1].offset_um_per_K[2] = 0.0f;
  EXPECT_EQ(ParseError(testing::WriteImageBytes(s)), Error::kOk);
  m.axis[1].slope_um_per_K_m[0] = 2.0f;
  EXPECT_EQ(write_error(s), Error::kThermalOnRotaryAxis);
}

TEST(ThermalSection, AnImageOfTheModelAloneIsACorrection) {
  const AlignedBytes img = Image(TwoAxisModel(), /*with_axis_table=*/false);
  ASSERT_NE(img.size(), 0u);
  const auto v = table::ParseImage(img.data(), img.size());
  ASSERT_TRUE(v.ok()) << v.status().name();
  EXPECT_FALSE(v->grid.present);
  EXPECT_EQ(v->axis1d_count, 0);
  EXPECT_NE(v->thermal, nullptr);
}

TEST(ThermalSection, ImagesWithoutItKeepMinorVersionZero) {
  int16_t values[2] = {0, 4};
  table::ImageSpec s;
  s.axis_count = 1;
  s.axes[0] = testing::LinearAxis('X');
  s.axis1d_count = 1;
  s.axis1d[0].dim = {2, 0, 1000};
  s.axis1d[0].forward.i16 = values;
  const AlignedBytes img = testing::WriteImageBytes(s);
  const auto v = table::ParseImage(img.data(), img.size());
  ASSERT_TRUE(v.ok());
  EXPECT_EQ(v->version_minor, 0);
  EXPECT_EQ(v->thermal, nullptr);
}

}  // namespace
}  // namespace volcomp
