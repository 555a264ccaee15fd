// Runs SDO client operations to completion over a blocking frame link (a real CAN transport, or
// the simulator's bus advanced event by event). A failure of the link ends the operation with the
// link's failure (SdoFailure without an abort).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "volcomp/can/can_frame.hpp"
#include "volcomp/canopen_client/sdo_client.hpp"

namespace volcomp::canopen_client {

/// How the runner talks to the bus.
struct FrameLink {
  std::function<Outcome(const CanFrame&)> send;
  /// Waits up to `timeout_us` for a frame (nullopt: none came).
  std::function<Expected<std::optional<CanFrame>>(uint64_t timeout_us)> receive;
  /// Microseconds of a monotonic clock.
  std::function<uint64_t()> now_us;
  /// Frames that are not SDO responses for this client (heartbeat, EMCY): optional observer.
  std::function<void(const CanFrame&)> other;
  /// What the link knows that may explain a failed transfer (e.g. frames the kernel dropped),
  /// appended to its message; empty: nothing. Optional.
  std::function<std::string()> diagnose;
};

/// Drives `client` (an operation already started) until it completes; returns its result.
const SdoExpected<std::vector<uint8_t>>& RunToCompletion(SdoClient& client, const FrameLink& link);

/// Writes `data` to (index, sub) of `node` (an SDO download: expedited, block or segmented as
/// the options say); `progress(bytes_done, total)` as acknowledgements arrive.
SdoOutcome WriteObject(const FrameLink& link,
                       uint8_t node,
                       uint16_t index,
                       uint8_t sub,
                       const std::vector<uint8_t>& data,
                       SdoClient::Options options = {},
                       std::function<void(uint32_t, uint32_t)> progress = {});
/// Reads (index, sub) of `node` (an SDO upload; `block` for block transfer).
SdoExpected<std::vector<uint8_t>> ReadObject(const FrameLink& link,
                                             uint8_t node,
                                             uint16_t index,
                                             uint8_t sub,
                                             bool block = false,
                                             SdoClient::Options options = {});
/// Writes an unsigned value as `size_bytes` little-endian bytes.
SdoOutcome WriteU32(const FrameLink& link,
                    uint8_t node,
                    uint16_t index,
                    uint8_t sub,
                    uint32_t value,
                    uint8_t size_bytes = 4,
                    SdoClient::Options options = {});
/// Reads an unsigned value of 1..4 bytes (another size: kInputInvalid, no abort).
SdoExpected<uint32_t> ReadU32(const FrameLink& link,
                              uint8_t node,
                              uint16_t index,
                              uint8_t sub,
                              SdoClient::Options options = {});

}  // namespace volcomp::canopen_client
