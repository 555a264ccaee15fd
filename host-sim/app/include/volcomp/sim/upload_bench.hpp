// Table upload over the simulated CAN bus in virtual time, with the real protocol on both ends:
// the PC tool's SDO client code and the firmware's node, each on a bus endpoint. Reports the
// transfer time, the rate, and the theoretical SDO block-transfer limit of the same bus (the
// same payload as an ideal exchange: initiate, every segment, one ack per 127 segments, end,
// back to back with no turnaround), so the efficiency is time_limit / time_measured.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace volcomp::sim {

struct UploadBenchOptions {
  uint32_t bitrate = 1000000;
  uint32_t grid_nodes = 33;  // per dimension, int16
  uint64_t poll_period_ns = 100000;
  bool activate = true;
};

struct UploadBenchResult {
  bool ok = false;
  std::string message;
  uint32_t image_bytes = 0;
  double transfer_s = 0;  // block download, initiate to end response (virtual time)
  double limit_s = 0;     // ideal exchange of the same payload on the same bus
  double rate_bytes_s = 0;
  double limit_bytes_s = 0;
  double efficiency = 0;  // limit_s / transfer_s
  uint64_t frames = 0;    // frames on the bus during the transfer
  uint32_t resent_segments = 0;
  bool activated = false;
  uint32_t active_crc = 0;
  uint32_t image_crc = 0;
};

/// Builds a grid image of grid_nodes^3 int16 nodes and uploads it to a simulated board.
UploadBenchResult RunUploadBench(const UploadBenchOptions& options);

/// Bits of the ideal block-download exchange for `payload` on a bus (see above).
uint64_t IdealBlockDownloadBits(const std::vector<uint8_t>& payload, uint8_t node_id);

}  // namespace volcomp::sim
