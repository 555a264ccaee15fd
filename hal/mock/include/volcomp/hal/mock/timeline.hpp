// A recorded, time-stamped history of what the firmware did at its HAL boundary, for tests to
// check against an expected script (Pigweed-style mock timeline).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace volcomp::hal::mock {

enum class EventKind : uint8_t {
  kStepLineA,     // output line A of an axis (STEP, CW or quadrature A) changed; value = level
  kStepLineB,     // output line B of an axis (DIR, CCW or quadrature B) changed; value = level
  kOutputLine,    // a slow output line changed; channel = OutputLine, value = level
  kCanTx,         // a CAN frame was sent; channel = 0, value = id
  kFlashErase,    // value = offset
  kFlashProgram,  // value = offset
};

struct Event {
  uint64_t time_ns = 0;
  EventKind kind = EventKind::kStepLineA;
  uint8_t channel = 0;  // axis or line
  int64_t value = 0;
  bool operator==(const Event& o) const {
    return time_ns == o.time_ns && kind == o.kind && channel == o.channel && value == o.value;
  }
};

std::string ToString(const Event& e);

class Timeline {
 public:
  void Record(const Event& e) {
    if (enabled_) events_.push_back(e);
  }
  /// Recording can be switched off for long runs (counters elsewhere still work).
  void set_enabled(bool on) { enabled_ = on; }
  const std::vector<Event>& events() const { return events_; }
  void Clear() { events_.clear(); }
  /// Events of one kind (and channel, if >= 0), in order.
  std::vector<Event> Filter(EventKind kind, int channel = -1) const;

 private:
  bool enabled_ = true;
  std::vector<Event> events_;
};

}  // namespace volcomp::hal::mock
