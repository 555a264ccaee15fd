// The per-tick data path of the board, as pure logic:
//
//   input counters -> commanded position -> (+ reference offset) machine position
//     -> compensator (lookup, clamp, rate limit) -> output target = commanded + correction
//     -> step generators -> one PulsePlan per axis
//
// Output position = input position + applied correction, exactly: the generators never drop or add
// a step; whatever does not fit a tick's timing stays as backlog for the next. Latency: an input
// step counted before tick k's counter read is planned in tick k (<= 2 ticks from edge to output
// while the backlog stays within one tick's pulse capacity; backlog() shows it).
//
// Run() is the tick ISR's body: no division, no allocation, O(axes). Everything else is for the
// control context between ticks.
#pragma once

#include <cstdint>

#include "volcomp/board_config.hpp"
#include "volcomp/compensator.hpp"
#include "volcomp/status.hpp"
#include "volcomp/step_generator.hpp"

namespace volcomp {

class ControlTick {
 public:
  /// Validates and applies `config`; resets positions to zero, unreferenced, no table. The input
  /// counters' baseline is zero until LatchCounters() says otherwise.
  Status Configure(const BoardConfig& config);

  /// Takes the current raw counter values as the baseline (commanded position unchanged), e.g. at
  /// start-up when the hardware counters hold arbitrary values.
  void LatchCounters(const uint32_t* input_counters);

  /// One tick: `input_counters[a]` is the raw hardware counter of axis a (wrapping at its
  /// configured width); fills `plans[a]` for every configured axis.
  void Run(const uint32_t* input_counters, PulsePlan* plans);

  /// Declares axis `a` referenced now: its machine position becomes the configured home position.
  void Reference(uint8_t axis);
  /// Forgets all references (e.g. drive alarm, e-stop): the correction ramps out.
  void Unreference();
  bool referenced(uint8_t axis) const { return referenced_[axis]; }
  bool all_referenced() const;

  Compensator& compensator() { return compensator_; }
  const Compensator& compensator() const { return compensator_; }
  uint8_t axis_count() const { return axis_count_; }
  const BoardConfig& config() const { return config_; }

  int32_t commanded(uint8_t a) const { return commanded_[a]; }
  int32_t machine_position(uint8_t a) const { return machine_[a]; }
  int32_t correction_steps(uint8_t a) const { return correction_[a]; }
  int32_t output_target(uint8_t a) const { return target_[a]; }
  int32_t output_position(uint8_t a) const { return generator_[a].position(); }
  /// Steps still owed to the drive after the last tick (0 when caught up).
  int32_t backlog(uint8_t a) const { return generator_[a].backlog(target_[a]); }
  /// Largest |backlog| seen since Configure(), per axis.
  uint32_t max_backlog(uint8_t a) const { return max_backlog_[a]; }
  uint64_t ticks() const { return ticks_; }
  /// Ticks since an input step was last counted on any axis (saturates).
  uint32_t idle_ticks() const { return idle_ticks_; }
  /// Ticks whose owed steps exceeded one tick's pulse capacity (the latency bound was at risk).
  uint32_t overruns() const { return overruns_; }
  const StepGenerator& generator(uint8_t a) const { return generator_[a]; }

 private:
  BoardConfig config_;
  uint8_t axis_count_ = 0;
  Compensator compensator_;
  StepGenerator generator_[table::kMaxAxes];
  uint32_t last_counter_[table::kMaxAxes] = {};
  uint8_t counter_shift_[table::kMaxAxes] = {};  // 32 - counter bits
  int32_t commanded_[table::kMaxAxes] = {};
  int32_t reference_offset_[table::kMaxAxes] = {};
  bool referenced_[table::kMaxAxes] = {};
  int32_t machine_[table::kMaxAxes] = {};
  int32_t correction_[table::kMaxAxes] = {};
  int32_t target_[table::kMaxAxes] = {};
  uint32_t max_backlog_[table::kMaxAxes] = {};
  uint64_t ticks_ = 0;
  uint32_t idle_ticks_ = 0xFFFFFFFFu;
  uint32_t overruns_ = 0;
};

}  // namespace volcomp
