// The compensator: correction = GRID3(x, y, z) + sum_i AXIS1D_i(q_i, direction_i) in Q24.8 steps,
// clamped to the board's maximum, then approached within rate/acceleration limits; Run() returns
// whole steps. Target = the table only while enabled, referenced, fault-free and with a table
// (else zero: the correction ramps in and out within the limits); zero correction = pass-through.
// A switch between an axis's AXIS1D forward and reverse tables moves at the axis's direction switch
// limits until the correction has caught up (docs/control-path.md, "Direction switch").
// One Run() is one compensation run (every CompensationDivider(tick_hz) control ticks on a board);
// the table evaluation is spread over refresh_runs() runs (docs/mcu-target.md, "Target refresh
// spread over runs"). Run() and its parts: no division, no allocation, O(axes). Threading: the
// control context only (tick ISR or the compensation interrupt); SetTable()/ClearTable() at rest.
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/config/board_config.hpp"
#include "volcomp/limiter/correction_limiter.hpp"
#include "volcomp/lookup/axis_lookup.hpp"
#include "volcomp/lookup/grid_lookup.hpp"
#include "volcomp/table/table_image.hpp"
#include "volcomp/thermal/thermal_term.hpp"

namespace volcomp {

/// A table prepared for the hot path (reciprocals computed, lookups bound to the image bytes).
struct PreparedTable {
  bool has_grid = false;
  GridLookup grid;
  uint8_t axis_table_count = 0;
  AxisLookup axis_table[table::kMaxAxes];
  int8_t axis_table_of[table::kMaxAxes] = {-1, -1, -1, -1, -1, -1};  // per board axis, or -1
  // Resolved per board axis when prepared, so activating the table in a run copies nothing:
  int8_t grid_component_of[table::kMaxAxes] = {-1, -1, -1, -1, -1, -1};  // grid component or -1
  uint8_t wrap_mask = 0;  // bit a: axis a's AXIS1D table wraps (rotary)
  uint32_t table_id = 0;
  uint32_t crc32 = 0;

  /// Prepares `image` for `config` (checks it matches the board). Leaves *this unchanged on error.
  /// A THERMAL section is not part of the prepared table: the owner's main loop applies it
  /// (firmware BoardThermal, PublishThermal()); a consumer without temperature channels refuses
  /// such an image itself (kThermalNotApplied).
  Status Prepare(const table::TableView& image, const BoardConfig& config);

  /// The table's correction per axis (Q24.8 steps, before clamp and limiter): GRID3 at
  /// `pos_steps` plus each AXIS1D at `axis_pos_steps` (the same positions, except wrap axes
  /// reduced into their period) in the direction given by `reverse`.
  void TargetsQ8(const int32_t* pos_steps,
                 const int32_t* axis_pos_steps,
                 const bool* reverse,
                 uint8_t axis_count,
                 int32_t* target_q8) const;
};

class Compensator {
 public:
  Compensator() = default;
  // Not copyable: the active table may be this object's own copy (a copy would point into it).
  Compensator(const Compensator&) = delete;
  Compensator& operator=(const Compensator&) = delete;

  /// Sets axis count and limits from a validated board configuration; resets all state. The
  /// limits are converted for one Run() every `ticks_per_run` ticks of config.tick_hz: a board
  /// runs it every CompensationDivider(tick_hz) ticks (the one-argument form), a caller that
  /// steps it every tick passes 1. kConfigInvalid when the limits do not fit that rate.
  Status Configure(const BoardConfig& config, uint32_t ticks_per_run);
  Status Configure(const BoardConfig& config) {
    return Configure(config, CompensationDivider(config.tick_hz));
  }
  /// Configure() in parts, for a caller without a whole board configuration (the native LinuxCNC
  /// component: its axes come from the table, its limits from HAL parameters, its rate from the
  /// servo thread). Reset(): `axis_count` axes (1..kMaxAxes), no table, every axis forward at
  /// zero correction and at rest, with placeholder limits until SetAxisLimits() (call it for each
  /// axis before Run()).
  void Reset(uint8_t axis_count);
  /// Axis `a`'s limits from `axis` as Configure() takes them (max_correction_steps, the
  /// correction's rate and acceleration, direction_hysteresis_steps, the direction switch limits),
  /// for one Run() every `ticks_per_run` ticks of `tick_hz`; the axis's state (direction, table,
  /// correction) carries on. kBusy while its correction moves (nothing changes: set them when
  /// at_rest(a), so its velocity never jumps); kConfigInvalid where ValidateBoardConfig() would
  /// refuse them (rules kMaxCorrection, kLimiter, kDirectionSwitch).
  Status SetAxisLimits(uint8_t a, const AxisConfig& axis, uint32_t tick_hz, uint32_t ticks_per_run);

  /// Makes `table` the active table (copied; the image bytes it points to must stay valid until
  /// the next SetTable/ClearTable). The applied correction moves to the new target within limits.
  void SetTable(const PreparedTable& table, const int32_t* machine_pos_steps);
  /// SetTable() without the copy: `*table` is used in place and must stay valid and unchanged
  /// until the next SetTable/UseTable/ClearTable (a board hands tables over in its own slots).
  void UseTable(const PreparedTable* table, const int32_t* machine_pos_steps) {
    BindTable(table);
    Rebase(machine_pos_steps);
  }
  /// UseTable() without its Rebase(), for a run that rebases once after several changes (table
  /// and referencing): Rebase() must follow before the next Run(). Constant time (no axis loop).
  void BindTable(const PreparedTable* table) {
    table_ = table;
    grid_ = table->has_grid ? &table->grid : nullptr;
    wrap_mask_ = table->wrap_mask;
    has_table_ = true;
    UpdateEngaged();
  }
  /// Drops the active table at once; the applied correction ramps out to zero.
  void ClearTable();
  /// A new table or new coordinates (re-referencing): restarts the refresh cycle and the rotary
  /// wrap tracking at `machine_pos_steps`. The drive-direction state carries on; an axis whose
  /// coordinates jumped must have been announced with MoveAxis() (which shifts it with them).
  void Rebase(const int32_t* machine_pos_steps);
  /// Rebase() in place of the next RefreshTargets() (the run's bounded cost: a table switch or
  /// referencing takes that run's refresh slice, and the refresh cycle restarts one run later),
  /// at the positions that run senses. An axis whose coordinates jump before then needs
  /// MoveAxis(), so that the run senses its motion, not the jump.
  void RequestRebase() { rebase_pending_ = true; }
  /// Axis `a`'s machine coordinates jump to `machine_pos_steps` (referencing): the next
  /// SenseAxis() measures motion from there, and the drive-direction state moves with them.
  void MoveAxis(uint8_t a, int32_t machine_pos_steps) {
    const uint32_t jump =
        static_cast<uint32_t>(machine_pos_steps) - static_cast<uint32_t>(last_pos_[a]);
    last_pos_[a] = machine_pos_steps;
    extreme_[a] = static_cast<int32_t>(static_cast<uint32_t>(extreme_[a]) + jump);
  }

  void SetEnabled(bool on) {
    enabled_ = on;
    UpdateEngaged();
  }
  void SetReferenced(bool on) {
    referenced_ = on;
    UpdateEngaged();
  }
  void SetFault(bool on) {
    fault_ = on;
    UpdateEngaged();
  }
  /// SetEnabled() and SetFault() at once (the board takes both every run: one update).
  void SetEnabledAndFault(bool enabled, bool fault) {
    enabled_ = enabled;
    fault_ = fault;
    UpdateEngaged();
  }

  /// The thermal terms of axes 0..count-1 (the others zero), added to each axis's table target
  /// before the clamp from the next refresh of the axis on (thermal/thermal_term.hpp; engaged
  /// only: the thermal term needs the table's coordinates). Written into the slot the run does not
  /// read, then that slot made current with one store: call it from a context the run preempts
  /// (the MCU's main loop) or never runs beside (not from a second core while Run() runs: a
  /// second publish within one run would rewrite the slot it reads). Zero after Reset().
  void PublishThermal(const thermal::ThermalTermSteps* terms, uint8_t count);
  /// The thermal terms of axis `a` the run applies.
  const thermal::ThermalTermSteps& thermal_term(uint8_t a) const {
    return thermal_[thermal_slot_][a];
  }

  /// One compensation run. `machine_pos_steps`: commanded position per axis in machine
  /// coordinates. Writes the whole-step correction to add to each axis's output position.
  void Run(const int32_t* machine_pos_steps, int32_t* correction_steps) {
    for (uint8_t a = 0; a < axis_count_; ++a) SenseAxis(a, machine_pos_steps[a]);
    RefreshTargets(machine_pos_steps);
    for (uint8_t a = 0; a < axis_count_; ++a) correction_steps[a] = LimitAxis(a);
  }

  /// Run() with the whole target refresh in the one run (every phase of RefreshTargets(), and a
  /// requested Rebase() first), for a caller whose run is long enough (the native LinuxCNC
  /// component, once per servo period); the correction stays in Q32.32 (applied_q32()).
  void RunWhole(const int32_t* machine_pos_steps) {
    for (uint8_t a = 0; a < axis_count_; ++a) SenseAxis(a, machine_pos_steps[a]);
    if (rebase_pending_) Rebase(machine_pos_steps);
    for (uint32_t k = 0; k < refresh_runs(); ++k) RefreshTargets(machine_pos_steps);
    for (uint8_t a = 0; a < axis_count_; ++a) (void)LimitAxis(a);
  }

  /// Run() in its three steps, for ControlTick::Compensate() (which walks its axes once before and
  /// once after the refresh): SenseAxis() for every axis, then RefreshTargets(), then LimitAxis()
  /// for every axis, in this order, once per run.
  /// Direction and rotary wrap tracking of axis `a` at its new position.
  void SenseAxis(uint8_t a, int32_t machine_pos_steps) {
    const uint32_t pos = static_cast<uint32_t>(machine_pos_steps);
    const int32_t delta = static_cast<int32_t>(pos - static_cast<uint32_t>(last_pos_[a]));
    last_pos_[a] = machine_pos_steps;
    if ((wrap_mask_ >> a) & 1u) wrap_[a].Update(delta);
    // The drive's direction: command + the last refresh's GRID3 part against the furthest point
    // reached in the current direction; moving back by more than the hysteresis turns it. The
    // AXIS1D part is left out: it follows the axis's own command with a slope far below one step
    // per step, so it never turns the drive, and its direction tables' difference must not turn
    // it back (docs/control-path.md). Selects, not branches.
    const uint32_t out = pos + static_cast<uint32_t>(grid_part_steps_[a]);
    const uint32_t dir = direction_[a];  // 0 forward, all ones reverse
    // Distance ahead of the extreme in the current direction (negated by the mask when reverse).
    const int32_t ahead =
        static_cast<int32_t>(((out - static_cast<uint32_t>(extreme_[a])) ^ dir) - dir);
    const uint32_t turn = static_cast<uint32_t>(ahead + hysteresis_[a]) >> 31;  // 1: turned
    extreme_[a] = ((ahead > 0) | (turn != 0)) ? static_cast<int32_t>(out) : extreme_[a];
    direction_[a] = dir ^ (0u - turn);
  }
  /// One phase of the table evaluation (or zero targets when not engaged), or the Rebase() that
  /// RequestRebase() asked for.
  void RefreshTargets(const int32_t* machine_pos_steps);
  /// One limiter step of axis `a` toward its target; returns the whole-step correction (round
  /// half up).
  int32_t LimitAxis(uint8_t a) {
    const int64_t p = limiter_[a].Step(static_cast<int64_t>(target_q8_[a]) * (int64_t{1} << 24));
    return static_cast<int32_t>((p + (int64_t{1} << 31)) >> 32);
  }

  bool has_table() const { return has_table_; }
  /// True when the target is the table (enabled, referenced, no fault, table active).
  bool engaged() const { return engaged_; }
  /// True when every axis has zero applied correction and is at rest (pure pass-through).
  bool passthrough() const;
  uint32_t table_id() const { return table_->table_id; }
  uint32_t table_crc32() const { return table_->crc32; }
  /// Target (the last refresh, clamped) and applied correction of an axis, Q24.8 steps.
  int32_t target_q8(int axis) const { return target_q8_[axis]; }
  int32_t applied_q8(int axis) const {
    return static_cast<int32_t>(limiter_[axis].position_q32() >> 24);
  }
  /// The applied correction of an axis unrounded, Q32.32 steps.
  int64_t applied_q32(int axis) const { return limiter_[axis].position_q32(); }
  /// True while the axis's correction does not move (its limiter at rest).
  bool at_rest(int axis) const { return limiter_[axis].at_rest(); }
  /// Target refreshes of axis `axis` (one per refresh_runs() while engaged) in which the table
  /// asked for more than the maximum correction (the target was clamped); wraps at 2^32.
  uint32_t clamped_refreshes(int axis) const { return clamped_refreshes_[axis]; }
  /// Target refreshes of axis `axis` at which its correction moved at the rate limit (it lags its
  /// target: a ramp, or a table steeper than the rate allows at the current speed); wraps at
  /// 2^32. Sampled at the refresh rather than counted every run (a cheaper run).
  uint32_t rate_limited_refreshes(int axis) const { return rate_limited_refreshes_[axis]; }
  /// True while the axis's drive moves in the negative direction (command plus the table's GRID3
  /// correction went back by more than its direction hysteresis): the AXIS1D reverse table
  /// applies.
  bool reverse(int axis) const { return direction_[axis] != 0; }
  /// True while the axis's correction takes up a switch between its AXIS1D forward and reverse
  /// tables at the direction switch limits (AxisSwitchLimiterParams()): from the refresh that
  /// first looks its table up in the new direction, if the correction had caught up with its
  /// target then (within one step: not in a ramp), to a refresh of the axis at which it is at
  /// rest again.
  bool switching(int axis) const { return (switch_state_[axis] & 1u) != 0; }
  uint8_t axis_count() const { return axis_count_; }

  /// Runs per target refresh: the grid's three parts, then one per axis.
  static constexpr uint8_t kGridPhases = 3;
  uint32_t refresh_runs() const { return kGridPhases + axis_count_; }

 private:
  // Bitwise, not short-circuit: no branches in the run (each Set...() may run every run).
  void UpdateEngaged() { engaged_ = (has_table_ & enabled_ & referenced_ & !fault_) != 0; }
  // While disengaged: a switch in progress comes to rest at the switch limits where it is, then
  // the correction ramps out at the correction's limits; the direction a refresh compares with
  // follows the drive (engaging is not a switch).
  void DisengageAxis(uint32_t a);

  uint8_t axis_count_ = 0;
  bool engaged_ = false;  // has_table_ && enabled_ && referenced_ && !fault_ (one load per run)
  bool enabled_ = false;
  bool referenced_ = false;
  bool fault_ = false;
  bool has_table_ = false;
  uint8_t phase_ = 0;            // next refresh phase, 0..refresh_runs()-1
  bool rebase_pending_ = false;  // RequestRebase(): the next RefreshTargets() rebases instead
  int32_t target_q8_[table::kMaxAxes] = {};
  // PublishThermal(): two slots, the run reads thermal_[thermal_slot_] (volatile: one load per
  // refresh, ordered after the slot's writes by the publisher's signal fence).
  thermal::ThermalTermSteps thermal_[2][table::kMaxAxes] = {};
  volatile uint8_t thermal_slot_ = 0;
  int32_t grid_q8_[3] = {};  // the grid part of the refresh
  int32_t max_q8_[table::kMaxAxes] = {};
  uint32_t clamped_refreshes_[table::kMaxAxes] = {};
  uint32_t rate_limited_refreshes_[table::kMaxAxes] = {};
  CorrectionLimiter limiter_[table::kMaxAxes];
  LimiterParams limits_[table::kMaxAxes][2] = {};  // [a][0] the correction's, [a][1] a switch's
  // The correction's acceleration step over the switch's, Q30 (<= 1): re-expresses the limiter's
  // velocity when it enters the switch limits.
  int32_t switch_k_scale_q30_[table::kMaxAxes] = {};
  // Bit 0: the axis at its switch limits; bit 1: the AXIS1D direction of its last refresh
  // (reverse). One word: one load and one store in the refresh.
  uint32_t switch_state_[table::kMaxAxes] = {};
  WrapTracker wrap_[table::kMaxAxes];
  uint8_t wrap_mask_ = 0;  // the active table's wrap_mask, 0 without a table
  int32_t last_pos_[table::kMaxAxes] = {};
  // The last refresh's GRID3 part of the axis's target in whole steps (its direction sensing).
  int32_t grid_part_steps_[table::kMaxAxes] = {};
  int32_t extreme_[table::kMaxAxes] = {};  // furthest such position in the current direction
  int32_t hysteresis_[table::kMaxAxes] = {};
  uint32_t direction_[table::kMaxAxes] = {};  // 0: forward, all ones: reverse (the AXIS1D table)
  GridLookup::Partial grid_partial_;
  PreparedTable own_;                   // SetTable()'s copy
  const PreparedTable* table_ = &own_;  // the active table (own_ or the caller's)
  const GridLookup* grid_ = nullptr;    // the active table's grid, null without one
};

}  // namespace volcomp
