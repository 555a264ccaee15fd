// Board configuration checks.
#include "volcomp/config/board_config.hpp"

namespace volcomp {
namespace {

bool ValidAxisName(char c) {
  for (const char* p = table::kAxisNames; *p != '\0'; ++p) {
    if (*p == c) return true;
  }
  return false;
}

ConfigRule AxisRule(const AxisConfig& a, uint32_t tick_hz) {
  if (!ValidAxisName(a.name)) return ConfigRule::kAxisName;
  if (a.resolution_e9 == 0) return ConfigRule::kResolution;
  if (a.kind != table::AxisKind::kLinear && a.kind != table::AxisKind::kRotary) {
    return ConfigRule::kAxisKind;
  }
  if (static_cast<uint8_t>(a.input_format) > 2 || static_cast<uint8_t>(a.output_format) > 2) {
    return ConfigRule::kPulseFormat;
  }
  if (a.input_counter_bits != 16 && a.input_counter_bits != 32) return ConfigRule::kCounterBits;
  if (a.max_correction_steps < 0 || a.max_correction_steps > table::kMaxCorrectionSteps) {
    return ConfigRule::kMaxCorrection;
  }
  if (a.max_input_rate_hz == 0 || a.drive.max_rate_hz == 0) return ConfigRule::kRateNotZero;
  // A 16-bit counter must not wrap by half its range within one tick.
  if (a.input_counter_bits == 16 && a.max_input_rate_hz / tick_hz >= 32768u) {
    return ConfigRule::kCounterWrap;
  }
  // The output must keep up with the fastest input plus the fastest correction.
  if (static_cast<uint64_t>(a.max_input_rate_hz) + a.max_correction_rate_steps_s >
      a.drive.max_rate_hz) {
    return ConfigRule::kDriveKeepsUp;
  }
  if (!AxisLimiterParams(a, tick_hz).ok()) return ConfigRule::kLimiter;
  // A switch is never slower than the correction: the limiter's velocity carries over from one
  // set of limits to the other (Compensator, "Direction switch").
  return a.direction_switch_accel_steps_s2 < a.max_correction_accel_steps_s2 ||
                 !AxisSwitchLimiterParams(a, tick_hz, CompensationDivider(tick_hz)).ok()
             ? ConfigRule::kDirectionSwitch
             : ConfigRule::kNone;
}

ConfigFinding FirstBrokenRule(const BoardConfig& config) {
  ConfigFinding f;
  if (config.tick_hz < kMinTickHz || config.tick_hz > kMaxTickHz) {
    f.rule = ConfigRule::kTickRate;
  } else if (config.pulse_clock_hz < config.tick_hz * 100u) {
    f.rule = ConfigRule::kPulseClock;
  } else if (config.axis_count < 1 || config.axis_count > table::kMaxAxes) {
    f.rule = ConfigRule::kAxisCount;
  }
  for (uint8_t i = 0; f.rule == ConfigRule::kNone && i < config.axis_count; ++i) {
    f.axis = static_cast<uint8_t>(i + 1);
    f.rule = AxisRule(config.axis[i], config.tick_hz);
    for (uint8_t j = 0; f.rule == ConfigRule::kNone && j < i; ++j) {
      if (config.axis[j].name == config.axis[i].name) f.rule = ConfigRule::kAxisName;
    }
  }
  if (f.rule == ConfigRule::kNone) f.axis = 0;
  return f;
}

}  // namespace

SwitchAccelInEffect DirectionSwitchAccelInEffect(const AxisConfig& axis,
                                                 uint32_t tick_hz,
                                                 uint32_t ticks_per_step) {
  SwitchAccelInEffect e{axis.direction_switch_accel_steps_s2, SwitchAccelBound::kNone};
  if (tick_hz == 0 || ticks_per_step == 0) return e;
  const uint64_t rate = axis.drive.max_rate_hz > axis.max_input_rate_hz
                            ? axis.drive.max_rate_hz - axis.max_input_rate_hz
                            : 0u;
  // The largest acceleration the period represents (accel * n^2 < f^2) and the one that reaches
  // the rate within one period (accel * n <= rate * f). Configuration time: divisions are fine.
  const uint64_t n = ticks_per_step;
  const uint64_t f = tick_hz;
  const uint64_t below_one_step = (f * f - 1u) / (n * n);
  const uint64_t within_one_period = rate * f / n;
  if (below_one_step < e.steps_s2 && below_one_step <= within_one_period) {
    e = {static_cast<uint32_t>(below_one_step), SwitchAccelBound::kPeriod};
  } else if (within_one_period < e.steps_s2) {
    e = {static_cast<uint32_t>(within_one_period), SwitchAccelBound::kRate};
  }
  return e;
}

Result<LimiterParams> AxisSwitchLimiterParams(const AxisConfig& axis,
                                              uint32_t tick_hz,
                                              uint32_t ticks_per_step) {
  if (tick_hz == 0 || ticks_per_step == 0 || axis.drive.max_rate_hz <= axis.max_input_rate_hz) {
    return Error::kConfigInvalid;
  }
  const uint64_t rate = axis.drive.max_rate_hz - axis.max_input_rate_hz;
  return CorrectionLimiter::MakeParams(
      tick_hz, static_cast<uint32_t>(rate < 0xFFFFFFFFu ? rate : 0xFFFFFFFFu),
      DirectionSwitchAccelInEffect(axis, tick_hz, ticks_per_step).steps_s2, ticks_per_step);
}

uint32_t PulseTimingRateHz(const AxisConfig& axis) {
  if (axis.output_format == PulseFormat::kQuadrature) return 0;
  const uint64_t period_ns = uint64_t{axis.drive.pulse_width_ns} + axis.drive.step_space_ns;
  return period_ns == 0 ? 0u : static_cast<uint32_t>(uint64_t{1000000000u} / period_ns);
}

Status ValidateStepOutputConfig(const BoardConfig& config, ConfigFinding* finding) {
  ConfigFinding f;
  VOLCOMP_TRY(ValidateBoardConfig(config, finding));
  for (uint8_t i = 0; i < config.axis_count; ++i) {
    const uint32_t rate = PulseTimingRateHz(config.axis[i]);
    if (rate != 0 && config.axis[i].drive.max_rate_hz > rate) {
      f = {ConfigRule::kPulseTiming, static_cast<uint8_t>(i + 1)};
      break;
    }
  }
  if (finding != nullptr) *finding = f;
  return f.rule == ConfigRule::kNone ? Status::Ok() : Status(Error::kConfigInvalid);
}

Status ValidateBoardConfig(const BoardConfig& config, ConfigFinding* finding) {
  const ConfigFinding f = FirstBrokenRule(config);
  if (finding != nullptr) *finding = f;
  if (f.rule != ConfigRule::kNone) return Error::kConfigInvalid;
  return Status::Ok();
}

Status CheckImageMatchesBoard(const table::TableView& image, const BoardConfig& config) {
  if (image.axis_count > config.axis_count) return Error::kConfigTooManyAxes;
  for (uint8_t i = 0; i < image.axis_count; ++i) {
    const table::AxisInfo& img = image.axes[i];
    const AxisConfig& cfg = config.axis[i];
    if (img.name != cfg.name || img.kind != cfg.kind) return Error::kConfigAxisMismatch;
    if (img.resolution_e9 != cfg.resolution_e9) return Error::kConfigResolutionMismatch;
  }
  return Status::Ok();
}

}  // namespace volcomp
