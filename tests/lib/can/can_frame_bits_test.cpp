// CanFrameBits: exact frame length incl. stuff bits, against hand-derived values, an independent
// reference (CRC by polynomial long division, stuffing on a bit vector) and the bounds of
// can-protocols.md §1.5.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "volcomp/can/can_frame.hpp"

namespace volcomp {
namespace {

CanFrame Make(uint32_t id, bool ext, bool rtr, std::vector<uint8_t> data, int dlc = -1) {
  CanFrame f;
  f.id = id;
  f.extended = ext;
  f.rtr = rtr;
  f.dlc = static_cast<uint8_t>(dlc >= 0 ? dlc : static_cast<int>(data.size()));
  for (size_t i = 0; i < data.size() && i < 8; ++i) f.data[i] = data[i];
  return f;
}

// Independent reference: build the unstuffed bit string SOF..CRC, compute the CRC-15 by long
// division by x^15+x^14+x^10+x^8+x^7+x^4+x^3+1, then count stuff bits on the final string.
uint32_t ReferenceBits(const CanFrame& f) {
  std::vector<int> b{0};
  auto put = [&b](uint32_t v, int n) {
    for (int i = n - 1; i >= 0; --i) b.push_back(static_cast<int>((v >> i) & 1));
  };
  if (f.extended) {
    put(f.id >> 18, 11);
    put(3, 2);  // SRR, IDE
    put(f.id & 0x3FFFF, 18);
    put(f.rtr, 1);
    put(0, 2);
  } else {
    put(f.id, 11);
    put(f.rtr, 1);
    put(0, 2);
  }
  put(f.dlc, 4);
  if (!f.rtr) {
    for (int i = 0; i < f.dlc; ++i) put(f.data[i], 8);
  }
  const int poly[16] = {1, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
  std::vector<int> reg(b);
  reg.resize(b.size() + 15, 0);
  for (size_t i = 0; i < b.size(); ++i) {
    if (reg[i] != 0) {
      for (int j = 0; j < 16; ++j) reg[i + j] ^= poly[j];
    }
  }
  b.insert(b.end(), reg.end() - 15, reg.end());
  uint32_t stuff = 0;
  int run = 0;
  int last = -1;
  for (int bit : b) {
    run = bit == last ? run + 1 : 1;
    last = bit;
    if (run == 5) {
      ++stuff;
      last = 1 - bit;
      run = 1;
    }
  }
  return static_cast<uint32_t>(b.size()) + stuff + 13;
}

TEST(CanIoFrameBits, AllZeroHeaderHandDerived) {
  // id 0, DLC 0: SOF + 11 id + RTR + IDE + r0 + 4 DLC = 19 zeros; the CRC of zeros is 0, so 34
  // zeros in a row get a stuff bit after every 5th: 6 stuff bits. 47 + 6 = 53.
  EXPECT_EQ(CanFrameBits(Make(0, false, false, {})), 53u);
}

TEST(CanIoFrameBits, NoStuffingOpportunity) {
  // 0x2AA with eight 0xAA bytes: alternating bits, runs of at most 4 in header and CRC
  // (bit string 0 01010101010 000 1000 1010... CRC 000011110101101): the 111-bit minimum.
  EXPECT_EQ(CanFrameBits(Make(0x2AA, false, false, std::vector<uint8_t>(8, 0xAA))), 111u);
}

TEST(CanIoFrameBits, HandCheckedValues) {
  EXPECT_EQ(CanFrameBits(Make(0, false, false, std::vector<uint8_t>(8, 0x00))), 127u);
  EXPECT_EQ(CanFrameBits(Make(0x7FF, false, false, std::vector<uint8_t>(8, 0xFF))), 126u);
  EXPECT_EQ(CanFrameBits(Make(0x555, false, false, std::vector<uint8_t>(8, 0x55))), 112u);
  EXPECT_EQ(CanFrameBits(Make(0x123, false, false, {0x11, 0x22, 0x33, 0x44})), 80u);
  EXPECT_EQ(CanFrameBits(Make(0x601, false, false, {0x40, 0, 0x10, 0, 0, 0, 0, 0})), 124u);
  EXPECT_EQ(CanFrameBits(Make(0x12345678, true, false, {1, 2, 3, 4, 5, 6, 7, 8})), 140u);
  EXPECT_EQ(CanFrameBits(Make(0x1FFFFFFF, true, false, {})), 74u);
  EXPECT_EQ(CanFrameBits(Make(0, true, false, std::vector<uint8_t>(8, 0))), 150u);
}

TEST(CanIoFrameBits, RemoteFramesCarryNoData) {
  EXPECT_EQ(CanFrameBits(Make(0x7FF, false, true, {})), 50u);
  // DLC 4 is transmitted, the data bytes are not (even if the struct holds some).
  EXPECT_EQ(CanFrameBits(Make(0x123, false, true, {1, 2, 3, 4})), 47u);
}

TEST(CanIoFrameBits, MatchesIndependentReferenceOnRandomFrames) {
  std::mt19937 rng(7);
  for (int i = 0; i < 20000; ++i) {
    CanFrame f;
    f.extended = (rng() & 1) != 0;
    f.rtr = (rng() % 8) == 0;
    f.id = static_cast<uint32_t>(rng()) & (f.extended ? 0x1FFFFFFFu : 0x7FFu);
    f.dlc = static_cast<uint8_t>(rng() % 9);
    // Bias towards long runs so stuffing is exercised hard.
    const int mode = static_cast<int>(rng() % 3);
    for (auto& d : f.data) {
      d = mode == 0 ? static_cast<uint8_t>(rng()) : (mode == 1 ? 0x00 : 0xFF);
    }
    ASSERT_EQ(CanFrameBits(f), ReferenceBits(f)) << i;
  }
}

TEST(CanIoFrameBits, BoundsForEightByteFrames) {
  // can-protocols.md §1.5: standard 8-byte frames take 111 + 0..24 bits. Extended: 131 + 0..29
  // (worst case floor((stuffed length - 1) / 4) over the 118 stuffed bits).
  std::mt19937 rng(11);
  uint32_t lo = 1000, hi = 0, elo = 1000, ehi = 0;
  for (int i = 0; i < 50000; ++i) {
    CanFrame f;
    f.extended = (i & 1) != 0;
    f.id = static_cast<uint32_t>(rng()) & (f.extended ? 0x1FFFFFFFu : 0x7FFu);
    f.dlc = 8;
    for (auto& d : f.data) d = static_cast<uint8_t>((rng() % 4 == 0) ? 0 : rng());
    const uint32_t bits = CanFrameBits(f);
    if (f.extended) {
      elo = std::min(elo, bits);
      ehi = std::max(ehi, bits);
    } else {
      lo = std::min(lo, bits);
      hi = std::max(hi, bits);
    }
  }
  EXPECT_GE(lo, 111u);
  EXPECT_LE(hi, 135u);
  EXPECT_GE(elo, 131u);
  EXPECT_LE(ehi, 160u);
}

TEST(CanIoFrameBits, HeavyStuffing) {
  // 0x3C bytes (00111100) put a stuff bit into nearly every byte: 20 stuff bits with id 0x02F,
  // the longest among ids 0..0x7FF with 0x0F/0x78/0x3C/0x1E/0xF0/0x87/0xC3/0xE1 payloads
  // (computed independently for these notes).
  EXPECT_EQ(CanFrameBits(Make(0x02F, false, false, std::vector<uint8_t>(8, 0x3C))), 131u);
}

}  // namespace
}  // namespace volcomp
