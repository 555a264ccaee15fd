// Table image validation: valid round trip, truncation, CRC, every field out of range.
#include "volcomp/table/table_image.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <set>

#include "test_tables.hpp"

namespace volcomp {
namespace {

using table::ParseImage;
using testing::AlignedBytes;
using testing::FixCrc;

// A small image with every section kind: AXES (X,Y,Z,A), GRID3 int16, AXIS1D on X with reverse,
// AXIS1D on A with wrap, INFO.
struct Fixture {
  std::vector<int16_t> grid = std::vector<int16_t>(3 * 3 * 2 * 3, 5);
  std::vector<int16_t> fwd = {1, 2, 3, 4}, rev = {-1, -2, -3, -4};
  std::vector<int32_t> wrap = {10, 20, 30, 10};
  std::string info = "machine=test\nowner=qa\n";
  AlignedBytes Build() const {
    table::GridSpec g;
    g.frac_bits = 4;
    g.dim[0] = {3, -100, 50};
    g.dim[1] = {3, 0, 40};
    g.dim[2] = {2, 10, 30};
    g.values.type = table::ElementType::kInt16;
    g.values.i16 = grid.data();
    table::ImageSpec s;
    s.table_id = 0xA5A5;
    s.axis_count = 4;
    s.axes[0] = testing::LinearAxis('X');
    s.axes[1] = testing::LinearAxis('Y', 500000);
    s.axes[2] = testing::LinearAxis('Z');
    s.axes[3] = {'A', table::AxisKind::kRotary, 1000000};
    s.grid = &g;
    s.axis1d_count = 2;
    table::Axis1dSpec& x = s.axis1d[0];
    x.axis = 0;
    x.frac_bits = 2;
    x.dim = {4, 0, 100};
    x.forward.type = x.reverse.type = table::ElementType::kInt16;
    x.forward.i16 = fwd.data();
    x.has_reverse = true;
    x.reverse.i16 = rev.data();
    x.backlash_q8 = 128;
    table::Axis1dSpec& a = s.axis1d[1];
    a.axis = 3;
    a.dim = {4, 0, 1000};
    a.period_steps = 3000;
    a.forward.type = table::ElementType::kInt32;
    a.forward.i32 = wrap.data();
    s.info = info.data();
    s.info_size = static_cast<uint32_t>(info.size());
    const auto size = table::ImageSize(s);
    AlignedBytes out(*size);
    EXPECT_TRUE(table::WriteImage(s, out.data(), out.size()).ok());
    return out;
  }
};

// Byte offsets inside the fixture image (header 24, AXES section header 8 + body 4 + 4*8).
constexpr size_t kAxesBody = 24 + 8;
constexpr size_t kGridHeader = kAxesBody + 4 + 4 * 8;
constexpr size_t kGridBody = kGridHeader + 8;
// GRID3 data: 3*3*2*3 int16 = 108 bytes -> body 44 + 108 = 152.
constexpr size_t kAxisXHeader = kGridBody + 152;
constexpr size_t kAxisXBody = kAxisXHeader + 8;
constexpr size_t kAxisABody = kAxisXBody + 24 + 16 + 8;

Error ParseError(const AlignedBytes& img) { return ParseImage(img.data(), img.size()).error(); }

TEST(TableImage, ValidImageRoundTrips) {
  const AlignedBytes img = Fixture().Build();
  const auto v = ParseImage(img.data(), img.size());
  ASSERT_TRUE(v.ok()) << v.status().name();
  EXPECT_EQ(v->table_id, 0xA5A5u);
  EXPECT_EQ(v->axis_count, 4);
  EXPECT_EQ(v->axes[1].name, 'Y');
  EXPECT_EQ(v->axes[1].resolution_e9, 500000u);
  EXPECT_EQ(v->axes[3].kind, table::AxisKind::kRotary);
  ASSERT_TRUE(v->grid.present);
  EXPECT_EQ(v->grid.dim[0].origin_steps, -100);
  EXPECT_EQ(v->grid.dim[2].nodes, 2u);
  EXPECT_EQ(v->grid.frac_bits, 4);
  EXPECT_EQ(v->axis1d_count, 2);
  EXPECT_EQ(v->axis1d[0].backlash_q8, 128);
  EXPECT_NE(v->axis1d[0].reverse, nullptr);
  EXPECT_EQ(v->axis1d[1].period_steps, 3000u);
  EXPECT_EQ(std::string(v->info, v->info_size), Fixture().info);
  EXPECT_EQ(v->crc32, LoadLe32(img.data() + img.size() - 4));
  EXPECT_EQ(table::ElementSteps(v->axis1d[0].reverse, table::ElementType::kInt16, 2, 3), -1.0);
  // Layout assumptions of the field tests below.
  EXPECT_EQ(LoadLe16(img.data() + kGridHeader), 2);
  EXPECT_EQ(LoadLe16(img.data() + kAxisXHeader), 3);
  EXPECT_EQ(img.data()[kAxisABody], 3);
}

TEST(TableImage, EveryTruncationIsRefused) {
  const AlignedBytes img = Fixture().Build();
  for (size_t n = 0; n < img.size(); ++n) {
    AlignedBytes cut(img.data(), n);
    const Error e = ParseError(cut);
    EXPECT_TRUE(e == Error::kImageTooShort || e == Error::kImageSizeMismatch)
        << n << " " << ErrorName(e);
  }
  // Header claims the cut size too (a consistent but shortened image): CRC or structure fails.
  for (size_t n = 28; n < img.size(); n += 4) {
    AlignedBytes cut(img.data(), n);
    StoreLe32(cut.data() + 8, static_cast<uint32_t>(n));
    EXPECT_NE(ParseError(cut), Error::kOk) << n;
    FixCrc(cut);
    EXPECT_NE(ParseError(cut), Error::kOk) << n;
  }
}

TEST(TableImage, EveryCorruptedByteIsRefusedByCrc) {
  const AlignedBytes img = Fixture().Build();
  for (size_t i = 0; i < img.size(); ++i) {
    AlignedBytes bad(img.data(), img.size());
    bad[i] ^= 0x5A;
    const Error e = ParseError(bad);
    // Bytes the parser reads before the CRC check may fail earlier, with their own code.
    if (i < 24) {
      EXPECT_NE(e, Error::kOk) << i;
    } else {
      EXPECT_EQ(e, Error::kImageBadCrc) << i;
    }
  }
}

TEST(TableImage, MisalignedAndNullAreRefused) {
  const AlignedBytes img = Fixture().Build();
  AlignedBytes shifted(img.size() + 1);
  std::memcpy(shifted.data() + 1, img.data(), img.size());
  EXPECT_EQ(ParseImage(shifted.data() + 1, img.size()).error(), Error::kImageMisaligned);
  EXPECT_EQ(ParseImage(nullptr, 100).error(), Error::kImageTooShort);
}

struct FieldCase {
  const char* what;
  std::function<void(AlignedBytes&)> edit;
  Error expected;
};

// Each edit keeps the CRC valid, so the field check itself must catch it.
TEST(TableImage, EveryFieldOutOfRangeHasItsError) {
  auto u8 = [](size_t off, uint8_t v) { return [=](AlignedBytes& b) { b[off] = v; }; };
  auto u16 = [](size_t off, uint16_t v) {
    return [=](AlignedBytes& b) { StoreLe16(b.data() + off, v); };
  };
  auto u32 = [](size_t off, uint32_t v) {
    return [=](AlignedBytes& b) { StoreLe32(b.data() + off, v); };
  };
  const std::vector<FieldCase> cases = {
      {"magic", u32(0, 0x12345678), Error::kImageBadMagic},
      {"major version", u8(4, 2), Error::kImageUnsupportedVersion},
      {"header size", u16(6, 28), Error::kImageBadHeaderSize},
      {"flags", u16(18, 1), Error::kImageReservedNotZero},
      {"reserved", u32(20, 1), Error::kImageReservedNotZero},
      {"section count 0", u16(16, 0), Error::kImageBadSectionCount},
      {"section count 17", u16(16, 17), Error::kImageBadSectionCount},
      {"section count 6", u16(16, 6), Error::kSectionTruncated},
      {"section count 4", u16(16, 4), Error::kImageTrailingBytes},
      {"section length odd", u32(kGridHeader + 4, 151), Error::kSectionBadLength},
      {"section length long", u32(kGridHeader + 4, 100000), Error::kSectionTruncated},
      {"section flags", u16(kGridHeader + 2, 2), Error::kImageReservedNotZero},
      {"unknown mandatory section", u16(kGridHeader, 99), Error::kSectionUnknown},
      {"axes duplicate", u16(kGridHeader, 1), Error::kSectionDuplicate},
      {"axis1d as a second grid", u16(kAxisXHeader, 2), Error::kSectionDuplicate},
      {"axis count 0", u8(kAxesBody, 0), Error::kAxesBadCount},
      {"axis count 7", u8(kAxesBody, 7), Error::kAxesBadCount},
      {"axis count 3", u8(kAxesBody, 3), Error::kSectionBadLength},
      {"axes reserved", u8(kAxesBody + 1, 1), Error::kImageReservedNotZero},
      {"axis name", u8(kAxesBody + 4, 'Q'), Error::kAxesBadName},
      {"axis name repeated", u8(kAxesBody + 12, 'X'), Error::kAxesBadName},
      {"axis kind", u8(kAxesBody + 5, 2), Error::kAxesBadKind},
      {"axis reserved", u16(kAxesBody + 6, 1), Error::kImageReservedNotZero},
      {"axis resolution 0", u32(kAxesBody + 8, 0), Error::kAxesBadResolution},
      {"grid element 0", u8(kGridBody, 0), Error::kElementBadType},
      {"grid element 4", u8(kGridBody, 4), Error::kElementBadType},
      {"grid element int32 (size)", u8(kGridBody, 2), Error::kSectionBadLength},
      {"grid frac 9", u8(kGridBody + 1, 9), Error::kElementBadFracBits},
      {"grid axis index", u8(kGridBody + 2, 4), Error::kAxisIndexInvalid},
      {"grid axis repeated", u8(kGridBody + 3, 0), Error::kGridDuplicateAxis},
      {"grid reserved", u8(kGridBody + 6, 1), Error::kImageReservedNotZero},
      {"grid nodes 0", u32(kGridBody + 8, 0), Error::kGridBadNodeCount},
      {"grid nodes 1", u32(kGridBody + 8, 1), Error::kGridBadNodeCount},
      {"grid nodes 1025", u32(kGridBody + 8, 1025), Error::kGridBadNodeCount},
      {"grid nodes huge", u32(kGridBody + 12, 0xFFFFFFFF), Error::kGridBadNodeCount},
      {"grid nodes 4 (size)", u32(kGridBody + 8, 4), Error::kSectionBadLength},
      {"grid spacing 0", u32(kGridBody + 32, 0), Error::kBadSpacing},
      {"grid spacing huge", u32(kGridBody + 32, 0x80000000u), Error::kBadSpacing},
      {"grid extent overflow", u32(kGridBody + 20, 0x7FFFFFF0u), Error::kGridExtentOverflow},
      {"axis1d axis index", u8(kAxisXBody, 9), Error::kAxisIndexInvalid},
      {"axis1d duplicate axis", u8(kAxisABody, 0), Error::kSectionDuplicate},
      {"axis1d element", u8(kAxisXBody + 1, 7), Error::kElementBadType},
      {"axis1d frac", u8(kAxisXBody + 2, 12), Error::kElementBadFracBits},
      {"axis1d flags", u8(kAxisXBody + 3, 0x81), Error::kAxis1dBadFlags},
      {"axis1d nodes 1", u32(kAxisXBody + 4, 1), Error::kAxis1dBadNodeCount},
      {"axis1d nodes 5 (size)", u32(kAxisXBody + 4, 5), Error::kSectionBadLength},
      {"axis1d spacing 0", u32(kAxisXBody + 12, 0), Error::kBadSpacing},
      {"axis1d period without wrap", u32(kAxisXBody + 16, 300), Error::kAxis1dBadPeriod},
      {"axis1d backlash", u32(kAxisXBody + 20, 0x7FFFFFFF), Error::kValueOutOfRange},
      {"axis1d wrap period", u32(kAxisABody + 16, 2999), Error::kAxis1dBadPeriod},
      {"axis1d wrap discontinuous", u32(kAxisABody + 24 + 12, 11), Error::kAxis1dWrapDiscontinuous},
      {"axis1d int32 value", u32(kAxisABody + 24 + 4, 0x7FFFFFFF), Error::kValueOutOfRange},
  };
  const AlignedBytes good = Fixture().Build();
  std::set<Error> seen;
  for (const FieldCase& c : cases) {
    AlignedBytes b(good.data(), good.size());
    c.edit(b);
    FixCrc(b);
    EXPECT_EQ(ParseError(b), c.expected) << c.what << ": got " << ErrorName(ParseError(b));
    seen.insert(c.expected);
  }
  EXPECT_GE(seen.size(), 25u);
}

TEST(TableImage, FloatValuesMustBeFiniteAndInRange) {
  std::vector<float> v(2 * 2 * 2 * 3, 0.5f);
  table::GridSpec g;
  for (auto& d : g.dim) d = {2, 0, 10};
  g.values.type = table::ElementType::kFloat32;
  g.values.f32 = v.data();
  const AlignedBytes out = testing::WriteImageBytes(testing::XyzImageSpec(g));
  ASSERT_NE(out.size(), 0u);
  const size_t data = 24 + 8 + 4 + 3 * 8 + 8 + 44;
  const std::pair<float, Error> cases[] = {
      {std::nanf(""), Error::kValueNotFinite},
      {INFINITY, Error::kValueNotFinite},
      {-INFINITY, Error::kValueNotFinite},
      {70000.0f, Error::kValueOutOfRange},
      {-65536.0f, Error::kOk},
  };
  for (const auto& [value, expected] : cases) {
    AlignedBytes b(out.data(), out.size());
    StoreLeF32(b.data() + data + 4 * 5, value);
    FixCrc(b);
    EXPECT_EQ(ParseError(b), expected) << value;
  }
  // float with fraction bits is refused.
  AlignedBytes b(out.data(), out.size());
  b[data - 44 + 1] = 1;
  FixCrc(b);
  EXPECT_EQ(ParseError(b), Error::kElementBadFracBits);
}

TEST(TableImage, OptionalUnknownSectionIsSkipped) {
  // An INFO section re-typed as an unknown optional type (flags bit 0 set by the writer).
  AlignedBytes b = Fixture().Build();
  const size_t info_header = b.size() - 4 - 24 - 8;  // INFO body is 24 bytes
  ASSERT_EQ(LoadLe16(b.data() + info_header), 4);
  StoreLe16(b.data() + info_header, 200);
  FixCrc(b);
  const auto v = ParseImage(b.data(), b.size());
  ASSERT_TRUE(v.ok()) << v.status().name();
  EXPECT_EQ(v->info, nullptr);
  // The same section without the optional flag is refused.
  StoreLe16(b.data() + info_header + 2, 0);
  FixCrc(b);
  EXPECT_EQ(ParseError(b), Error::kSectionUnknown);
}

TEST(TableImage, PaddingMustBeZero) {
  // 3x3x3 nodes x 3 int16 = 162 data bytes, padded with 2 zero bytes.
  std::vector<int16_t> v(81, 1);
  table::GridSpec g;
  for (auto& d : g.dim) d = {3, 0, 10};
  g.values.i16 = v.data();
  AlignedBytes b = testing::WriteImageBytes(testing::XyzImageSpec(g));
  ASSERT_NE(b.size(), 0u);
  const size_t pad = 24 + 8 + 28 + 8 + 44 + 162;
  EXPECT_EQ(b[pad], 0);
  b[pad + 1] = 0x10;
  FixCrc(b);
  EXPECT_EQ(ParseError(b), Error::kImageReservedNotZero);
}

TEST(TableImage, InfoTextMustBePrintable) {
  AlignedBytes b = Fixture().Build();
  const size_t info_body = b.size() - 4 - 24;
  b[info_body + 2] = 0x01;
  FixCrc(b);
  EXPECT_EQ(ParseError(b), Error::kInfoBadText);
}

TEST(TableImage, WriterRefusesBadArguments) {
  table::ImageSpec s;
  uint8_t buf[64];
  EXPECT_EQ(table::WriteImage(s, buf, sizeof buf).error(), Error::kWriterBadArgument);
  s.axis_count = 1;
  s.axes[0] = testing::LinearAxis('X');
  // No correction section: the writer's own validation reports it.
  alignas(4) uint8_t out[256];
  EXPECT_EQ(table::WriteImage(s, out, sizeof out).error(), Error::kImageNoCorrection);
  int16_t v[2] = {0, 0};
  s.axis1d_count = 1;
  s.axis1d[0].dim = {2, 0, 10};
  s.axis1d[0].forward.i16 = v;
  EXPECT_EQ(table::WriteImage(s, out, 16).error(), Error::kWriterBufferTooSmall);
  EXPECT_TRUE(table::WriteImage(s, out, sizeof out).ok());
}

TEST(TableImage, PeekImageSize) {
  const AlignedBytes img = Fixture().Build();
  EXPECT_EQ(*table::PeekImageSize(img.data(), img.size() + 100), img.size());
  EXPECT_EQ(table::PeekImageSize(img.data(), img.size() - 1).error(), Error::kImageTooLarge);
  EXPECT_EQ(table::PeekImageSize(img.data(), 10).error(), Error::kImageTooShort);
  AlignedBytes erased(256);
  std::memset(erased.data(), 0xFF, 256);
  EXPECT_EQ(table::PeekImageSize(erased.data(), 256).error(), Error::kImageBadMagic);
}

TEST(ErrorNames, AreDistinctAndReadable) {
  std::set<std::string> names;
  for (int i = 0; i < 100; ++i) {
    const std::string n = ErrorName(static_cast<Error>(i));
    if (n == "kUnknown") continue;
    EXPECT_TRUE(names.insert(n).second) << n;
    EXPECT_STRNE(ErrorText(static_cast<Error>(i)), "unknown error");
  }
  EXPECT_GE(names.size(), 40u);
  EXPECT_STREQ(ErrorName(Error::kImageBadCrc), "kImageBadCrc");
}

}  // namespace
}  // namespace volcomp
