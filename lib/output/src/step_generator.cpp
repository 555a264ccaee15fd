// Output pulse planning.
#include "volcomp/output/step_generator.hpp"

namespace volcomp {
namespace {

uint32_t NsToClock(uint32_t ns, uint32_t clock_hz) {
  return static_cast<uint32_t>((static_cast<uint64_t>(ns) * clock_hz + 999999999u) / 1000000000u);
}

// floor((2^32 - 1) / n) for n = 1..kMaxPulsesPerTick (entry 0 unused): n pulses spread over a
// window are MulHiU32(window, of[n]) apart. One table for every axis, built by the compiler. On the
// STM32G474 it is tick data in CCM SRAM (section .ccm_data, copied at start-up): zero wait states,
// where a read from flash could cost 4 wait states on an ART data-cache miss; 1 KB of the 32 KB.
struct PulseCountReciprocals {
  uint32_t of[StepGenerator::kMaxPulsesPerTick + 1];
  constexpr PulseCountReciprocals() : of() {
    for (uint32_t n = 1; n <= StepGenerator::kMaxPulsesPerTick; ++n) of[n] = 0xFFFFFFFFu / n;
  }
};
#if defined(__ARM_ARCH_7EM__) && !defined(__linux__)
__attribute__((section(".ccm_data.pulse_count_reciprocals")))
#endif
constexpr PulseCountReciprocals kReciprocals;

}  // namespace

Result<PulseTiming> PulseTiming::FromDrive(const AxisConfig& axis,
                                           uint32_t tick_hz,
                                           uint32_t pulse_clock_hz) {
  if (tick_hz == 0 || pulse_clock_hz < tick_hz || axis.drive.max_rate_hz == 0) {
    return Error::kConfigInvalid;
  }
  constexpr uint32_t kTimeLimit = 1u << 29;
  const bool edges_only = axis.output_format == PulseFormat::kQuadrature;
  PulseTiming t;
  t.tick = pulse_clock_hz / tick_hz;
  t.width = edges_only ? 0 : NsToClock(axis.drive.pulse_width_ns, pulse_clock_hz);
  const uint32_t space = edges_only ? 0 : NsToClock(axis.drive.step_space_ns, pulse_clock_hz);
  const uint64_t setup = static_cast<uint64_t>(axis.drive.dir_setup_ns) * pulse_clock_hz;
  const uint64_t hold = static_cast<uint64_t>(axis.drive.dir_hold_ns) * pulse_clock_hz;
  if (t.tick >= kTimeLimit || setup >= uint64_t{kTimeLimit} * 1000000000u ||
      hold >= uint64_t{kTimeLimit} * 1000000000u) {
    return Error::kConfigInvalid;
  }
  t.setup = NsToClock(axis.drive.dir_setup_ns, pulse_clock_hz);
  t.hold = NsToClock(axis.drive.dir_hold_ns, pulse_clock_hz);
  const uint32_t rate_period =
      static_cast<uint32_t>((static_cast<uint64_t>(pulse_clock_hz) + axis.drive.max_rate_hz - 1) /
                            axis.drive.max_rate_hz);
  t.min_period = t.width + space > rate_period ? t.width + space : rate_period;
  if (t.min_period == 0) t.min_period = 1;
  if (t.min_period > t.tick) return Error::kConfigInvalid;
  t.max_per_tick = t.tick / t.min_period;
  if (t.max_per_tick > StepGenerator::kMaxPulsesPerTick) {
    t.max_per_tick = StepGenerator::kMaxPulsesPerTick;
  }
  return t;
}

Status StepGenerator::Configure(const AxisConfig& axis, uint32_t tick_hz, uint32_t pulse_clock_hz) {
  const Result<PulseTiming> t = PulseTiming::FromDrive(axis, tick_hz, pulse_clock_hz);
  if (!t.ok()) return t.error();
  tick_ = t->tick;
  min_period_ = t->min_period;
  width_ = t->width;
  setup_ = t->setup;
  hold_ = t->hold;
  max_per_tick_ = t->max_per_tick;
  by_min_period_.Init(min_period_);
  reciprocals_ = kReciprocals.of;
  return Status::Ok();
}

}  // namespace volcomp
