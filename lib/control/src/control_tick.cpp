// The per-tick data path.
#include "volcomp/control/control_tick.hpp"

namespace volcomp {

Status ControlTick::Configure(const BoardConfig& config) {
  VOLCOMP_TRY(ValidateBoardConfig(config));
  VOLCOMP_TRY(compensator_.Configure(config, CompensationDivider(config.tick_hz)));
  for (uint8_t a = 0; a < config.axis_count; ++a) {
    counter_shift_[a] = static_cast<uint8_t>(32u - config.axis[a].input_counter_bits);
    last_counter_[a] = 0;
    commanded_[a].store(0, std::memory_order_relaxed);
    published_[a].store(0, std::memory_order_relaxed);
    machine_[a] = correction_[a] = target_[a] = 0;
    reference_offset_[a] = 0;
    home_[a] = config.axis[a].home_position_steps;
  }
  referenced_mask_ = 0;
  axis_count_ = config.axis_count;
  divider_ = CompensationDivider(config.tick_hz);
  countdown_ = 1;
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

bool ControlTick::MarkReferenced(uint32_t axis_mask) {
  const uint32_t n = axis_count_;
  const uint32_t done = axis_mask & ((1u << n) - 1u);
  if (done == 0) return false;
  for (uint32_t a = 0; a < n; ++a) {
    if (((done >> a) & 1u) == 0) continue;
    const int32_t home = home_[a];
    reference_offset_[a] = static_cast<int32_t>(
        static_cast<uint32_t>(home) - static_cast<uint32_t>(commanded(static_cast<uint8_t>(a))));
    machine_[a] = home;
    compensator_.MoveAxis(static_cast<uint8_t>(a), home);
  }
  referenced_mask_ |= done;
  // The caller's one rebase covers every axis referenced at once (the same state as one
  // Reference() per axis).
  compensator_.SetReferenced(all_referenced());
  return true;
}

void ControlTick::Unreference() {
  referenced_mask_ = 0;
  compensator_.SetReferenced(false);
}

}  // namespace volcomp
