// The compensator: correction = GRID3(x, y, z) + sum_i AXIS1D_i(q_i, direction_i), clamped to the
// board's maximum, then moved toward by a rate/acceleration limiter per axis. Both limits are
// counted per axis at each target refresh (clamped_refreshes(), rate_limited_refreshes()) so doing
// less than the table asks is visible (the board's diagnostics 0x2134-0x2136).
//
// The target is the table lookup only while the compensator is enabled, referenced, fault-free and
// has an active table; otherwise the target is zero, so enabling ramps the correction in, and
// disabling, losing the reference or a fault ramps it out (always within the limits). When the
// applied correction is zero the output equals the input exactly (pass-through).
//
// A "tick" of the compensator is one Tick() call: one compensation run, which the board makes
// every CompensationDivider(tick_hz) control ticks (board_config.hpp; its limiters are converted
// for that rate: 3 ticks = 60 us at the default 50 kHz, every tick at 20 kHz and below).
//
// Target refresh (the cycle budget, docs/mcu-target.md): while engaged, the tables are evaluated
// in refresh_ticks() = 3 + axis_count parts, one per run: (0) locate the grid cell at the current
// positions and form the y-level weights; (1) the grid's lower z level; (2) its upper z level;
// (3 + a) axis a: its grid component plus its AXIS1D table at its current position and direction,
// clamped, becomes the axis's new target. So with 3 axes each target is refreshed every 6 runs
// (360 us at 50 kHz), from a grid position at most 5 runs old, and a new target (engaging,
// SetTable(), Rebase()) is in effect after at most 6 runs (7 after RequestRebase(), whose rebase
// takes one run's refresh slice). Each refresh equals PreparedTable::TargetsQ8() (clamped) at
// those positions: compensator_test checks it against an independent evaluation. The correction
// changes by at most the rate limit per run (of the order of 10^4 steps/s: below one step per run
// at 20 kHz), so the refresh interval only adds a few runs of motion to the position a target
// belongs to (at 1 m/min and a table gradient of 10 um per 100 mm, 360 us of motion is 6 um of
// travel and 0.6 nm of correction). The limiter and the whole-step correction run every run.
//
// Tick() is the per-tick hot path: no division, no allocation, constant time per axis.
// Threading: call everything from the control context (the tick ISR or the code it defers to);
// SetTable() and ClearTable() are meant for moments when the axes stand still.
#pragma once

#include <cstdint>

#include "volcomp/lookup/axis_lookup.hpp"
#include "volcomp/config/board_config.hpp"
#include "volcomp/limiter/correction_limiter.hpp"
#include "volcomp/lookup/grid_lookup.hpp"
#include "volcomp/base/status.hpp"
#include "volcomp/table/table_image.hpp"

namespace volcomp {

/// A table prepared for the hot path (reciprocals computed, lookups bound to the image bytes).
struct PreparedTable {
  bool has_grid = false;
  GridLookup grid;
  uint8_t axis_table_count = 0;
  AxisLookup axis_table[table::kMaxAxes];
  int8_t axis_table_of[table::kMaxAxes] = {-1, -1, -1, -1, -1, -1};  // per board axis, or -1
  // Resolved per board axis when prepared, so activating the table in the tick copies nothing:
  int8_t grid_component_of[table::kMaxAxes] = {-1, -1, -1, -1, -1, -1};  // grid component or -1
  uint8_t wrap_mask = 0;  // bit a: axis a's AXIS1D table wraps (rotary)
  uint32_t table_id = 0;
  uint32_t crc32 = 0;

  /// Prepares `image` for `config` (checks it matches the board). Leaves *this unchanged on error.
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
  /// limits are converted for one Tick() every `ticks_per_run` ticks of config.tick_hz: a board
  /// runs it every CompensationDivider(tick_hz) ticks (the one-argument form), a caller that
  /// steps it every tick passes 1. kConfigInvalid when the limits do not fit that rate.
  Status Configure(const BoardConfig& config, uint32_t ticks_per_run);
  Status Configure(const BoardConfig& config) {
    return Configure(config, CompensationDivider(config.tick_hz));
  }

  /// Makes `table` the active table (copied; the image bytes it points to must stay valid until
  /// the next SetTable/ClearTable). The applied correction moves to the new target within limits.
  void SetTable(const PreparedTable& table, const int32_t* machine_pos_steps);
  /// SetTable() without the copy: `*table` is used in place and must stay valid and unchanged
  /// until the next SetTable/UseTable/ClearTable (a board hands tables over in its own slots).
  void UseTable(const PreparedTable* table, const int32_t* machine_pos_steps) {
    BindTable(table);
    Rebase(machine_pos_steps);
  }
  /// UseTable() without its Rebase(), for a tick that rebases once after several changes (table
  /// and referencing): Rebase() must follow before the next Tick(). Constant time (no axis loop).
  void BindTable(const PreparedTable* table) {
    table_ = table;
    grid_ = table->has_grid ? &table->grid : nullptr;
    wrap_mask_ = table->wrap_mask;
    has_table_ = true;
    UpdateEngaged();
  }
  /// Drops the active table at once; the applied correction ramps out to zero.
  void ClearTable();
  /// Machine coordinates jumped (re-referencing): restart direction and wrap tracking from
  /// `machine_pos_steps` without treating the jump as motion.
  void Rebase(const int32_t* machine_pos_steps);
  /// Rebase() in place of the next RefreshTargets() (the tick's bounded cost: a table switch or
  /// referencing takes that tick's refresh slice, and the refresh cycle restarts one tick later),
  /// at the positions that tick senses. An axis whose coordinates jump before then needs
  /// MoveAxis(), so that the tick senses its motion, not the jump.
  void RequestRebase() { rebase_pending_ = true; }
  /// Axis `a`'s machine coordinates jump to `machine_pos_steps` (referencing): the next
  /// SenseAxis() measures motion from there.
  void MoveAxis(uint8_t a, int32_t machine_pos_steps) { last_pos_[a] = machine_pos_steps; }

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
  /// SetEnabled() and SetFault() at once (the tick takes both every tick: one update).
  void SetEnabledAndFault(bool enabled, bool fault) {
    enabled_ = enabled;
    fault_ = fault;
    UpdateEngaged();
  }

  /// One compensation run (a control tick where the board runs it every tick). `machine_pos_steps`:
  /// commanded position per axis in machine coordinates. Writes the whole-step correction to add to
  /// each axis's output position.
  void Tick(const int32_t* machine_pos_steps, int32_t* correction_steps) {
    for (uint8_t a = 0; a < axis_count_; ++a) SenseAxis(a, machine_pos_steps[a]);
    RefreshTargets(machine_pos_steps);
    for (uint8_t a = 0; a < axis_count_; ++a) correction_steps[a] = ApplyAxis(a);
  }

  /// Tick() in its three steps, for ControlTick::Run() (which walks its axes once before and once
  /// after the refresh): SenseAxis() for every axis, then RefreshTargets(), then ApplyAxis() for
  /// every axis, in this order, once per tick.
  /// Direction and rotary wrap tracking of axis `a` at its new position.
  void SenseAxis(uint8_t a, int32_t machine_pos_steps) {
    const int32_t delta = static_cast<int32_t>(static_cast<uint32_t>(machine_pos_steps) -
                                               static_cast<uint32_t>(last_pos_[a]));
    last_pos_[a] = machine_pos_steps;
    if (delta != 0) reverse_[a] = delta < 0;
    if ((wrap_mask_ >> a) & 1u) wrap_[a].Update(delta);
  }
  /// One phase of the table evaluation (or zero targets when not engaged), or the Rebase() that
  /// RequestRebase() asked for.
  void RefreshTargets(const int32_t* machine_pos_steps);
  /// Limiter step toward the axis's target; returns the whole-step correction (round half up).
  int32_t ApplyAxis(uint8_t a) {
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
  /// Target refreshes of axis `axis` (one per refresh_ticks() while engaged) in which the table
  /// asked for more than the maximum correction (the target was clamped); wraps at 2^32.
  uint32_t clamped_refreshes(int axis) const { return clamped_refreshes_[axis]; }
  /// Target refreshes of axis `axis` at which its correction moved at the rate limit (it lags its
  /// target: a ramp, or a table steeper than the rate allows at the current speed); wraps at
  /// 2^32. Sampled at the refresh rather than counted every tick: the tick stays as it was.
  uint32_t rate_limited_refreshes(int axis) const { return rate_limited_refreshes_[axis]; }
  /// True while the axis last moved in the negative direction.
  bool reverse(int axis) const { return reverse_[axis]; }
  uint8_t axis_count() const { return axis_count_; }

  /// Ticks per target refresh: the grid's three parts, then one per axis (see the top of this
  /// file).
  static constexpr uint8_t kGridPhases = 3;
  uint32_t refresh_ticks() const { return kGridPhases + axis_count_; }

 private:
  // Bitwise, not short-circuit: no branches in the tick (each Set...() runs every tick).
  void UpdateEngaged() { engaged_ = (has_table_ & enabled_ & referenced_ & !fault_) != 0; }

  uint8_t axis_count_ = 0;
  bool engaged_ = false;  // has_table_ && enabled_ && referenced_ && !fault_ (one load per tick)
  bool enabled_ = false;
  bool referenced_ = false;
  bool fault_ = false;
  bool has_table_ = false;
  uint8_t phase_ = 0;            // next refresh phase, 0..refresh_ticks()-1
  bool rebase_pending_ = false;  // RequestRebase(): the next RefreshTargets() rebases instead
  int32_t target_q8_[table::kMaxAxes] = {};
  int32_t grid_q8_[3] = {};  // the grid part of the refresh
  int32_t max_q8_[table::kMaxAxes] = {};
  uint32_t clamped_refreshes_[table::kMaxAxes] = {};
  uint32_t rate_limited_refreshes_[table::kMaxAxes] = {};
  CorrectionLimiter limiter_[table::kMaxAxes];
  WrapTracker wrap_[table::kMaxAxes];
  uint8_t wrap_mask_ = 0;  // the active table's wrap_mask, 0 without a table
  int32_t last_pos_[table::kMaxAxes] = {};
  bool reverse_[table::kMaxAxes] = {};
  GridLookup::Partial grid_partial_;
  PreparedTable own_;                   // SetTable()'s copy
  const PreparedTable* table_ = &own_;  // the active table (own_ or the caller's)
  const GridLookup* grid_ = nullptr;    // the active table's grid, null without one
};

}  // namespace volcomp
