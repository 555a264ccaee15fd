// The control tick of the board application when it runs as a Linux process: a hal::TickTimer on
// a timerfd (CLOCK_MONOTONIC, periodic, absolute period: no drift). The board application sets
// its rate and starts and stops it (at start and at every node reset); the event loop polls fd(),
// which becomes readable at each expiry, and Take() reads how many periods elapsed since the
// last Take() (more than one means the process was late: the caller runs the missed ticks or
// counts them). fd() stays the same from Open() to Close(), across rate changes.
//
// The period is 1e9 / tick_hz ns, truncated: exact for rates that divide 1e9 (1000, 2000, 4000,
// 5000, 8000, 10000, ..., 50000, 200000 Hz), otherwise less than 1 ns short per period.
// Stop() disarms the timer and discards expirations not yet taken.
//
// Thread-safety: one thread per object.
#pragma once

#include <cstdint>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/hal/tick_timer.hpp"

namespace volcomp::hal::linux_board {

class TickTimer final : public hal::TickTimer {
 public:
  TickTimer() = default;
  ~TickTimer() { Close(); }
  TickTimer(const TickTimer&) = delete;
  TickTimer& operator=(const TickTimer&) = delete;

  /// Creates the timerfd, stopped. kIoError with the system's reason when it cannot.
  Expected<void> Open();
  void Close();
  int fd() const { return fd_; }
  /// The programmed period (0 before SetRate()).
  uint64_t period_ns() const { return period_ns_; }
  bool running() const { return running_; }
  /// How many times it was started (a caller notices a restart: a node reset).
  uint64_t starts() const { return starts_; }

  /// Expirations since the last call (0 when none: the fd is non-blocking).
  uint64_t Take();

 private:
  // SetRate: kNotReady before Open(); kConfigInvalid for a period below 1 us (above 1 MHz).
  Status DoSetRate(uint32_t tick_hz) override;
  Status DoStart() override;
  void DoStop() override;
  uint32_t DoRateHz() const override { return rate_hz_; }

  int fd_ = -1;
  uint32_t rate_hz_ = 0;
  uint64_t period_ns_ = 0;
  bool running_ = false;
  uint64_t starts_ = 0;
};

}  // namespace volcomp::hal::linux_board
