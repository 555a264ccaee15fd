// Pacing virtual bus time to the wall clock (the simulated node serving external clients).
//
//   RealtimeClock clock;                       // virtual 0 = now
//   VOLCOMP_TRY(RunRealtime(bus, clock, end_ns, [&](std::chrono::microseconds wait) {
//     return ServeSlcan(server, endpoint, wait);  // I/O while waiting for the next bus event
//   }));
//
// When the host falls behind, virtual time catches up at once (frames are never dropped, only
// delivered late in wall-clock terms). Thread-safety: none (one loop thread).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/sim/sim_bus.hpp"

namespace volcomp::sim {

class RealtimeClock {
 public:
  using Wall = std::chrono::steady_clock;
  /// Virtual time `virtual_start_ns` corresponds to the wall time now; `speed` scales it (2.0 =
  /// virtual time runs twice as fast as the wall clock). Precondition: speed > 0.
  explicit RealtimeClock(uint64_t virtual_start_ns = 0, double speed = 1.0);
  /// Virtual time of the wall-clock now.
  uint64_t Now() const;
  /// Wall-clock time at which virtual time reaches `virtual_ns`.
  Wall::time_point WallTime(uint64_t virtual_ns) const;
  /// How long until `virtual_ns` (0 when already past).
  std::chrono::microseconds Until(uint64_t virtual_ns) const;

 private:
  Wall::time_point wall_start_;
  uint64_t virtual_start_;
  double speed_;
};

/// Runs `bus` paced by `clock` until virtual time `until_ns`. Between events it calls
/// `wait(timeout)`, which must return within about `timeout` (it may return earlier, e.g. after
/// I/O, and may Send() frames on endpoints; they are queued at the current virtual time). Stops
/// at the first failure `wait` returns and returns it.
Outcome RunRealtime(SimBus& bus,
                    const RealtimeClock& clock,
                    uint64_t until_ns,
                    const std::function<Outcome(std::chrono::microseconds timeout)>& wait);

}  // namespace volcomp::sim
