// The per-tick data path.
#include "volcomp/control_tick.hpp"

namespace volcomp {

Status ControlTick::Configure(const BoardConfig& config) {
  VOLCOMP_TRY(ValidateBoardConfig(config));
  VOLCOMP_TRY(compensator_.Configure(config));
  for (uint8_t a = 0; a < config.axis_count; ++a) {
    counter_shift_[a] = static_cast<uint8_t>(32u - config.axis[a].input_counter_bits);
    last_counter_[a] = 0;
    commanded_[a] = machine_[a] = correction_[a] = target_[a] = 0;
    reference_offset_[a] = 0;
    referenced_[a] = false;
  }
  config_ = config;
  axis_count_ = config.axis_count;
  idle_ticks_ = 0xFFFFFFFFu;
  ticks_ = 0;
  compensator_.SetReferenced(false);
  return Status::Ok();
}

void ControlTick::LatchCounters(const uint32_t* input_counters) {
  for (uint8_t a = 0; a < axis_count_; ++a) last_counter_[a] = input_counters[a];
}

void ControlTick::Reference(uint8_t axis) {
  if (axis < axis_count_) ReferenceAxes(1u << axis);
}

void ControlTick::ReferenceAxes(uint32_t axis_mask) {
  uint32_t done = 0;
  for (uint32_t a = 0; a < axis_count_; ++a) {
    if ((axis_mask & (1u << a)) == 0) continue;
    reference_offset_[a] =
        static_cast<int32_t>(static_cast<uint32_t>(config_.axis[a].home_position_steps) -
                             static_cast<uint32_t>(commanded_[a]));
    machine_[a] = config_.axis[a].home_position_steps;
    referenced_[a] = true;
    done |= 1u << a;
  }
  if (done == 0) return;
  // One rebase for every axis referenced at once (the same state as one Reference() per axis).
  compensator_.Rebase(machine_);
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
