// Pumps between external CAN links and SimBus endpoints.
#include "volcomp/sim/bus_bridge.hpp"

namespace volcomp::sim {

size_t PumpSlcan(can_io::SlcanServer& server, Endpoint& endpoint) {
  size_t moved = 0;
  for (const CanFrame& f : server.TakeReceived()) {
    endpoint.Send(f);
    ++moved;
  }
  CanFrame f;
  while (endpoint.Receive(&f)) {
    server.Send(f);
    ++moved;
  }
  return moved;
}

Outcome ServeSlcan(can_io::SlcanServer& server,
                   Endpoint& endpoint,
                   std::chrono::microseconds timeout) {
  PumpSlcan(server, endpoint);
  VOLCOMP_TRY(server.Poll(timeout));
  PumpSlcan(server, endpoint);
  return Outcome::Ok();
}

void SlcanBridge::Pump() {
  // What the server received came from the client of its last Poll() (accepting a client and
  // reading from it never happen in the same Poll): it goes on the bus unless a session that
  // ended is still draining.
  for (const CanFrame& f : server_.TakeReceived()) {
    if (draining_) {
      held_.push_back(f);
    } else {
      endpoint_.Send(f);
    }
  }
  // A session ended (the client went away, or another one was accepted since the last look):
  // what the bus delivers from now on answers the departed client.
  const bool connected = server_.client_connected();
  const uint64_t clients = server_.stats().clients;
  if (connected_ && (!connected || clients != clients_)) {
    draining_ = true;
    last_traffic_ns_ = bus_.now();
  }
  connected_ = connected;
  clients_ = clients;
  CanFrame f;
  while (endpoint_.Receive(&f)) {
    if (draining_) {
      ++dropped_;
      last_traffic_ns_ = bus_.now();
    } else {
      server_.Send(f);
    }
  }
  if (draining_ && bus_.idle() && bus_.now() - last_traffic_ns_ >= quiet_ns_) {
    draining_ = false;
    for (const CanFrame& h : held_) endpoint_.Send(h);
    held_.clear();
  }
}

Outcome SlcanBridge::Serve(std::chrono::microseconds timeout) {
  Pump();
  VOLCOMP_TRY(server_.Poll(timeout));
  Pump();
  return Outcome::Ok();
}

Expected<size_t> PumpTransport(can_io::CanTransport& transport, Endpoint& endpoint) {
  size_t moved = 0;
  for (;;) {
    VOLCOMP_TRY_ASSIGN(const std::optional<CanFrame> f,
                       transport.Receive(std::chrono::microseconds(0)));
    if (!f) break;
    endpoint.Send(*f);
    ++moved;
  }
  CanFrame f;
  while (endpoint.Receive(&f)) {
    VOLCOMP_TRY(transport.Send(f));
    ++moved;
  }
  return moved;
}

}  // namespace volcomp::sim
