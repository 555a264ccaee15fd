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

void ServeSlcan(can_io::SlcanServer& server,
                Endpoint& endpoint,
                std::chrono::microseconds timeout) {
  PumpSlcan(server, endpoint);
  server.Poll(timeout);
  PumpSlcan(server, endpoint);
}

size_t PumpTransport(can_io::CanTransport& transport, Endpoint& endpoint) {
  size_t moved = 0;
  while (auto f = transport.Receive(std::chrono::microseconds(0))) {
    endpoint.Send(*f);
    ++moved;
  }
  CanFrame f;
  while (endpoint.Receive(&f)) {
    transport.Send(f);
    ++moved;
  }
  return moved;
}

}  // namespace volcomp::sim
