// The native component's per-period compensation (see the header).
#include "native/native_compensator.hpp"

#include <cmath>
#include <cstdint>

namespace volcomp::linuxcnc {
namespace {

constexpr double kQ32 = 4294967296.0;

// Position in table steps, saturated to the int32 range of the lookups (they clamp to the table).
int32_t ToSteps(double pos, double steps_per_unit) {
  const double s = std::nearbyint(pos * steps_per_unit);
  if (!(s > -2147483648.0)) return INT32_MIN;  // also NaN
  if (s > 2147483647.0) return INT32_MAX;
  return static_cast<int32_t>(s);
}

// `value` in whole units of `unit` (the nearest, or the one at or below when `down`; a billionth
// of a step below a whole one counts as it), when it is a finite number from `min` to `max` steps.
bool WholeSteps(
    double value, double unit, double min, double max, uint32_t* out, bool down = false) {
  if (!std::isfinite(value)) return false;
  const double s = down ? std::floor(value / unit + 1e-9) : std::nearbyint(value / unit);
  if (!(s >= min) || s > max) return false;
  *out = static_cast<uint32_t>(s);
  return true;
}

}  // namespace

AxisLimits NativeCompensator::DefaultLimits(const NativeAxis& axis) {
  const AxisConfig d;
  const double u = axis.units_per_step;
  AxisLimits l;
  l.max_correction = d.max_correction_steps * u;
  l.max_vel = d.max_correction_rate_steps_s * u;
  l.max_accel = d.max_correction_accel_steps_s2 * u;
  l.direction_hysteresis = d.direction_hysteresis_steps * u;
  l.switch_vel = static_cast<double>(d.drive.max_rate_hz - d.max_input_rate_hz) * u;
  l.switch_accel = d.direction_switch_accel_steps_s2 * u;
  return l;
}

void NativeCompensator::UseTable(const NativeTable* table) {
  if (table_ == nullptr) {
    axis_count_ = table->axis_count();
    comp_.Reset(axis_count_);
    for (uint8_t a = 0; a < axis_count_; ++a) limits_[a] = DefaultLimits(table->axis(a));
  }
  table_ = table;
  table_bound_ = false;
}

Status NativeCompensator::Convert(uint8_t a, const AxisLimits& l, AxisConfig* axis) const {
  if (table_ == nullptr || a >= axis_count_ || tick_hz_ == 0) return Error::kNotReady;
  const NativeAxis& t = table_->axis(a);
  const double u = t.units_per_step;
  AxisConfig c;
  c.name = t.name;
  c.kind = t.kind;
  c.resolution_e9 = t.resolution_e9;
  uint32_t max = 0, hysteresis = 0;
  // No input stream: the whole switch velocity is the drive rate the switch may use.
  c.max_input_rate_hz = 0;
  // The maximum correction rounds down: never a larger correction than asked.
  if (!WholeSteps(l.max_correction, u, 0, table::kMaxCorrectionSteps, &max, true) ||
      !WholeSteps(l.max_vel, u, 1, 4294967295.0, &c.max_correction_rate_steps_s) ||
      !WholeSteps(l.max_accel, u, 1, 4294967295.0, &c.max_correction_accel_steps_s2) ||
      !WholeSteps(l.direction_hysteresis, u, 0, 65535, &hysteresis) ||
      !WholeSteps(l.switch_vel, u, 1, 4294967295.0, &c.drive.max_rate_hz) ||
      !WholeSteps(l.switch_accel, u, 1, 4294967295.0, &c.direction_switch_accel_steps_s2)) {
    return Error::kConfigInvalid;
  }
  c.max_correction_steps = static_cast<int32_t>(max);
  c.direction_hysteresis_steps = static_cast<uint16_t>(hysteresis);
  *axis = c;
  return Status::Ok();
}

Status NativeCompensator::SetPeriod(long period_ns) {
  if (period_ns <= 0) return Error::kInvalidArgument;
  const double hz = std::nearbyint(1e9 / static_cast<double>(period_ns));
  tick_hz_ = hz < 1 ? 1u : static_cast<uint32_t>(hz);
  period_s_ = static_cast<double>(period_ns) * 1e-9;
  Status result = Status::Ok();
  for (uint8_t a = 0; a < axis_count_; ++a) {
    const Status s = SetLimits(a, limits_[a]);
    if (!s.ok()) result = s;
  }
  return result;
}

Status NativeCompensator::SetLimits(uint8_t a, const AxisLimits& limits) {
  AxisConfig c;
  VOLCOMP_TRY(Convert(a, limits, &c));
  const Status s = comp_.SetAxisLimits(a, c, tick_hz_, 1);
  // kBusy: valid, taken once the axis's correction is at rest (Tick()).
  if (!s.ok() && s.error() != Error::kBusy) return s;
  limits_[a] = limits;
  config_[a] = c;
  has_pending_[a] = !s.ok();
  limits_valid_[a] = limits_valid_[a] || s.ok();
  return Status::Ok();
}

SwitchAccelBound NativeCompensator::SwitchAccel(uint8_t a, double* accel) const {
  const SwitchAccelInEffect e = DirectionSwitchAccelInEffect(config_[a], tick_hz_, 1);
  *accel = table_ != nullptr ? e.steps_s2 * table_->axis(a).units_per_step : 0;
  return e.bound;
}

double NativeCompensator::MaxAccel(uint8_t a) const {
  if (table_ == nullptr || tick_hz_ == 0) return 0;
  const double f = tick_hz_;
  return (f * f - 1) * table_->axis(a).units_per_step;
}

double NativeCompensator::MinVel(uint8_t a, double accel) const {
  if (table_ == nullptr || tick_hz_ == 0) return 0;
  const double ups = table_->axis(a).units_per_step;
  return std::ceil(accel / ups / tick_hz_) * ups;
}

void NativeCompensator::Tick(
    const double* pos, bool enable, bool referenced, double* correction, double* velocity) {
  const uint8_t n = axis_count_;
  if (table_ == nullptr || tick_hz_ == 0) {
    for (uint8_t a = 0; a < n; ++a) correction[a] = velocity[a] = 0;
    engaged_ = clamped_ = false;
    return;
  }
  int32_t steps[kMaxAxes] = {};
  bool all_limits = true;
  uint32_t clamped_before = 0;
  for (uint8_t a = 0; a < n; ++a) {
    steps[a] = ToSteps(pos[a], 1.0 / table_->axis(a).units_per_step);
    // The first period: the drive-direction sensing starts here, forward (no motion sensed).
    if (!have_last_) comp_.MoveAxis(a, steps[a]);
    if (has_pending_[a] && comp_.at_rest(a)) {
      has_pending_[a] = !comp_.SetAxisLimits(a, config_[a], tick_hz_, 1).ok();
      limits_valid_[a] = limits_valid_[a] || !has_pending_[a];
    }
    all_limits = all_limits && limits_valid_[a];
    clamped_before += comp_.clamped_refreshes(a);
  }
  have_last_ = true;
  if (!table_bound_) {
    comp_.BindTable(&table_->prepared());
    table_bound_ = true;
  }
  // Every period: the rotary wrap from the absolute position (as a homing jump needs), the
  // refresh cycle from its first phase (RunWhole() runs them all).
  comp_.RequestRebase();
  comp_.SetEnabled(enable);
  comp_.SetReferenced(referenced);
  comp_.SetFault(!all_limits);
  comp_.RunWhole(steps);
  engaged_ = comp_.engaged();
  uint32_t clamped_after = 0;
  for (uint8_t a = 0; a < n; ++a) {
    clamped_after += comp_.clamped_refreshes(a);
    const double c =
        static_cast<double>(comp_.applied_q32(a)) / kQ32 * table_->axis(a).units_per_step;
    velocity[a] = (c - last_correction_[a]) / period_s_;
    last_correction_[a] = c;
    correction[a] = c;
  }
  clamped_ = clamped_after != clamped_before;
}

}  // namespace volcomp::linuxcnc
