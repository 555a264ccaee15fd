// Connecting external CAN links to a SimBus endpoint: an SlcanServer (clients on a pty / TCP)
// or any can_io::CanTransport (e.g. socketcan:vcan0 inside user-mode-linux).
//
// Frames from the link are queued on the endpoint at the bus's current time; frames the endpoint
// received are forwarded to the link. Call these from the loop that drives the bus (after
// SlcanServer::Poll, or between RunUntil steps). A failure of the link (the server's poll, the
// transport's send or receive) is returned with the link's message. Thread-safety: that loop's
// thread only.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "volcomp/can_io/slcan_server.hpp"
#include "volcomp/can_io/transport.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/sim/sim_bus.hpp"

namespace volcomp::sim {

/// Moves frames both ways; returns the number moved. The endpoint must use its receive queue
/// (no receive callback).
size_t PumpSlcan(can_io::SlcanServer& server, Endpoint& endpoint);
/// One step of a realtime loop serving SLCAN clients (use it as RunRealtime's wait): forwards
/// what the endpoint received (so it is written before waiting), Poll(timeout), then queues what
/// the client sent on the endpoint. Fails when the server's Poll() does.
Outcome ServeSlcan(can_io::SlcanServer& server,
                   Endpoint& endpoint,
                   std::chrono::microseconds timeout);
/// ServeSlcan() session by session, for a TCP server whose clients come and go: when a client
/// disconnects, what the bus still delivers of its conversation (the node's answers queued for it,
/// e.g. the rest of a block-upload sub-block) is dropped instead of reaching the next client, and
/// the next client's frames are held back, until the bus has been quiet (no frame delivered to
/// the endpoint, nothing in flight or queued) for `quiet_ns` of bus time; then the held frames
/// go on the bus in order. Use Serve() as RunRealtime's wait.
class SlcanBridge {
 public:
  SlcanBridge(SimBus& bus,
              can_io::SlcanServer& server,
              Endpoint& endpoint,
              uint64_t quiet_ns = 1000000)
      : bus_(bus), server_(server), endpoint_(endpoint), quiet_ns_(quiet_ns) {}

  /// Fails when the server's Poll() does.
  Outcome Serve(std::chrono::microseconds timeout);
  /// Frames dropped because their client had disconnected.
  uint64_t dropped() const { return dropped_; }

 private:
  void Pump();

  SimBus& bus_;
  can_io::SlcanServer& server_;
  Endpoint& endpoint_;
  uint64_t quiet_ns_;
  bool connected_ = false;
  uint64_t clients_ = 0;
  bool draining_ = false;
  uint64_t last_traffic_ns_ = 0;
  std::vector<CanFrame> held_;
  uint64_t dropped_ = 0;
};

/// Same for a transport (non-blocking Receive(0) until empty); the transport's failure, if any.
Expected<size_t> PumpTransport(can_io::CanTransport& transport, Endpoint& endpoint);

}  // namespace volcomp::sim
