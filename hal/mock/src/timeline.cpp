// Timeline helpers.
#include "volcomp/hal/mock/timeline.hpp"

namespace volcomp::hal::mock {

std::string ToString(const Event& e) {
  static const char* const kNames[] = {"lineA", "lineB", "out", "can_tx", "erase", "program"};
  return std::to_string(e.time_ns) + "ns " + kNames[static_cast<int>(e.kind)] + "[" +
         std::to_string(e.channel) + "]=" + std::to_string(e.value);
}

std::vector<Event> Timeline::Filter(EventKind kind, int channel) const {
  std::vector<Event> out;
  for (const Event& e : events_) {
    if (e.kind == kind && (channel < 0 || e.channel == channel)) out.push_back(e);
  }
  return out;
}

}  // namespace volcomp::hal::mock
