// SlcanServer: the device side of SLCAN, for the simulator: the simulated bus looks like an SLCAN
// adapter to clients (the PC tool's slcan:/slcan-tcp: transports, python-can, slcand via a pty),
// on a pty it creates with openpty() (the slave kept open so clients may come and go) or on a TCP
// socket (one client at a time; the next starts with the channel closed). Its answers to each
// command: docs/can-transports.md "SLCAN dialect".
//
// The owner drives it from its own loop: Poll(timeout) does the I/O, TakeReceived() returns the
// frames clients sent, Send() queues a frame to the client (dropped and counted while the channel
// is closed or when the client does not read: the backlog is bounded).
//
// Errors: the factories and Poll() return kIoError failures for the server's own resources (pty,
// socket, poll); client-side problems are no failure (a broken client is disconnected).
// Thread-safety: one thread drives a server.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "volcomp/can/can_frame.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::can_io {

struct SlcanServerOptions {
  std::string symlink;           // pty only: create this symlink to the slave (replaced if present)
  bool cr_tx_ack = false;        // answer t/T/r/R with "\r" (can-utils slcanpty) instead of z/Z
  std::string version = "0100";  // V reply (4 characters)
  std::string detail = "0100";   // v reply
  std::string serial = "VC01";   // N reply
  size_t max_backlog = 64 * 1024;  // bytes queued for a slow client before frames are dropped
};

struct SlcanServerStats {
  uint64_t frames_from_client = 0;
  uint64_t frames_to_client = 0;
  uint64_t frames_dropped = 0;   // Send() while closed or with the backlog full
  uint64_t errors_answered = 0;  // BELs sent (unknown, malformed, refused)
  uint64_t clients = 0;          // TCP connections accepted
};

class SlcanServer {
 public:
  /// A pty server; fails when openpty() fails or the symlink cannot be created.
  static Expected<std::unique_ptr<SlcanServer>> CreatePty(const SlcanServerOptions& options = {});
  /// A TCP server on address:port (port 0 = any free port; read it back with port()).
  static Expected<std::unique_ptr<SlcanServer>> CreateTcp(const std::string& address,
                                                          uint16_t port,
                                                          const SlcanServerOptions& options = {});
  ~SlcanServer();
  SlcanServer(const SlcanServer&) = delete;
  SlcanServer& operator=(const SlcanServer&) = delete;

  /// The pty slave path, or "ADDRESS:PORT".
  std::string endpoint() const;
  /// The spec a client passes to OpenTransport(): "slcan:/dev/pts/N" or "slcan-tcp:ADDR:PORT".
  std::string client_spec() const;
  uint16_t port() const;

  /// Waits up to `timeout` for I/O and handles everything pending. Returns true when frames
  /// arrived from the client (TakeReceived() has them); fails only when poll() itself does.
  Expected<bool> Poll(std::chrono::microseconds timeout);
  std::vector<CanFrame> TakeReceived();
  /// Queues a frame for the client.
  void Send(const CanFrame& frame);

  bool client_connected() const;
  bool channel_open() const;
  bool listen_only() const;
  /// Bitrate of the last S command in bit/s (0 before any).
  uint32_t bitrate() const;
  const SlcanServerStats& stats() const;

 private:
  struct Impl;
  explicit SlcanServer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace volcomp::can_io
