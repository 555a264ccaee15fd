// Runs SDO client operations to completion over a blocking frame link (a real CAN transport).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>

#include "volcomp/can/can_frame.hpp"
#include "volcomp/canopen_client/sdo_client.hpp"

namespace volcomp::canopen_client {

/// How the runner talks to the bus.
struct FrameLink {
  std::function<void(const CanFrame&)> send;
  /// Waits up to `timeout_us` for a frame.
  std::function<std::optional<CanFrame>(uint64_t timeout_us)> receive;
  /// Microseconds of a monotonic clock.
  std::function<uint64_t()> now_us;
  /// Frames that are not SDO responses for this client (heartbeat, EMCY): optional observer.
  std::function<void(const CanFrame&)> other;
};

/// Drives `client` (an operation already started) until it completes; returns its result.
const SdoResult& RunToCompletion(SdoClient& client, const FrameLink& link);

/// Convenience operations (each runs to completion).
SdoResult Download(const FrameLink& link,
                   uint8_t node,
                   uint16_t index,
                   uint8_t sub,
                   const std::vector<uint8_t>& data,
                   SdoClient::Options options = {},
                   std::function<void(uint32_t, uint32_t)> progress = {});
SdoResult Upload(const FrameLink& link,
                 uint8_t node,
                 uint16_t index,
                 uint8_t sub,
                 bool block = false,
                 SdoClient::Options options = {});
/// Little-endian helpers for numeric objects.
SdoResult WriteU32(const FrameLink& link,
                   uint8_t node,
                   uint16_t index,
                   uint8_t sub,
                   uint32_t value,
                   uint8_t size_bytes = 4,
                   SdoClient::Options options = {});
/// Reads an unsigned value of 1..4 bytes; on success `*value` is set.
SdoResult ReadU32(const FrameLink& link,
                  uint8_t node,
                  uint16_t index,
                  uint8_t sub,
                  uint32_t* value,
                  SdoClient::Options options = {});

}  // namespace volcomp::canopen_client
