// hal::Clock on CLOCK_MONOTONIC (Linux board): nanoseconds since boot, unaffected by wall-clock
// changes. Thread-safe (clock_gettime has no shared state).
#pragma once

#include <cstdint>

#include "volcomp/hal/clock.hpp"

namespace volcomp::hal::linux_board {

/// CLOCK_MONOTONIC in nanoseconds (also for code that is not a hal::Clock user).
uint64_t MonotonicNowNs();

class MonotonicClock final : public Clock {
 public:
  MonotonicClock() = default;
  ~MonotonicClock() = default;

 private:
  uint64_t DoNowNs() override { return MonotonicNowNs(); }
};

}  // namespace volcomp::hal::linux_board
