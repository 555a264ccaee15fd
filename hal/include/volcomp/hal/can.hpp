// A CAN controller port (classic CAN 2.0A/B, 8-byte frames). Send() queues a frame for
// transmission and never blocks; Receive() pops the next received frame if any. Per-frame use
// from the main loop; backends: mock (tests, simulated bus), SocketCAN, SLCAN, FDCAN (MCU).
#pragma once

#include <cstdint>

#include "volcomp/can_frame.hpp"
#include "volcomp/status.hpp"

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

 protected:
  ~CanPort() = default;  // not deletable through the interface (no heap in firmware)

 private:
  virtual Status DoSend(const CanFrame& frame) = 0;
  virtual bool DoReceive(CanFrame* frame) = 0;
};

}  // namespace volcomp::hal
