// SocketCAN client transport (Linux): a CanTransport over hal::socketcan::SocketCanSocket.
//
// Send() paces on ENOBUFS (the interface queue is full; CAN netdevs default to txqueuelen 10):
// it backs off 100 µs .. 2 ms and retries until `send_timeout`, then fails with a hint to raise
// txqueuelen. Error frames become BusEvents; a bus-off triggers one restart request (rtnetlink,
// needs CAP_NET_ADMIN) and, until the controller reports a restart, Send() fails ("controller is
// bus-off"). The receive buffer is enlarged (SocketCanOptions) and the kernel's count of frames it
// dropped for the socket is kept (dropped_frames()). Failures are kCommunication (transport.hpp).
//
// Thread-safety: one thread at a time.
#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "volcomp/can_io/transport.hpp"
#include "volcomp/hal/linux/socketcan_socket.hpp"

namespace volcomp::can_io {

struct SocketCanOptions {
  /// The socket's receive buffer is 1 MiB unless set otherwise: about 1 s of a 1 Mbit/s bus at
  /// full load (the kernel's default, a few hundred frames, fills in ~0.1 s), so a PC tool that
  /// does not run for a moment loses nothing. Capped by the kernel unless the process may force
  /// it (CAP_NET_ADMIN).
  SocketCanOptions() { socket.receive_buffer_bytes = 1u << 20; }

  hal::socketcan::SocketCanSocket::Options socket;  // filters, error frames, receive own, buffer
  std::chrono::milliseconds send_timeout{2000};
  bool restart_on_bus_off = true;
};

class SocketCanTransport : public CanTransport {
 public:
  /// Opens and binds; a failure carries SocketCanErrorText's message (kInvalidArgument for a bad
  /// interface name, else kCommunication).
  static Expected<std::unique_ptr<SocketCanTransport>> Open(const std::string& iface,
                                                            const SocketCanOptions& options);

  Outcome Send(const CanFrame& frame) override;
  Expected<std::optional<CanFrame>> Receive(std::chrono::microseconds timeout) override;
  std::string description() const override { return "socketcan:" + socket_.iface(); }
  std::vector<BusEvent> TakeEvents() override;
  uint64_t dropped_frames() const override { return socket_.dropped_frames(); }

  hal::socketcan::BusState bus_state() const { return state_; }

 private:
  explicit SocketCanTransport(const SocketCanOptions& options) : options_(options) {}
  void OnError(const hal::socketcan::CanErrorInfo& info);
  // Reads without blocking; true when a data frame was stored in *frame.
  Expected<bool> ReadOne(CanFrame* frame);

  SocketCanOptions options_;
  hal::socketcan::SocketCanSocket socket_;
  hal::socketcan::BusState state_ = hal::socketcan::BusState::kErrorActive;
  std::vector<BusEvent> events_;
};

}  // namespace volcomp::can_io
