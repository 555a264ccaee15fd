// Table upload over the simulated CAN bus in virtual time, with the real protocol on both ends:
// the PC tool's SDO client code and the firmware's node, each on a bus endpoint. Reports the
// transfer time, the rate, and the theoretical SDO block-transfer limit of the same bus (the
// same payload as an ideal exchange: initiate, every segment, one ack per 127 segments, end,
// back to back with no turnaround), so the efficiency is time_limit / time_measured; and the
// bus's no-stuffing ceiling for block download (NoStuffingCeilingBytesPerS). The figures are in
// docs/canopen.md. The default grid, 31x31x31 int16, is the largest that fits a table bank of the
// STM32G474 reference board (docs/mcu-target.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::sim {

struct UploadBenchOptions {
  uint32_t bitrate = 1000000;
  uint32_t grid_nodes = 31;  // per dimension, int16
  uint64_t poll_period_ns = 100000;
  bool activate = true;
};

struct UploadBenchResult {
  uint32_t image_bytes = 0;
  double transfer_s = 0;  // block download, initiate to end response (virtual time)
  double limit_s = 0;     // ideal exchange of the same payload on the same bus
  double rate_bytes_s = 0;
  double limit_bytes_s = 0;
  double efficiency = 0;       // limit_s / transfer_s
  double ceiling_bytes_s = 0;  // NoStuffingCeilingBytesPerS(bitrate)
  double ceiling_share = 0;    // rate_bytes_s / ceiling_bytes_s
  uint64_t frames = 0;         // frames on the bus during the transfer
  uint32_t resent_segments = 0;
  bool activated = false;
  uint32_t active_crc = 0;
  uint32_t image_crc = 0;
};

/// Builds a grid image of grid_nodes^3 int16 nodes and uploads it to a simulated board. Fails
/// with kInvalidArgument for a bit rate of 0 or a grid the image format refuses, and with the PC
/// tool's explanation when a step of the upload fails ("staging: ...", "verify: ...").
Expected<UploadBenchResult> RunUploadBench(const UploadBenchOptions& options);

/// The most SDO block-download payload a classic CAN bus can carry, in bytes/s: 7 bytes per
/// segment in 8-byte frames of 111 bits without stuff bits (SOF, 11-bit identifier, RTR, IDE, r0,
/// DLC, 64 data bits, CRC 15 + delimiter, ACK 2, EOF 7, intermission 3), and one acknowledgement
/// frame per 127 segments: bitrate * 7 * 127 / (111 * 128).
double NoStuffingCeilingBytesPerS(uint32_t bitrate);

/// Bits of the ideal block-download exchange for `payload` on a bus (see above).
uint64_t IdealBlockDownloadBits(const std::vector<uint8_t>& payload, uint8_t node_id);

}  // namespace volcomp::sim
