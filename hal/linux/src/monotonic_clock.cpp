// CLOCK_MONOTONIC clock.
#include "volcomp/hal/linux/monotonic_clock.hpp"

#include <time.h>

namespace volcomp::hal::linux_board {

uint64_t MonotonicNowNs() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<uint64_t>(ts.tv_sec) * 1000000000u + static_cast<uint64_t>(ts.tv_nsec);
}

}  // namespace volcomp::hal::linux_board
