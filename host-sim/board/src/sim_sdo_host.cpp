// SDO client operations against a simulated board, event by event.
#include "volcomp/sim/sim_sdo_host.hpp"

#include <algorithm>

#include "volcomp/canopen_client/node_objects.hpp"

namespace volcomp::sim {

void SimSdoHost::Run(canopen_client::SdoClient& client,
                     uint64_t timeout_ns,
                     const std::function<bool(uint64_t)>& pc_alive) {
  const uint64_t end = bus_.now() + timeout_ns;
  CanFrame f;
  while (!client.done() && bus_.now() < end) {
    const bool alive = !pc_alive || pc_alive(bus_.now());
    if (alive) {
      while (client.PopTx(&f)) pc_.Send(f);
    }
    const uint64_t t = std::clamp(NextEventTime(bus_, board_), bus_.now(), end);
    StepTo(bus_, board_, t);
    if (!alive) continue;
    while (pc_.Receive(&f)) client.OnFrame(f, t / 1000);
    client.Poll(t / 1000);
  }
  while (client.PopTx(&f)) pc_.Send(f);  // a final abort or acknowledgement
}

canopen_client::SdoExpected<std::vector<uint8_t>> SimSdoHost::Write(canopen::ObjectId id,
                                                                    uint32_t value,
                                                                    uint64_t timeout_ns) {
  canopen_client::SdoClient client(node_);
  canopen_client::StartNumericWrite(client, id, value);
  Run(client, timeout_ns);
  return client.result();
}

const canopen_client::FrameLink& SimSdoHost::Link() {
  if (!link_.send) {
    link_.send = [this](const CanFrame& f) {
      pc_.Send(f);
      return Outcome::Ok();
    };
    link_.receive = [this](uint64_t timeout_us) -> Expected<std::optional<CanFrame>> {
      const uint64_t end = bus_.now() + timeout_us * 1000;
      CanFrame f;
      while (!pc_.Receive(&f)) {
        if (bus_.now() >= end) return std::optional<CanFrame>();
        StepTo(bus_, board_, std::clamp(NextEventTime(bus_, board_), bus_.now(), end));
      }
      return std::optional<CanFrame>(f);
    };
    link_.now_us = [this] { return bus_.now() / 1000; };
  }
  return link_;
}

void SimSdoHost::Idle(uint64_t ns) {
  AdvanceInEventOrder(bus_, board_, bus_.now() + ns);
  CanFrame f;
  while (pc_.Receive(&f)) {
  }
}

}  // namespace volcomp::sim
