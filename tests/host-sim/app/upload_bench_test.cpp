// Table upload over the simulated 1 Mbit/s bus with the real protocol on both ends (virtual time,
// so the figures are deterministic and may be asserted): a 31x31x31 int16 grid (the largest that
// fits a table bank of the STM32G474 reference board) must take <= 5 s, reach >= 85 % of the SDO
// block-transfer limit of the bus and stay below the bus's no-stuffing ceiling, and end up active
// on the board.
#include "volcomp/sim/upload_bench.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace volcomp {
namespace {

TEST(UploadBench, Grid31Int16AtOneMegabit) {
  const Expected<sim::UploadBenchResult> run = sim::RunUploadBench(sim::UploadBenchOptions());
  ASSERT_TRUE(run.ok()) << run.error().message;
  const sim::UploadBenchResult& r = *run;
  std::printf(
      "[ metric ] 31^3 int16 grid, %u bytes at 1 Mbit/s: %.3f s, %.1f kB/s; SDO-block "
      "limit %.3f s, %.1f kB/s; efficiency %.1f %%; bus ceiling %.1f kB/s (%.1f %% of it); "
      "%llu frames\n",
      r.image_bytes, r.transfer_s, r.rate_bytes_s / 1000, r.limit_s, r.limit_bytes_s / 1000,
      100 * r.efficiency, r.ceiling_bytes_s / 1000, 100 * r.ceiling_share,
      static_cast<unsigned long long>(r.frames));
  // The reference board's table bank: 176 KB less the store's records (docs/mcu-target.md).
  EXPECT_LE(r.image_bytes, 176u * 1024u - 64u);
  EXPECT_LE(r.transfer_s, 5.0);
  EXPECT_LT(r.rate_bytes_s, r.ceiling_bytes_s);
  EXPECT_GE(r.efficiency, 0.85);
  EXPECT_LE(r.efficiency, 1.0);
  EXPECT_TRUE(r.activated);
  EXPECT_EQ(r.active_crc, r.image_crc);
}

TEST(UploadBench, OptionsTheBenchCannotRunAreFailures) {
  sim::UploadBenchOptions o;
  o.bitrate = 0;
  const Expected<sim::UploadBenchResult> no_bus = sim::RunUploadBench(o);
  ASSERT_FALSE(no_bus.ok());
  EXPECT_EQ(no_bus.error().code, Error::kInvalidArgument);
  o = sim::UploadBenchOptions();
  o.grid_nodes = 1;  // GRID3 needs 2..1024 nodes per dimension
  const Expected<sim::UploadBenchResult> no_grid = sim::RunUploadBench(o);
  ASSERT_FALSE(no_grid.ok());
  EXPECT_EQ(no_grid.error().code, Error::kGridBadNodeCount);
  EXPECT_NE(no_grid.error().message.find("grid image"), std::string::npos)
      << no_grid.error().message;
}

TEST(UploadBench, NoStuffingCeilingMatchesAHandCount) {
  // 1 Mbit/s: 9009 frames of 111 bits per second; of every 128 frames 127 carry 7 bytes.
  EXPECT_NEAR(sim::NoStuffingCeilingBytesPerS(1000000), 62570, 1);
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
