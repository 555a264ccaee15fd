// A volcomp::hal::CanPort on a SimBus endpoint, so the firmware (which talks to a CanPort, like
// MockCan) can sit on the simulated bus. Send() queues on the endpoint (kFull beyond
// `tx_capacity` frames waiting, like a controller's transmit mailboxes/FIFO; kIoError while the
// endpoint is bus-off); Receive() pops the endpoint's receive queue. SetBitrate() sets the
// endpoint's controller to that rate and accepts every rate, as a CAN controller does: it cannot
// know the bus's rate. At another rate than the bus's the endpoint is off the bus (sim_bus.hpp).
// Thread-safety: the bus's thread only.
#pragma once

#include <cstddef>

#include "volcomp/hal/can.hpp"
#include "volcomp/sim/sim_bus.hpp"

namespace volcomp::sim {

class SimBusCanPort final : public hal::CanPort {
 public:
  explicit SimBusCanPort(Endpoint& endpoint, size_t tx_capacity = 64)
      : endpoint_(endpoint), tx_capacity_(tx_capacity) {}
  ~SimBusCanPort() = default;

  Endpoint& endpoint() { return endpoint_; }

 private:
  Status DoSend(const CanFrame& frame) override {
    if (endpoint_.tx_pending() >= tx_capacity_) return Error::kFull;
    return endpoint_.Send(frame) ? Status::Ok() : Status(Error::kIoError);
  }
  bool DoReceive(CanFrame* frame) override { return endpoint_.Receive(frame); }
  Status DoSetBitrate(uint32_t bitrate_bps) override {
    endpoint_.set_bitrate(bitrate_bps);
    return Status::Ok();
  }

  Endpoint& endpoint_;
  size_t tx_capacity_;
};

}  // namespace volcomp::sim
