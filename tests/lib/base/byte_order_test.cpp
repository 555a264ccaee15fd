// Little-endian loads and stores at any alignment, against byte values written out by hand.
#include "volcomp/base/byte_order.hpp"

#include <gtest/gtest.h>

#include <cstring>

namespace volcomp {
namespace {

TEST(ByteOrder, LoadsLittleEndianAtEveryAlignment) {
  uint8_t buf[8] = {0x00, 0x78, 0x56, 0x34, 0x12, 0xFF, 0xFE, 0x00};
  EXPECT_EQ(LoadLe16(buf + 1), 0x5678u);
  EXPECT_EQ(LoadLe32(buf + 1), 0x12345678u);  // odd address
  EXPECT_EQ(LoadLe32(buf + 2), 0xFF123456u);
  EXPECT_EQ(LoadLe16(buf + 5), 0xFEFFu);
  const uint8_t minus_two[4] = {0xFE, 0xFF, 0xFF, 0xFF};
  EXPECT_EQ(LoadLeI32(minus_two), -2);
  const uint8_t int_min[4] = {0x00, 0x00, 0x00, 0x80};
  EXPECT_EQ(LoadLeI32(int_min), INT32_MIN);
}

TEST(ByteOrder, StoresLittleEndian) {
  uint8_t buf[7] = {};
  StoreLe32(buf + 1, 0xA1B2C3D4u);
  StoreLe16(buf + 5, 0x0102u);
  const uint8_t want[7] = {0x00, 0xD4, 0xC3, 0xB2, 0xA1, 0x02, 0x01};
  EXPECT_EQ(std::memcmp(buf, want, sizeof buf), 0);
}

TEST(ByteOrder, Float32IsItsIeeeBitPattern) {
  uint8_t buf[5] = {};
  StoreLeF32(buf + 1, 1.0f);  // 0x3F800000
  EXPECT_EQ(buf[1], 0x00);
  EXPECT_EQ(buf[2], 0x00);
  EXPECT_EQ(buf[3], 0x80);
  EXPECT_EQ(buf[4], 0x3F);
  EXPECT_EQ(LoadLeF32(buf + 1), 1.0f);
  const uint8_t minus_2_5[4] = {0x00, 0x00, 0x20, 0xC0};  // -2.5 = 0xC0200000
  EXPECT_EQ(LoadLeF32(minus_2_5), -2.5f);
}

}  // namespace
}  // namespace volcomp
