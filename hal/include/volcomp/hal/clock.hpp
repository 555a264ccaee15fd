// Monotonic time for timeouts and diagnostics (not for step timing, which the tick owns).
#pragma once

#include <cstdint>

namespace volcomp::hal {

class Clock {
 public:
  /// Nanoseconds since an arbitrary start, monotonic, never wraps in practice.
  uint64_t NowNs() { return DoNowNs(); }

 protected:
  ~Clock() = default;  // not deletable through the interface (no heap in firmware)

 private:
  virtual uint64_t DoNowNs() = 0;
};

}  // namespace volcomp::hal
