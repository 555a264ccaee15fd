// The control tick's "timer" on a LinuxCNC HAL thread (hal/tick_timer.hpp). The component's
// thread function calls BoardApp::Tick() once every `periods_per_tick` invocations of a thread
// with period `period_ns`, so the one tick rate this timer can run is
// 1e9 / (periods_per_tick x period_ns) Hz, and only when that is a whole number: SetRate() of any
// other rate (a configuration whose tick_hz is not what the thread runs) is refused with
// kConfigInvalid, which BoardApp::Start() reports (config_status(), FAULT) instead of running the
// data path at a rate it was not configured for.
//
// running() tells the thread function whether to tick (between Start() and Stop()). Main loop and
// tick share the base thread here, so no synchronisation is needed.
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/hal/tick_timer.hpp"

namespace volcomp::linuxcnc {

class ThreadTickTimer final : public hal::TickTimer {
 public:
  ThreadTickTimer(uint32_t period_ns, uint32_t periods_per_tick)
      : tick_ns_(uint64_t{period_ns} * periods_per_tick), periods_per_tick_(periods_per_tick) {}

  /// The tick rate the thread runs (Hz), or 0 when it is not a whole number of Hz.
  uint32_t thread_rate_hz() const {
    return tick_ns_ != 0 && kNsPerS % tick_ns_ == 0 ? static_cast<uint32_t>(kNsPerS / tick_ns_)
                                                    : 0u;
  }
  uint32_t periods_per_tick() const { return periods_per_tick_; }
  bool running() const { return running_; }

 private:
  static constexpr uint64_t kNsPerS = 1000000000u;

  Status DoSetRate(uint32_t tick_hz) override {
    if (running_) return Error::kBusy;
    if (uint64_t{tick_hz} * tick_ns_ != kNsPerS) return Error::kConfigInvalid;
    rate_hz_ = tick_hz;
    return Status::Ok();
  }
  Status DoStart() override {
    if (rate_hz_ == 0) return Error::kNotReady;
    running_ = true;
    return Status::Ok();
  }
  void DoStop() override { running_ = false; }
  uint32_t DoRateHz() const override { return rate_hz_; }

  uint64_t tick_ns_;
  uint32_t periods_per_tick_;
  uint32_t rate_hz_ = 0;
  bool running_ = false;
};

}  // namespace volcomp::linuxcnc
