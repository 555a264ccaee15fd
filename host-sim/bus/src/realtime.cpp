// RealtimeClock and the paced run loop.
#include "volcomp/sim/realtime.hpp"

#include <algorithm>

#include "volcomp/sim/contract.hpp"

namespace volcomp::sim {

RealtimeClock::RealtimeClock(uint64_t virtual_start_ns, double speed)
    : wall_start_(Wall::now()), virtual_start_(virtual_start_ns), speed_(speed) {
  VOLCOMP_SIM_EXPECT(speed > 0, "RealtimeClock: speed must be > 0");
}

uint64_t RealtimeClock::Now() const {
  const auto elapsed =
      std::chrono::duration_cast<std::chrono::nanoseconds>(Wall::now() - wall_start_).count();
  return virtual_start_ + static_cast<uint64_t>(static_cast<double>(elapsed) * speed_);
}

RealtimeClock::Wall::time_point RealtimeClock::WallTime(uint64_t virtual_ns) const {
  const double delta = virtual_ns >= virtual_start_
                           ? static_cast<double>(virtual_ns - virtual_start_) / speed_
                           : -static_cast<double>(virtual_start_ - virtual_ns) / speed_;
  return wall_start_ + std::chrono::nanoseconds(static_cast<int64_t>(delta));
}

std::chrono::microseconds RealtimeClock::Until(uint64_t virtual_ns) const {
  const auto left =
      std::chrono::duration_cast<std::chrono::microseconds>(WallTime(virtual_ns) - Wall::now());
  return std::max(left, std::chrono::microseconds(0));
}

Outcome RunRealtime(SimBus& bus,
                    const RealtimeClock& clock,
                    uint64_t until_ns,
                    const std::function<Outcome(std::chrono::microseconds timeout)>& wait) {
  for (;;) {
    const uint64_t now = std::min(clock.Now(), until_ns);
    bus.RunUntil(now);
    if (now >= until_ns) return Outcome::Ok();
    const auto next = bus.NextEventTime();
    const uint64_t target = next ? std::min(*next, until_ns) : until_ns;
    VOLCOMP_TRY(wait(clock.Until(target)));
  }
}

}  // namespace volcomp::sim
