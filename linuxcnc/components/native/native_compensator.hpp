// The native component's per-period compensation (one instance): the firmware's Compensator
// (lib/control), run whole every servo period (Compensator::RunWhole(): the table lookup with
// direction rows and rotary wrap, the direction sensed on the drive's output with its hysteresis,
// the clamp to the maximum correction, the correction limiter and the direction switch limits),
// at the machine position of each table axis. Units: positions, corrections and limits in the
// table's units (mm for linear axes, degrees for rotary ones); the caller converts machine units
// (inch) to these. The correction is the limiter's exact value (Q32.32 steps), not whole steps.
//
// Servo thread only (Tick, UseTable, SetLimits, SetPeriod): no allocation, no blocking, no file
// access; a table is built outside the thread (NativeTable) and handed over by pointer.
#pragma once

#include <cstdint>

#include "native/native_table.hpp"
#include "volcomp/base/status.hpp"
#include "volcomp/config/board_config.hpp"
#include "volcomp/control/compensator.hpp"
#include "volcomp/table/table_format.hpp"

namespace volcomp::linuxcnc {

/// Limits of one axis, in the table's units (mm or degrees): the board's AxisConfig fields of the
/// same names (board_config.hpp), converted to whole table steps (the nearest; max_correction the
/// one at or below: MaxCorrectionInForce()).
struct AxisLimits {
  double max_correction = 0;        // largest |correction|
  double max_vel = 0;               // per second
  double max_accel = 0;             // per second^2
  double direction_hysteresis = 0;  // the output's move back that turns the AXIS1D direction
  // A switch between the AXIS1D forward and reverse rows: its velocity (the board's drive rate
  // beyond the input; here there is no input stream, the whole value is the switch's) and
  // acceleration (at least max_accel; in force as DirectionSwitchAccelInEffect() says).
  double switch_vel = 0;
  double switch_accel = 0;
};
class NativeCompensator {
 public:
  static constexpr uint8_t kMaxAxes = table::kMaxAxes;

  /// The board's default limits (AxisConfig{}: 1000 steps, 2000 steps/s, 200000 steps/s^2,
  /// hysteresis 1 step, switch at 10^6 steps/s and 10^8 steps/s^2) in the units of `axis`.
  static AxisLimits DefaultLimits(const NativeAxis& axis);

  /// Makes `table` the active table (kept by the caller until the next UseTable and while Tick
  /// runs). The first call sets the axes; later tables must have the same axes
  /// (NativeTable::CheckSameAxes). The correction moves to the new table within the limits.
  void UseTable(const NativeTable* table);
  const NativeTable* table() const { return table_; }

  /// The servo period (ns, > 0): converts the limits for it. kConfigInvalid when a limit does not
  /// fit this period (then that axis keeps its previous limits, none before the first success).
  Status SetPeriod(long period_ns);
  /// Limits of axis `a` (needs a table and a period). The maximum correction and the hysteresis
  /// apply from the next period in which the axis's correction is at rest, as the velocities and
  /// accelerations do (the limiter continues its motion under the limits it started it with).
  /// kConfigInvalid when they do not fit the limiter at this period or break a rule of the board
  /// (nothing changes): MaxAccel() and MinVel() give the bounds of the limiter.
  Status SetLimits(uint8_t a, const AxisLimits& limits);
  const AxisLimits& limits(uint8_t a) const { return limits_[a]; }
  /// The maximum correction of axis `a` in force (table units): whole table steps at or below
  /// limits(a).max_correction.
  double MaxCorrectionInForce(uint8_t a) const {
    return table_ != nullptr ? config_[a].max_correction_steps * table_->axis(a).units_per_step : 0;
  }
  /// The acceleration (table units/s^2) a direction switch of axis `a` runs with at this period,
  /// and what bounds it below limits(a).switch_accel (DirectionSwitchAccelInEffect()).
  SwitchAccelBound SwitchAccel(uint8_t a, double* accel) const;
  /// The largest acceleration (table units/s^2) axis `a`'s limiter takes at this period, and the
  /// smallest velocity for an acceleration `accel` (one acceleration step per period).
  double MaxAccel(uint8_t a) const;
  double MinVel(uint8_t a, double accel) const;

  /// One servo period. `pos`: machine position per table axis (table units). Writes the applied
  /// correction (table units) and its velocity (units/s) per table axis. The correction moves
  /// toward the table's value while `enable` and `referenced` (and a table and a period), toward
  /// zero otherwise.
  void Tick(const double* pos, bool enable, bool referenced, double* correction, double* velocity);

  bool engaged() const { return engaged_; }
  /// The table asked for more than the maximum correction on some axis in the last period.
  bool clamped() const { return clamped_; }
  uint8_t axis_count() const { return axis_count_; }

 private:
  Status Convert(uint8_t a, const AxisLimits& l, AxisConfig* axis) const;

  const NativeTable* table_ = nullptr;
  bool table_bound_ = false;  // table_ is the compensator's
  uint8_t axis_count_ = 0;
  uint32_t tick_hz_ = 0;
  double period_s_ = 0;
  bool engaged_ = false;
  bool clamped_ = false;
  bool have_last_ = false;
  Compensator comp_;
  AxisLimits limits_[kMaxAxes];
  AxisConfig config_[kMaxAxes];  // limits_ in steps, as the compensator has them (or will)
  bool limits_valid_[kMaxAxes] = {};
  bool has_pending_[kMaxAxes] = {};
  double last_correction_[kMaxAxes] = {};
};

}  // namespace volcomp::linuxcnc
