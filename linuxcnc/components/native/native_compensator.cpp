// The native component's per-period compensation (see the header).
#include "native/native_compensator.hpp"

#include <cmath>
#include <cstdint>

#include "volcomp/config/board_config.hpp"

namespace volcomp::linuxcnc {
namespace {

constexpr double kQ32 = 4294967296.0;
// The board's default AXIS1D direction hysteresis (BoardConfig), in table steps.
constexpr int32_t kDirectionHysteresisSteps = AxisConfig{}.direction_hysteresis_steps;

// Position in table steps, saturated to the int32 range of the lookups (they clamp to the table).
int32_t ToSteps(double pos, double steps_per_unit) {
  const double s = std::nearbyint(pos * steps_per_unit);
  if (!(s > -2147483648.0)) return INT32_MIN;  // also NaN
  if (s > 2147483647.0) return INT32_MAX;
  return static_cast<int32_t>(s);
}

// `value` in whole units of `unit`, when it is a finite positive number that fits a uint32.
bool WholeSteps(double value, double unit, uint32_t* out) {
  if (!(value > 0) || !std::isfinite(value)) return false;
  const double s = std::nearbyint(value / unit);
  if (!(s >= 1) || s > 4294967295.0) return false;
  *out = static_cast<uint32_t>(s);
  return true;
}

}  // namespace

AxisLimits NativeCompensator::DefaultLimits(const NativeAxis& axis) {
  AxisLimits l;
  l.max_correction = 1000 * axis.units_per_step;
  l.max_vel = 2000 * axis.units_per_step;
  l.max_accel = 200000 * axis.units_per_step;
  return l;
}

void NativeCompensator::UseTable(const NativeTable* table) {
  if (table_ == nullptr) {
    axis_count_ = table->axis_count();
    for (uint8_t a = 0; a < axis_count_; ++a) limits_[a] = DefaultLimits(table->axis(a));
  }
  table_ = table;
}

Status NativeCompensator::Convert(uint8_t a,
                                  const AxisLimits& l,
                                  LimiterParams* params,
                                  int32_t* max_q8) const {
  if (table_ == nullptr || a >= axis_count_ || tick_hz_ == 0) return Error::kNotReady;
  const double ups = table_->axis(a).units_per_step;
  if (!(l.max_correction >= 0) || !std::isfinite(l.max_correction)) return Error::kConfigInvalid;
  const double q8 = std::nearbyint(l.max_correction / ups * (1 << table::kCorrectionFracBits));
  *max_q8 = q8 >= table::kMaxCorrectionQ8 ? table::kMaxCorrectionQ8 : static_cast<int32_t>(q8);
  uint32_t rate = 0, accel = 0;
  if (!WholeSteps(l.max_vel, ups, &rate) || !WholeSteps(l.max_accel, ups, &accel)) {
    return Error::kConfigInvalid;
  }
  const Result<LimiterParams> p = CorrectionLimiter::MakeParams(tick_hz_, rate, accel, 1);
  if (!p.ok()) return p.status();
  *params = *p;
  return Status::Ok();
}

Status NativeCompensator::SetPeriod(long period_ns) {
  if (period_ns <= 0) return Error::kInvalidArgument;
  const double hz = std::nearbyint(1e9 / static_cast<double>(period_ns));
  tick_hz_ = hz < 1 ? 1u : static_cast<uint32_t>(hz);
  period_s_ = static_cast<double>(period_ns) * 1e-9;
  Status result = Status::Ok();
  for (uint8_t a = 0; a < axis_count_; ++a) {
    LimiterParams p;
    int32_t max_q8 = 0;
    const Status s = Convert(a, limits_[a], &p, &max_q8);
    if (!s.ok()) {
      result = s;
      continue;
    }
    max_q8_[a] = max_q8;
    if (!limits_valid_[a]) {
      limiter_[a].set_params(p);  // at rest: nothing applied yet
      limits_valid_[a] = true;
    } else {
      pending_[a] = p;
      has_pending_[a] = true;
    }
  }
  return result;
}

Status NativeCompensator::SetLimits(uint8_t a, const AxisLimits& limits) {
  LimiterParams p;
  int32_t max_q8 = 0;
  VOLCOMP_TRY(Convert(a, limits, &p, &max_q8));
  limits_[a] = limits;
  max_q8_[a] = max_q8;
  if (!limits_valid_[a]) {
    limiter_[a].set_params(p);
    limits_valid_[a] = true;
  } else {
    pending_[a] = p;
    has_pending_[a] = true;
  }
  return Status::Ok();
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
  int32_t steps[kMaxAxes] = {}, axis_steps[kMaxAxes] = {};
  bool all_limits = true;
  for (uint8_t a = 0; a < n; ++a) {
    const NativeAxis& ax = table_->axis(a);
    const int32_t s = ToSteps(pos[a], 1.0 / ax.units_per_step);
    // Direction for the AXIS1D direction tables, as on the board (Compensator::SenseAxis): the
    // drive's output, the position plus the last period's GRID3 part, against the furthest point
    // reached in the current direction; moving back by more than the hysteresis turns it.
    const int32_t out =
        static_cast<int32_t>(static_cast<uint32_t>(s) + static_cast<uint32_t>(grid_part_steps_[a]));
    if (!have_last_) {
      extreme_[a] = out;
    } else {
      const int32_t ahead = static_cast<int32_t>(
          reverse_[a] ? static_cast<uint32_t>(extreme_[a]) - static_cast<uint32_t>(out)
                      : static_cast<uint32_t>(out) - static_cast<uint32_t>(extreme_[a]));
      if (ahead > 0) {
        extreme_[a] = out;
      } else if (ahead < -kDirectionHysteresisSteps) {
        reverse_[a] = !reverse_[a];
        extreme_[a] = out;
      }
    }
    steps[a] = s;
    if (ax.wrap_period_steps != 0) {
      const int64_t period = ax.wrap_period_steps;
      int64_t r = (int64_t{s} - ax.wrap_origin_steps) % period;
      if (r < 0) r += period;
      axis_steps[a] = static_cast<int32_t>(ax.wrap_origin_steps + r);
    } else {
      axis_steps[a] = s;
    }
    all_limits = all_limits && limits_valid_[a];
  }
  have_last_ = true;
  // PreparedTable::TargetsQ8 in two parts: the GRID3 part alone (in whole steps) is the next
  // period's direction sensing (zero while not engaged, as on the board), then the AXIS1D tables.
  const PreparedTable& prepared = table_->prepared();
  int32_t wanted_q8[kMaxAxes] = {};
  if (prepared.has_grid) {
    int32_t g[3];
    prepared.grid.Lookup(steps, g);
    for (int c = 0; c < 3; ++c) wanted_q8[prepared.grid.axis(c)] += g[c];
  }
  engaged_ = enable && referenced && all_limits;
  for (uint8_t a = 0; a < n; ++a) {
    grid_part_steps_[a] = engaged_ ? (wanted_q8[a] + 128) >> 8 : 0;
    const int8_t i = prepared.axis_table_of[a];
    if (i >= 0) wanted_q8[a] += prepared.axis_table[i].Lookup(axis_steps[a], reverse_[a]);
  }
  clamped_ = false;
  for (uint8_t a = 0; a < n; ++a) {
    int32_t target = 0;
    if (engaged_) {
      const int32_t max = max_q8_[a];
      target = wanted_q8[a] > max ? max : (wanted_q8[a] < -max ? -max : wanted_q8[a]);
      clamped_ = clamped_ || target != wanted_q8[a];
    }
    if (has_pending_[a] && limiter_[a].at_rest()) {
      limiter_[a].set_params(pending_[a]);
      has_pending_[a] = false;
    }
    const int64_t q32 = limits_valid_[a] ? limiter_[a].Step(int64_t{target} * (int64_t{1} << 24))
                                         : limiter_[a].position_q32();
    const double c = static_cast<double>(q32) / kQ32 * table_->axis(a).units_per_step;
    velocity[a] = (c - last_correction_[a]) / period_s_;
    last_correction_[a] = c;
    correction[a] = c;
  }
}

}  // namespace volcomp::linuxcnc
