// The step/dir output stage: one StepGenerator per axis, planning each tick the pulses that move
// every output toward ControlTick::targets(); output = target exactly once the owed steps are
// worked off. Plan()/PlanEach(): the tick's output step, no division, no allocation, O(axes);
// Configure(): control context between ticks. Latency and backlog: docs/control-path.md.
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/config/board_config.hpp"
#include "volcomp/output/step_generator.hpp"
#include "volcomp/table/table_format.hpp"

namespace volcomp {

class StepOutput {
 public:
  /// Converts every configured axis's drive timing (StepGenerator::Configure: kConfigInvalid when
  /// a tick cannot carry one pulse or a time is out of range); output positions restart at zero,
  /// backlog statistics cleared. On error the stage keeps no axes.
  Status Configure(const BoardConfig& config);

  /// One tick: plans[a] moves axis a toward target_steps[a], for every configured axis. Inline:
  /// the walk over the axes becomes part of the tick routine that calls it (one routine, one
  /// prologue); each axis is one call of StepGenerator::PlanTick().
  __attribute__((always_inline)) void Plan(const int32_t* target_steps, PulsePlan* plans) {
    Walk(
        target_steps, [plans](uint32_t a, PulsePlan&) -> PulsePlan& { return plans[a]; },
        [](uint32_t, const PulsePlan&) {});
  }
  /// Plan() handing each axis's plan to `sink(a, plan)` as soon as it is made, in axis order
  /// (a step I/O that programs its timers per axis takes the plan from registers: no plan array
  /// between planning and output).
  template <class Sink>
  __attribute__((always_inline)) void PlanEach(const int32_t* target_steps, Sink&& sink) {
    Walk(
        target_steps, [](uint32_t, PulsePlan& local) -> PulsePlan& { return local; }, sink);
  }

  uint8_t axis_count() const { return axis_count_; }
  /// Output position after every pulse planned so far.
  int32_t position(uint8_t a) const { return axis_[a].generator.position(); }
  /// Steps still owed toward `target_steps` (the target of the last Plan()) after the last tick.
  int32_t backlog(uint8_t a, int32_t target_steps) const {
    return axis_[a].generator.backlog(target_steps);
  }
  /// Largest number of steps owed after a tick since Configure(), per axis.
  uint32_t max_backlog(uint8_t a) const { return axis_[a].max_backlog; }
  /// Ticks whose owed steps exceeded one tick's pulse capacity (the latency bound was at risk).
  uint32_t overruns() const { return overruns_; }
  const StepGenerator& generator(uint8_t a) const { return axis_[a].generator; }

 private:
  struct Axis {
    StepGenerator generator;
    uint32_t max_backlog = 0;
  };
  // The walk of Plan() and PlanEach(): axis a's plan goes to slot(a, local), then to sink(a, plan).
  template <class Slot, class Sink>
  __attribute__((always_inline)) void Walk(const int32_t* target_steps, Slot&& slot, Sink&& sink) {
    // Pointer walk, overrun count in a register: few live registers around the calls.
    uint32_t overruns = overruns_;
    Axis* const end = axis_ + axis_count_;
    uint32_t a = 0;
    for (Axis* ax = axis_; ax != end; ++ax, ++target_steps, ++a) {
      PulsePlan local;
      PulsePlan& plan = slot(a, local);
      const uint32_t left = ax->generator.PlanTick(*target_steps, &plan);
      ax->max_backlog = left > ax->max_backlog ? left : ax->max_backlog;
      overruns += left > ax->generator.max_pulses_per_tick() ? 1u : 0u;
      sink(a, plan);
    }
    overruns_ = overruns;
  }
  uint8_t axis_count_ = 0;
  uint32_t overruns_ = 0;
  Axis axis_[table::kMaxAxes];
};

}  // namespace volcomp
