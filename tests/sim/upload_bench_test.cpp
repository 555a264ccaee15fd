// Table upload over the simulated 1 Mbit/s bus with the real protocol on both ends (virtual time,
// so the figures are deterministic and may be asserted): a 33x33x33 int16 grid must take <= 5 s
// and reach >= 85 % of the SDO block-transfer limit of the bus, and end up active on the board.
#include "volcomp/sim/upload_bench.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace volcomp {
namespace {

TEST(UploadBench, Grid33Int16AtOneMegabit) {
  const sim::UploadBenchResult r = sim::RunUploadBench(sim::UploadBenchOptions());
  ASSERT_TRUE(r.ok) << r.message;
  std::printf(
      "[ metric ] 33^3 int16 grid, %u bytes at 1 Mbit/s: %.3f s, %.1f kB/s; SDO-block "
      "limit %.3f s, %.1f kB/s; efficiency %.1f %%; %llu frames\n",
      r.image_bytes, r.transfer_s, r.rate_bytes_s / 1000, r.limit_s, r.limit_bytes_s / 1000,
      100 * r.efficiency, static_cast<unsigned long long>(r.frames));
  EXPECT_LE(r.transfer_s, 5.0);
  EXPECT_GE(r.efficiency, 0.85);
  EXPECT_LE(r.efficiency, 1.0);
  EXPECT_TRUE(r.activated);
  EXPECT_EQ(r.active_crc, r.image_crc);
}

TEST(UploadBench, IdealExchangeBitsMatchAHandCount) {
  // 14 bytes: initiate + response, 2 segments, 1 ack, end + response = 7 frames of 8 bytes.
  const std::vector<uint8_t> payload(14, 0x55);
  const uint64_t bits = sim::IdealBlockDownloadBits(payload, 0x10);
  // Each 8-byte data frame is 111 bits plus 0..24 stuff bits (11-bit id, 3-bit intermission).
  EXPECT_GE(bits, 7u * 111u);
  EXPECT_LE(bits, 7u * 135u);
}

}  // namespace
}  // namespace volcomp
