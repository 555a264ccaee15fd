// The native component's per-period compensation (one instance): the firmware's table lookup
// (lib/: PreparedTable's GRID3 and AXIS1D lookups, direction rows and rotary wrap; the direction
// sensed on the drive's output with the board's default hysteresis of one step), the clamp to
// the maximum correction and the firmware's CorrectionLimiter, every servo period, at the machine
// position of each table axis. Units: positions and corrections in the table's units (mm for
// linear axes, degrees for rotary ones); the caller converts machine units (inch) to these.
//
// Servo thread only (Tick, UseTable, SetLimits, SetPeriod): no allocation, no blocking, no file
// access; a table is built outside the thread (NativeTable) and handed over by pointer.
#pragma once

#include <cstdint>

#include "native/native_table.hpp"
#include "volcomp/base/status.hpp"
#include "volcomp/limiter/correction_limiter.hpp"
#include "volcomp/table/table_format.hpp"

namespace volcomp::linuxcnc {

/// Limits of one axis's correction, in the table's units (mm or degrees).
struct AxisLimits {
  double max_correction = 0;  // largest |correction|
  double max_vel = 0;         // per second
  double max_accel = 0;       // per second^2
};

class NativeCompensator {
 public:
  static constexpr uint8_t kMaxAxes = table::kMaxAxes;

  /// The firmware's default limits in steps (BoardConfig): 1000 steps, 2000 steps/s,
  /// 200000 steps/s^2; `DefaultLimits` gives them in the units of `axis`.
  static AxisLimits DefaultLimits(const NativeAxis& axis);

  /// Makes `table` the active table (kept by the caller until the next UseTable and while Tick
  /// runs). The first call sets the axes; later tables must have the same axes
  /// (NativeTable::CheckSameAxes). The correction moves to the new table within the limits.
  void UseTable(const NativeTable* table);
  const NativeTable* table() const { return table_; }

  /// The servo period (ns, > 0): converts the limits for it. kConfigInvalid when a limit does not
  /// fit this period (then that axis keeps its previous limits, none before the first success).
  Status SetPeriod(long period_ns);
  /// Limits of axis `a` (needs a table and a period). The maximum correction applies at once;
  /// the velocity and acceleration from the next period in which the axis's correction is at
  /// rest (the limiter continues its motion under the limits it started it with).
  /// kConfigInvalid when they do not fit the limiter at this period (nothing changes): see
  /// LimitsFit().
  Status SetLimits(uint8_t a, const AxisLimits& limits);
  const AxisLimits& limits(uint8_t a) const { return limits_[a]; }
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
  Status Convert(uint8_t a, const AxisLimits& l, LimiterParams* params, int32_t* max_q8) const;

  const NativeTable* table_ = nullptr;
  uint8_t axis_count_ = 0;
  uint32_t tick_hz_ = 0;
  double period_s_ = 0;
  bool engaged_ = false;
  bool clamped_ = false;
  bool have_last_ = false;
  AxisLimits limits_[kMaxAxes];
  bool limits_valid_[kMaxAxes] = {};
  CorrectionLimiter limiter_[kMaxAxes];
  LimiterParams pending_[kMaxAxes];
  bool has_pending_[kMaxAxes] = {};
  int32_t max_q8_[kMaxAxes] = {};
  // AXIS1D direction sensing (as Compensator::SenseAxis): the last period's GRID3 part in whole
  // steps, the furthest output position in the current direction, the direction.
  int32_t grid_part_steps_[kMaxAxes] = {};
  int32_t extreme_[kMaxAxes] = {};
  bool reverse_[kMaxAxes] = {};
  double last_correction_[kMaxAxes] = {};
};

}  // namespace volcomp::linuxcnc
