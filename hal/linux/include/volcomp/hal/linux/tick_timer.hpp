// hal::TickTimer on a timerfd (CLOCK_MONOTONIC, periodic, absolute: no drift) for the board
// application as a Linux process. The event loop polls fd() (the same from Open() to Close()) and
// Take() returns the periods elapsed since the last Take() (more than one: the process was late).
// Period 1e9 / tick_hz ns, truncated. Stop() discards expirations not yet taken. Threading: one
// thread per object. docs/linux-board.md, "Configuration in force".
#pragma once

#include <cstdint>

#include "volcomp/hal/tick_timer.hpp"
#include "volcomp/hosted/expected.hpp"

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
