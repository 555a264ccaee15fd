// hal::CanPort on a Linux SocketCAN interface (the Linux board, or user-mode-linux on vcan0).
// Send() never blocks: a bounded software queue (kFull when full) flushed on every Send()/
// Receive()/Service(), paced on ENOBUFS; bus-off restarts requested over rtnetlink. SetBitrate()
// cannot set the interface's rate: it compares (kCanBitrateMismatch; Ok when there is nothing to
// compare, bitrate_check() says why). Threading: one thread (the main loop), like every CanPort.
// Pacing, error frames and bus-off: docs/can-transports.md, "SocketCAN".
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>

#include "volcomp/hal/can.hpp"
#include "volcomp/hal/linux/socketcan_socket.hpp"

namespace volcomp::hal::socketcan {

class SocketCanPort final : public CanPort {
 public:
  struct Options {
    SocketCanSocket::Options socket;
    size_t tx_capacity = 256;  // frames waiting in software
    std::chrono::microseconds enobufs_backoff{200};
    bool restart_on_bus_off = true;
    std::chrono::milliseconds restart_interval{1000};
  };
  struct Counters {
    uint64_t tx_frames = 0;     // written to the socket
    uint64_t rx_frames = 0;     // data/remote frames received
    uint64_t rx_dropped = 0;    // frames the kernel dropped: the socket's receive buffer was full
    uint64_t error_frames = 0;  // error frames received
    uint64_t enobufs = 0;       // writes deferred because the interface queue was full
    uint64_t tx_dropped = 0;    // frames dropped after a hard write error
    uint64_t bus_off = 0;       // bus-off events
    uint64_t restarts = 0;      // restart requests the kernel accepted
  };

  SocketCanPort() = default;
  ~SocketCanPort() = default;

  /// What the last SetBitrate() found.
  struct BitrateCheck {
    uint32_t configured_bps = 0;            // 0: SetBitrate() not called yet
    std::optional<uint32_t> interface_bps;  // the interface's rate, when the kernel reports one
    std::string note;                       // why nothing was compared (no interface rate)
  };

  /// Opens and binds the socket; a failure names the interface and the cause.
  Expected<void> Open(const std::string& iface, const Options& options);
  Expected<void> Open(const std::string& iface) { return Open(iface, Options()); }
  bool is_open() const { return socket_.is_open(); }
  /// Flushes queued frames and reads pending error frames (call from the main loop when idle).
  void Service();

  BusState bus_state() const { return state_; }
  const Counters& counters() const { return counters_; }
  size_t pending_tx() const { return tx_.size(); }
  /// The last problem seen (write error, restart failure, error frame, bit-rate mismatch).
  const std::optional<Failure>& last_failure() const { return last_failure_; }
  const BitrateCheck& bitrate_check() const { return bitrate_check_; }
  int fd() const { return socket_.fd(); }

 private:
  Status DoSend(const CanFrame& frame) override;
  bool DoReceive(CanFrame* frame) override;
  Status DoSetBitrate(uint32_t bitrate_bps) override;
  void Flush();
  void OnError(const CanErrorInfo& info);

  using Clock = std::chrono::steady_clock;
  Options options_;
  SocketCanSocket socket_;
  std::deque<CanFrame> tx_;
  std::deque<CanFrame> rx_;  // data frames read while looking for error frames in Service()
  Clock::time_point retry_at_{};
  Clock::time_point last_restart_{};
  BusState state_ = BusState::kErrorActive;
  Counters counters_;
  std::optional<Failure> last_failure_;
  BitrateCheck bitrate_check_;
};

}  // namespace volcomp::hal::socketcan
