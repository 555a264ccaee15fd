// The per-tick data path.
#include "volcomp/control_tick.hpp"

namespace volcomp {

Status ControlTick::Configure(const BoardConfig& config) {
  VOLCOMP_TRY(ValidateBoardConfig(config));
  VOLCOMP_TRY(compensator_.Configure(config));
  for (uint8_t a = 0; a < config.axis_count; ++a) {
    VOLCOMP_TRY(generator_[a].Configure(config.axis[a], config.tick_hz, config.pulse_clock_hz));
    generator_[a].Reset(0);
    counter_shift_[a] = static_cast<uint8_t>(32u - config.axis[a].input_counter_bits);
    last_counter_[a] = 0;
    commanded_[a] = machine_[a] = correction_[a] = target_[a] = 0;
    reference_offset_[a] = 0;
    referenced_[a] = false;
    max_backlog_[a] = 0;
  }
  config_ = config;
  axis_count_ = config.axis_count;
  idle_ticks_ = 0xFFFFFFFFu;
  overruns_ = 0;
  ticks_ = 0;
  compensator_.SetReferenced(false);
  return Status::Ok();
}

void ControlTick::Run(const uint32_t* input_counters, PulsePlan* plans) {
  // Two walks over the axes around the compensator's target refresh (Compensator::Tick() in its
  // three steps, fused with the counter and output work of each axis).
  uint32_t moved = 0;
  for (uint8_t a = 0; a < axis_count_; ++a) {
    const uint32_t raw = input_counters[a];
    // Sign-extend the counter difference from the counter width (16 or 32 bits).
    const uint32_t diff = (raw - last_counter_[a]) << counter_shift_[a];
    last_counter_[a] = raw;
    moved |= diff;
    const uint32_t commanded =
        static_cast<uint32_t>(commanded_[a]) +
        static_cast<uint32_t>(static_cast<int32_t>(diff) >> counter_shift_[a]);
    commanded_[a] = static_cast<int32_t>(commanded);
    machine_[a] = static_cast<int32_t>(commanded + static_cast<uint32_t>(reference_offset_[a]));
    compensator_.SenseAxis(a, machine_[a]);
  }
  compensator_.RefreshTargets(machine_);
  for (uint8_t a = 0; a < axis_count_; ++a) {
    const int32_t correction = compensator_.ApplyAxis(a);
    correction_[a] = correction;
    const int32_t target = static_cast<int32_t>(static_cast<uint32_t>(commanded_[a]) +
                                                static_cast<uint32_t>(correction));
    target_[a] = target;
    const uint32_t left = generator_[a].PlanTick(target, &plans[a]);
    max_backlog_[a] = left > max_backlog_[a] ? left : max_backlog_[a];
    overruns_ += left > generator_[a].max_pulses_per_tick() ? 1u : 0u;
  }
  idle_ticks_ = moved != 0 ? 0u : idle_ticks_ + (idle_ticks_ != 0xFFFFFFFFu ? 1u : 0u);
  ++ticks_;
}

void ControlTick::LatchCounters(const uint32_t* input_counters) {
  for (uint8_t a = 0; a < axis_count_; ++a) last_counter_[a] = input_counters[a];
}

void ControlTick::Reference(uint8_t axis) {
  if (axis >= axis_count_) return;
  reference_offset_[axis] =
      static_cast<int32_t>(static_cast<uint32_t>(config_.axis[axis].home_position_steps) -
                           static_cast<uint32_t>(commanded_[axis]));
  machine_[axis] = config_.axis[axis].home_position_steps;
  compensator_.Rebase(machine_);
  referenced_[axis] = true;
  compensator_.SetReferenced(all_referenced());
}

void ControlTick::Unreference() {
  for (uint8_t a = 0; a < axis_count_; ++a) referenced_[a] = false;
  compensator_.SetReferenced(false);
}

bool ControlTick::all_referenced() const {
  for (uint8_t a = 0; a < axis_count_; ++a) {
    if (!referenced_[a]) return false;
  }
  return axis_count_ > 0;
}

}  // namespace volcomp
