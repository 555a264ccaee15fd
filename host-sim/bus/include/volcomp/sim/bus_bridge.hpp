// Connecting external CAN links to a SimBus endpoint: an SlcanServer (clients on a pty / TCP)
// or any can_io::CanTransport (e.g. socketcan:vcan0 inside user-mode-linux).
//
// Frames from the link are queued on the endpoint at the bus's current time; frames the endpoint
// received are forwarded to the link. Call these from the loop that drives the bus (after
// SlcanServer::Poll, or between RunUntil steps). Thread-safety: that loop's thread only.
#pragma once

#include <chrono>
#include <cstddef>

#include "volcomp/can_io/slcan_server.hpp"
#include "volcomp/can_io/transport.hpp"
#include "volcomp/sim/sim_bus.hpp"

namespace volcomp::sim {

/// Moves frames both ways; returns the number moved. The endpoint must use its receive queue
/// (no receive callback).
size_t PumpSlcan(can_io::SlcanServer& server, Endpoint& endpoint);
/// One step of a realtime loop serving SLCAN clients (use it as RunRealtime's wait): forwards
/// what the endpoint received (so it is written before waiting), Poll(timeout), then queues what
/// the client sent on the endpoint.
void ServeSlcan(can_io::SlcanServer& server, Endpoint& endpoint, std::chrono::microseconds timeout);
/// Same for a transport (non-blocking Receive(0) until empty). Transport errors propagate.
size_t PumpTransport(can_io::CanTransport& transport, Endpoint& endpoint);

}  // namespace volcomp::sim
