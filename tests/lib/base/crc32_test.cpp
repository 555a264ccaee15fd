// CRC-32 (zlib) against its published check values and a bit-serial reference written from the
// non-reflected definition (polynomial 0x04C11DB7, input and output bit-reversed).
#include "volcomp/base/crc32.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

namespace volcomp {
namespace {

uint32_t Reflect(uint32_t v, int bits) {
  uint32_t r = 0;
  for (int i = 0; i < bits; ++i) r |= ((v >> i) & 1u) << (bits - 1 - i);
  return r;
}

// MSB-first long division by 0x04C11DB7 on the bit-reversed bytes, init 0xFFFFFFFF, output
// reversed and inverted: the textbook definition, not the table's reflected shortcut.
uint32_t ReferenceCrc32(const uint8_t* data, size_t size) {
  uint32_t crc = 0xFFFFFFFFu;
  for (size_t i = 0; i < size; ++i) {
    crc ^= Reflect(data[i], 8) << 24;
    for (int k = 0; k < 8; ++k) crc = (crc & 0x80000000u) ? (crc << 1) ^ 0x04C11DB7u : crc << 1;
  }
  return Reflect(crc, 32) ^ 0xFFFFFFFFu;
}

uint32_t OfString(const char* s) {
  return ComputeCrc32(reinterpret_cast<const uint8_t*>(s), std::strlen(s));
}

TEST(Crc32, PublishedCheckValues) {
  EXPECT_EQ(OfString("123456789"), 0xCBF43926u);  // the CRC catalogue's check value
  EXPECT_EQ(OfString("The quick brown fox jumps over the lazy dog"), 0x414FA339u);
  EXPECT_EQ(OfString(""), 0x00000000u);
  EXPECT_EQ(OfString("a"), 0xE8B7BE43u);
}

TEST(Crc32, IncrementalEqualsWhole) {
  const char* s = "123456789";
  const auto* p = reinterpret_cast<const uint8_t*>(s);
  for (size_t cut = 0; cut <= 9; ++cut) {
    Crc32 c;
    c.Update(p, cut);
    c.Update(p + cut, 9 - cut);
    EXPECT_EQ(c.value(), 0xCBF43926u) << "split at " << cut;
  }
  Crc32 none;
  EXPECT_EQ(none.value(), 0u);
}

TEST(Crc32, EqualsTheBitSerialDefinitionOnRandomData) {
  std::mt19937_64 rng(26);
  for (int n = 0; n < 300; ++n) {
    std::vector<uint8_t> data(static_cast<size_t>(rng() % 200));
    for (auto& b : data) b = static_cast<uint8_t>(rng());
    ASSERT_EQ(ComputeCrc32(data.data(), data.size()), ReferenceCrc32(data.data(), data.size()))
        << "length " << data.size();
  }
}

}  // namespace
}  // namespace volcomp
