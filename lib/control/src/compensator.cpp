// Compensator: table lookup -> clamp -> rate/acceleration limiter -> whole steps.
#include "volcomp/control/compensator.hpp"

#include <atomic>

#include "volcomp/base/interp_arith.hpp"

namespace volcomp {

Status PreparedTable::Prepare(const table::TableView& image, const BoardConfig& config) {
  VOLCOMP_TRY(CheckImageMatchesBoard(image, config));
  PreparedTable t;
  if (image.grid.present) {
    VOLCOMP_TRY(t.grid.Init(image.grid));
    t.has_grid = true;
  }
  for (uint8_t i = 0; i < image.axis1d_count; ++i) {
    VOLCOMP_TRY(t.axis_table[i].Init(image.axis1d[i]));
    t.axis_table_of[image.axis1d[i].axis] = static_cast<int8_t>(i);
    if (t.axis_table[i].wraps())
      t.wrap_mask = static_cast<uint8_t>(t.wrap_mask | 1u << image.axis1d[i].axis);
  }
  if (t.has_grid) {
    for (int8_t c = 0; c < 3; ++c) t.grid_component_of[t.grid.axis(c)] = c;
  }
  t.axis_table_count = image.axis1d_count;
  t.table_id = image.table_id;
  t.crc32 = image.crc32;
  *this = t;
  return Status::Ok();
}

void PreparedTable::TargetsQ8(const int32_t* pos_steps,
                              const int32_t* axis_pos_steps,
                              const bool* reverse,
                              uint8_t axis_count,
                              int32_t* target_q8) const {
  for (uint8_t a = 0; a < axis_count; ++a) target_q8[a] = 0;
  if (has_grid) {
    int32_t g[3];
    grid.Lookup(pos_steps, g);
    for (int c = 0; c < 3; ++c) target_q8[grid.axis(c)] += g[c];
  }
  for (uint8_t a = 0; a < axis_count; ++a) {
    const int8_t i = axis_table_of[a];
    if (i >= 0) target_q8[a] += axis_table[i].Lookup(axis_pos_steps[a], reverse[a]);
  }
}

Status Compensator::Configure(const BoardConfig& config, uint32_t ticks_per_run) {
  VOLCOMP_TRY(ValidateBoardConfig(config));
  Reset(config.axis_count);
  for (uint8_t a = 0; a < config.axis_count; ++a) {
    VOLCOMP_TRY(SetAxisLimits(a, config.axis[a], config.tick_hz, ticks_per_run));
  }
  return Status::Ok();
}

void Compensator::Reset(uint8_t axis_count) {
  for (uint8_t a = 0; a < table::kMaxAxes; ++a) {
    limiter_[a] = CorrectionLimiter();
    limits_[a][0] = limits_[a][1] = LimiterParams();
    switch_k_scale_q30_[a] = 1 << 30;
    switch_state_[a] = 0;
    max_q8_[a] = 0;
    clamped_refreshes_[a] = 0;
    rate_limited_refreshes_[a] = 0;
    last_pos_[a] = 0;
    grid_part_steps_[a] = 0;
    extreme_[a] = 0;
    hysteresis_[a] = 0;
    direction_[a] = 0;
    target_q8_[a] = 0;
    thermal_[0][a] = thermal_[1][a] = thermal::ThermalTermSteps();
  }
  wrap_mask_ = 0;
  rebase_pending_ = false;
  axis_count_ = axis_count <= table::kMaxAxes ? axis_count : table::kMaxAxes;
  has_table_ = false;
  UpdateEngaged();
  phase_ = 0;
}

Status Compensator::SetAxisLimits(uint8_t a,
                                  const AxisConfig& axis,
                                  uint32_t tick_hz,
                                  uint32_t ticks_per_run) {
  if (a >= axis_count_) return Error::kInvalidArgument;
  if (axis.max_correction_steps < 0 || axis.max_correction_steps > table::kMaxCorrectionSteps ||
      axis.direction_switch_accel_steps_s2 < axis.max_correction_accel_steps_s2) {
    return Error::kConfigInvalid;
  }
  const Result<LimiterParams> p = AxisLimiterParams(axis, tick_hz, ticks_per_run);
  if (!p.ok()) return p.status();
  const Result<LimiterParams> q = AxisSwitchLimiterParams(axis, tick_hz, ticks_per_run);
  if (!q.ok()) return q.status();
  if (!limiter_[a].at_rest()) return Error::kBusy;
  limiter_[a].set_params(*p);
  limits_[a][0] = *p;
  limits_[a][1] = *q;
  // Configuration time (a division is fine): the switch's acceleration step is at least the
  // correction's where the period does not bound it, so the scale is at most 1 (capped there).
  const uint64_t scale = (static_cast<uint64_t>(p->accel_q32) << 30) / q->accel_q32;
  switch_k_scale_q30_[a] = static_cast<int32_t>(scale < (1u << 30) ? scale : (1u << 30));
  switch_state_[a] &= 2u;  // at rest: no switch in progress
  max_q8_[a] = axis.max_correction_steps * (1 << table::kCorrectionFracBits);
  hysteresis_[a] = axis.direction_hysteresis_steps;
  return Status::Ok();
}

void Compensator::SetTable(const PreparedTable& table, const int32_t* machine_pos_steps) {
  own_ = table;
  UseTable(&own_, machine_pos_steps);
}

void Compensator::ClearTable() {
  has_table_ = false;
  UpdateEngaged();
  wrap_mask_ = 0;
}

void Compensator::Rebase(const int32_t* machine_pos_steps) {
  phase_ = 0;  // a refresh in progress used the old coordinates
  rebase_pending_ = false;
  for (uint8_t a = 0; a < axis_count_; ++a) {
    last_pos_[a] = machine_pos_steps[a];
    if ((wrap_mask_ >> a) & 1u) {
      const AxisLookup& t = table_->axis_table[table_->axis_table_of[a]];
      wrap_[a].Init(machine_pos_steps[a], t.origin_steps(), t.period_divider());
    }
  }
}

void Compensator::PublishThermal(const thermal::ThermalTermSteps* terms, uint8_t count) {
  const uint8_t next = thermal_slot_ ^ 1u;
  for (uint8_t a = 0; a < table::kMaxAxes; ++a) {
    thermal_[next][a] = a < count ? terms[a] : thermal::ThermalTermSteps();
  }
  // The slot's words are stored before the index that makes it current (the run that preempts
  // this sees the whole slot or the old one).
  std::atomic_signal_fence(std::memory_order_release);
  thermal_slot_ = next;
}

bool Compensator::passthrough() const {
  for (uint8_t a = 0; a < axis_count_; ++a) {
    if (limiter_[a].position_q32() != 0 || !limiter_[a].at_rest()) return false;
  }
  return true;
}

// Inlined into RefreshTargets(): the tick's hot range (toolchain/hot-sections.ld) lists no other
// function of the refresh.
__attribute__((always_inline)) inline void Compensator::DisengageAxis(uint32_t a) {
  grid_part_steps_[a] = 0;
  const uint32_t state = switch_state_[a];
  CorrectionLimiter& limiter = limiter_[a];
  const bool rest = limiter.at_rest();
  if ((state & 1u) != 0 && rest) limiter.set_params(limits_[a][0]);  // at rest: k stays 0
  // A switch in progress comes to rest where it is (at its limits), then ramps out at the
  // correction's; the direction of the next refresh follows the drive.
  const bool braking = (state & 1u) != 0 && !rest;
  target_q8_[a] = braking ? static_cast<int32_t>(limiter.position_q32() >> 24) : 0;
  switch_state_[a] = (direction_[a] & 2u) | (braking ? 1u : 0u);
}

void Compensator::RefreshTargets(const int32_t* machine_pos_steps) {
  if (rebase_pending_) {
    Rebase(machine_pos_steps);
    return;
  }
  if (!engaged()) {
    for (uint8_t a = 0; a < axis_count_; ++a) DisengageAxis(a);
    phase_ = 0;
    return;
  }
  // One part per run; an if-chain, not a switch (a jump table would be an indirect jump, which
  // the static cycle bound of toolchain/cyclemodel refuses).
  const uint32_t phase = phase_;
  uint32_t next = phase + 1u;
  if (phase < kGridPhases) {
    const GridLookup* grid = grid_;
    if (grid != nullptr) {
      if (phase == 0) {
        grid->Begin(machine_pos_steps, &grid_partial_);
      } else if (phase == 1) {
        grid->AccumulateZ0(&grid_partial_);
      } else {
        grid->FinishZ1(grid_partial_, grid_q8_);
      }
    }
  } else {
    // Axis a: its grid component (from the positions latched in part 0), its AXIS1D table at
    // its current position and direction, clamped: the new target of the axis.
    const uint32_t a = phase - kGridPhases;
    const PreparedTable& table = *table_;
    const int8_t c = table.grid_component_of[a];
    const int8_t i = table.axis_table_of[a];
    int32_t t = c >= 0 ? grid_q8_[c] : 0;
    grid_part_steps_[a] = (t + 128) >> 8;
    const uint32_t direction = direction_[a];
    if (i >= 0) {
      const int32_t pos = (wrap_mask_ >> a) & 1u ? wrap_[a].position() : machine_pos_steps[a];
      t += table.axis_table[i].Lookup(pos, direction != 0);
    }
    // The thermal term at the commanded machine position: one 32x32->64 multiply; within int32 by
    // the bounds of thermal_term.hpp; the sum with the table's part saturates before the clamp.
    const thermal::ThermalTermSteps& th = thermal_[thermal_slot_][a];
    const int32_t from_p0 = static_cast<int32_t>(static_cast<uint32_t>(machine_pos_steps[a]) -
                                                 static_cast<uint32_t>(th.p0_steps));
    const int32_t thermal_q8 =
        th.offset_q8 + static_cast<int32_t>((static_cast<int64_t>(th.slope_q32) * from_p0) >> 24);
    const int32_t asked = AddSat(t, thermal_q8);
    const int32_t max = max_q8_[a];
    t = asked > max ? max : asked;
    t = t < -max ? -max : t;
    // Direction switch (selects, not branches): it begins at the refresh that first looks the
    // table up in the new direction if the correction had caught up with its target (within one
    // step: a ramp in progress keeps the correction's limits), and lasts while the limiter moves.
    CorrectionLimiter& limiter = limiter_[a];
    const uint32_t state = switch_state_[a];
    const int32_t behind = target_q8_[a] - static_cast<int32_t>(limiter.position_q32() >> 24);
    const uint32_t moving = limiter.at_rest() ? 0u : 1u;
    const uint32_t enter = ((state ^ direction) >> 1) & (i >= 0 ? 1u : 0u) &
                           (static_cast<uint32_t>(behind + 256) < 512u ? 1u : 0u) &
                           (~state | (moving ^ 1u));
    const uint32_t on = enter | (state & moving);
    limiter.SwitchParams(limits_[a][on & 1u], enter != 0 ? switch_k_scale_q30_[a] : 1 << 30);
    switch_state_[a] = (direction & 2u) | (on & 1u);
    target_q8_[a] = t;
    // Selects, not branches: whether the table was clamped, whether the limiter is at its rate.
    clamped_refreshes_[a] += t != asked ? 1u : 0u;
    rate_limited_refreshes_[a] += limiter_[a].at_rate_limit() ? 1u : 0u;
    next = a + 1u == axis_count_ ? 0u : next;
  }
  phase_ = static_cast<uint8_t>(next);
}

}  // namespace volcomp
