// A CAN controller port (classic CAN 2.0A/B, 8-byte frames). Send() queues a frame for
// transmission and never blocks; Receive() pops the next received frame if any. SetBitrate()
// applies the bit rate of the configuration in force (the board application calls it at start and
// at every node reset). Main-loop use only; backends: mock (tests), the simulated bus, SocketCAN,
// FDCAN (MCU).
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/can/can_frame.hpp"

namespace volcomp::hal {

using volcomp::CanFrame;

class CanPort {
 public:
  /// Queues `frame`; kFull when the transmit queue is full, kInvalidArgument for a bad frame.
  Status Send(const CanFrame& frame) {
    if (!frame.valid()) return Error::kInvalidArgument;
    return DoSend(frame);
  }
  /// Pops the next received frame into *frame; false when none is waiting.
  bool Receive(CanFrame* frame) { return DoReceive(frame); }
  /// Runs the controller at `bitrate_bps` bit/s (re-initialising it: frames queued or being
  /// received are lost, as at a CANopen reset). kInvalidArgument for 0; kConfigInvalid when the
  /// controller cannot produce that rate exactly (the previous rate stays); kCanBitrateMismatch
  /// when the port cannot set the rate itself and the interface runs at another one (SocketCAN:
  /// the rate belongs to the network interface).
  Status SetBitrate(uint32_t bitrate_bps) {
    if (bitrate_bps == 0) return Error::kInvalidArgument;
    return DoSetBitrate(bitrate_bps);
  }

 protected:
  ~CanPort() = default;  // not deletable through the interface (no heap in firmware)

 private:
  virtual Status DoSend(const CanFrame& frame) = 0;
  virtual bool DoReceive(CanFrame* frame) = 0;
  virtual Status DoSetBitrate(uint32_t bitrate_bps) = 0;
};

}  // namespace volcomp::hal
