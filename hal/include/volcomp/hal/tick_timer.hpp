// The timer that runs the control tick (it calls BoardApp::Tick() once per period). The board
// application owns its rate: it stops the timer before it reconfigures the data path, programs
// the rate of the configuration in force and starts it again, so the tick never runs at a period
// other than the one ControlTick was configured with. NVI interface, main loop only (never from
// the tick itself). Backends: STM32 TIM6, a Linux timerfd, the mock (tests and the simulator,
// whose board ticks at the rate programmed here).
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"

namespace volcomp::hal {

class TickTimer {
 public:
  /// Programs the period for `tick_hz` ticks per second. kInvalidArgument for 0; kBusy while
  /// running (Stop() first); kConfigInvalid when this timer cannot run at exactly that rate
  /// (nothing changes then: the previous rate stays programmed).
  Status SetRate(uint32_t tick_hz) {
    if (tick_hz == 0) return Error::kInvalidArgument;
    return DoSetRate(tick_hz);
  }
  /// Starts ticking at the programmed rate; kNotReady when no rate was programmed.
  Status Start() { return DoStart(); }
  /// Stops ticking: once it returns, no new tick begins until Start(). Idempotent.
  void Stop() { DoStop(); }
  /// The programmed rate in Hz (0 before the first successful SetRate()).
  uint32_t rate_hz() const { return DoRateHz(); }

 protected:
  ~TickTimer() = default;  // not deletable through the interface (no heap in firmware)

 private:
  virtual Status DoSetRate(uint32_t tick_hz) = 0;
  virtual Status DoStart() = 0;
  virtual void DoStop() = 0;
  virtual uint32_t DoRateHz() const = 0;
};

}  // namespace volcomp::hal
