// A periodic monotonic tick on a timerfd (CLOCK_MONOTONIC, absolute period, no drift): the control
// tick of the board application when it runs as a Linux process. The fd becomes readable at each
// expiry; Take() reads how many periods elapsed since the last Take() (more than one means the
// process was late: the caller runs the missed ticks or counts them). Use fd() in poll/epoll.
//
// Thread-safety: one thread per object.
#pragma once

#include <cstdint>
#include <string>

namespace volcomp::hal::linux_board {

class TickTimer {
 public:
  TickTimer() = default;
  ~TickTimer() { Close(); }
  TickTimer(const TickTimer&) = delete;
  TickTimer& operator=(const TickTimer&) = delete;

  /// Starts a periodic timer of `period_ns` (>= 1000); returns "" or the reason it failed.
  std::string Start(uint64_t period_ns);
  void Close();
  int fd() const { return fd_; }
  uint64_t period_ns() const { return period_ns_; }

  /// Expirations since the last call (0 when none: the fd is non-blocking).
  uint64_t Take();

 private:
  int fd_ = -1;
  uint64_t period_ns_ = 0;
};

}  // namespace volcomp::hal::linux_board
