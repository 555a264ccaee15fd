// A PC on the simulated bus running SDO client operations against one simulated board, one event
// at a time in virtual time (the upload benchmark, the fault campaign). With Run() the caller keeps
// control between events: it can stall the PC or inject faults. Link() is the same PC as a blocking
// FrameLink, for the PC tool's own sequences (canopen_client/table_staging.hpp) between those.
#pragma once

#include <cstdint>
#include <functional>

#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/canopen_client/sdo_client.hpp"
#include "volcomp/canopen_client/sdo_runner.hpp"
#include "volcomp/sim/simulated_board.hpp"

namespace volcomp::sim {

class SimSdoHost {
 public:
  /// `pc` is the PC's endpoint on `bus`; `node` the board's node id.
  SimSdoHost(SimBus& bus, SimulatedBoard& board, Endpoint& pc, uint8_t node)
      : bus_(bus), board_(board), pc_(pc), node_(node) {}

  /// Drives `client` (an operation already started) until it is done or `timeout_ns` of virtual
  /// time have passed. While `pc_alive` (optional) returns false the PC neither sends, reads nor
  /// polls: received frames stay queued, as in a stalled host's OS.
  void Run(canopen_client::SdoClient& client,
           uint64_t timeout_ns,
           const std::function<bool(uint64_t now_ns)>& pc_alive = {});
  /// Writes a numeric object with its dictionary size; gives up after `timeout_ns`.
  canopen_client::SdoExpected<std::vector<uint8_t>> Write(canopen::ObjectId id,
                                                          uint32_t value,
                                                          uint64_t timeout_ns);
  /// Advances the board and the bus by `ns`, discarding what the PC receives.
  void Idle(uint64_t ns);
  /// The PC as a FrameLink: receive() advances the board and the bus event by event until a frame
  /// reaches the PC or its timeout has passed in virtual time. Valid while this host lives.
  const canopen_client::FrameLink& Link();
  uint8_t node() const { return node_; }

 private:
  SimBus& bus_;
  SimulatedBoard& board_;
  Endpoint& pc_;
  uint8_t node_;
  canopen_client::FrameLink link_;
};

}  // namespace volcomp::sim
