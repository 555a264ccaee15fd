// Pure computations behind the STM32G474 drivers (host-tested).
#include "volcomp/hal/stm32g4/config_math.hpp"

namespace volcomp::stm32g4 {

Result<PllConfig> ComputePll(uint32_t input_hz, uint32_t target_hz) {
  for (uint32_t m = 1; m <= 16; ++m) {
    const uint32_t ref = input_hz / m;
    if (ref * m != input_hz || ref < 2660000u || ref > 16000000u) continue;
    for (uint32_t r = 2; r <= 8; r += 2) {
      const uint64_t vco = static_cast<uint64_t>(target_hz) * r;
      if (vco % ref != 0) continue;
      const uint64_t n = vco / ref;
      if (n < 8 || n > 127 || vco < 96000000u || vco > 344000000u) continue;
      PllConfig c;
      c.m = m;
      c.n = static_cast<uint32_t>(n);
      c.r = r;
      c.q = r;
      c.sysclk_hz = target_hz;
      return c;
    }
  }
  return Error::kConfigInvalid;
}

uint32_t FlashWaitStates(uint32_t hclk_hz, bool boost_mode) {
  const uint32_t per_ws = boost_mode ? 34000000u : 30000000u;
  return hclk_hz == 0 ? 0 : (hclk_hz - 1u) / per_ws;
}

Result<CanBitTiming> ComputeCanBitTiming(uint32_t kernel_hz,
                                         uint32_t bitrate,
                                         uint32_t sample_permille) {
  if (bitrate == 0) return Error::kConfigInvalid;
  bool found = false;
  CanBitTiming best;
  uint32_t best_err = ~0u;
  for (uint32_t tq = 25; tq >= 8; --tq) {  // more quanta first: finer sample point
    const uint64_t clocks = static_cast<uint64_t>(bitrate) * tq;
    if (kernel_hz % clocks != 0) continue;
    const uint32_t prescaler = static_cast<uint32_t>(kernel_hz / clocks);
    if (prescaler < 1 || prescaler > 512) continue;
    // Sample point = (1 + tseg1) / tq; tseg2 >= 1.
    uint32_t tseg1 = (sample_permille * tq + 500u) / 1000u;
    tseg1 = tseg1 < 2 ? 1 : tseg1 - 1u;
    if (tseg1 > tq - 2u) tseg1 = tq - 2u;
    const uint32_t tseg2 = tq - 1u - tseg1;
    const uint32_t sp = (1000u * (1u + tseg1)) / tq;
    const uint32_t err = sp > sample_permille ? sp - sample_permille : sample_permille - sp;
    if (err < best_err) {
      best = {prescaler, tseg1, tseg2, tseg2 < 4 ? tseg2 : 4u};
      best_err = err;
      found = true;
    }
  }
  if (!found) return Error::kConfigInvalid;
  return best;
}

Result<TickTimerSettings> ComputeTickTimer(uint32_t timer_clock_hz, uint32_t tick_hz) {
  if (tick_hz == 0 || timer_clock_hz % tick_hz != 0) return Error::kConfigInvalid;
  const uint32_t clocks = timer_clock_hz / tick_hz;
  // The smallest divider that brings the period within 16 bits and divides it exactly.
  for (uint32_t div = (clocks + 0xFFFFu) / 0x10000u; div <= 0x10000u; ++div) {
    if (clocks % div != 0) continue;
    if (clocks / div < 2) break;  // ARR = 0 stops the counter
    TickTimerSettings t;
    t.psc = div - 1u;
    t.arr = clocks / div - 1u;
    return t;
  }
  return Error::kConfigInvalid;
}

BoardConfig ReferenceBoardConfig() {
  BoardConfig c = DefaultBoardConfig();
  c.pulse_clock_hz = kSysclkHz;
  for (uint8_t a = 0; a < kStepAxes; ++a) c.axis[a].input_counter_bits = kInputCounterBits[a];
  return c;
}

Result<StepIoSetup> PlanStepIo(const BoardConfig& config, uint32_t timer_clock_hz) {
  if (config.axis_count > kStepAxes || config.pulse_clock_hz != timer_clock_hz ||
      config.tick_hz == 0 || timer_clock_hz % config.tick_hz != 0) {
    return Error::kConfigInvalid;
  }
  StepIoSetup s;
  s.axes = config.axis_count;
  s.tick_clocks = timer_clock_hz / config.tick_hz;
  for (uint8_t a = 0; a < s.axes; ++a) {
    const AxisConfig& ax = config.axis[a];
    if (ax.input_counter_bits != kInputCounterBits[a]) return Error::kConfigInvalid;
    if (ax.output_format == PulseFormat::kQuadrature) return Error::kConfigInvalid;
    const Result<PulseTiming> t = PulseTiming::FromDrive(ax, config.tick_hz, timer_clock_hz);
    if (!t.ok()) return t.status();
    // The longest first period of a plan: a rise just before the tick ends plus the pulse width.
    if (uint64_t{t->tick} + t->width > (uint64_t{1} << kOutputTimerBits)) {
      return Error::kConfigInvalid;
    }
    // PWM mode 2 needs a high time and a low time of at least one clock each: then every plan of
    // the generator fits the timer (PlanToTimerFitted(), StepIo::Apply checks nothing per tick).
    if (t->width == 0 || t->min_period <= t->width) return Error::kConfigInvalid;
    s.input_format[a] = ax.input_format;
    s.invert_input_dir[a] = ax.invert_input_dir;
    s.cw_ccw_output[a] = ax.output_format == PulseFormat::kCwCcw;
  }
  return s;
}

Result<PulseTimerSettings> PlanToTimer(const PulsePlan& plan,
                                       uint32_t tick,
                                       uint32_t counter_bits) {
  PulseTimerSettings s;
  if (!PlanToTimerInto(plan, tick, counter_bits, &s)) return Error::kConfigInvalid;
  return s;
}

}  // namespace volcomp::stm32g4
