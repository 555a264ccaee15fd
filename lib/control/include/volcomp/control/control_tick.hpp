// The board's data path from the input stage's counters to the target positions (whole steps,
// wrapping int32; target = commanded + applied correction, exactly, every tick), in two parts:
// RunSteps() every tick and Compensate() every compensation_divider() ticks; Run() is both in
// order. Both: no division, no allocation, O(axes). Threading: RunSteps() may preempt Compensate()
// (they share only single-word relaxed atomics, each written by one side); everything else from
// the compensation context between runs. The schedule and its rules: docs/mcu-target.md, "Two
// rates"; the output stages that take targets(): docs/architecture.md.
#pragma once

#include <atomic>
#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/config/board_config.hpp"
#include "volcomp/control/compensator.hpp"
#include "volcomp/table/table_format.hpp"

namespace volcomp {

class ControlTick {
 public:
  /// Validates and applies `config`; resets positions to zero, unreferenced, no table. The input
  /// counters' baseline is zero until LatchCounters() says otherwise. Keeps what the data path
  /// needs, not `config` itself: the caller owns the configuration in force.
  Status Configure(const BoardConfig& config);

  /// Takes the current raw counter values as the baseline (commanded position unchanged), e.g. at
  /// start-up when the hardware counters hold arbitrary values.
  void LatchCounters(const uint32_t* input_counters);

  /// One tick as a whole: RunSteps(), then Compensate() when due.
  void Run(const uint32_t* input_counters) {
    if (RunSteps(input_counters)) Compensate();
  }
  /// The step path of one tick: `input_counters[a]` is the raw input counter of axis a (wrapping
  /// at its configured width); sets commanded, applied correction and target of every configured
  /// axis. Returns true when Compensate() is due (every compensation_divider() ticks, the first
  /// tick included). Always inlined (below): the tick routine that calls it and then its output
  /// stage is one function, one prologue.
  inline bool RunSteps(const uint32_t* input_counters);
  /// One compensation run: machine positions from the commanded positions, the compensator's
  /// sensing, one target refresh slice (or a requested rebase), the limiters; publishes the
  /// corrections the next RunSteps() apply.
  inline void Compensate();
  /// Compensate() for a run that rebases the compensator (a table switch or referencing): the
  /// rebase in place of the target refresh slice, as compensator().RequestRebase() followed by
  /// Compensate() would do it, written as its own path so that the static cycle bound of such a
  /// run (the hand-over's work and the rebase) and of a normal run (the refresh) are separate
  /// (docs/mcu-target.md, "Two rates").
  inline void CompensateRebasing();
  /// Ticks per compensation run (CompensationDivider() of the configured tick rate).
  uint32_t compensation_divider() const { return divider_; }

  /// Declares axis `a` referenced now: its machine position becomes the configured home position.
  void Reference(uint8_t axis);
  /// Reference() for every axis whose bit is set in `axis_mask` (bits of unconfigured axes are
  /// ignored), with one compensator rebase: the tick's bounded cost for referencing all axes.
  void ReferenceAxes(uint32_t axis_mask) {
    if (MarkReferenced(axis_mask)) RebaseCompensator();
  }
  /// ReferenceAxes() without the compensator's rebase, for a tick that rebases once after several
  /// changes (a table switch and referencing): returns true when an axis was referenced, and then
  /// a rebase must follow: RebaseCompensator() now, or compensator().RequestRebase(), which the
  /// next Run() performs in place of its target refresh.
  bool MarkReferenced(uint32_t axis_mask);
  /// Restarts the compensator's direction and wrap tracking at the present machine positions
  /// (Compensator::Rebase()).
  void RebaseCompensator() { compensator_.Rebase(machine_); }
  /// Forgets all references (e.g. drive alarm, e-stop): the correction ramps out.
  void Unreference();
  bool referenced(uint8_t axis) const { return ((referenced_mask_ >> axis) & 1u) != 0; }
  bool all_referenced() const {
    return axis_count_ > 0 && referenced_mask_ == (1u << axis_count_) - 1u;
  }

  Compensator& compensator() { return compensator_; }
  const Compensator& compensator() const { return compensator_; }
  uint8_t axis_count() const { return axis_count_; }

  int32_t commanded(uint8_t a) const { return commanded_[a].load(std::memory_order_relaxed); }
  /// Commanded position in machine coordinates (commanded + reference offset).
  int32_t machine_position(uint8_t a) const {
    return static_cast<int32_t>(static_cast<uint32_t>(commanded(a)) +
                                static_cast<uint32_t>(reference_offset_[a]));
  }
  /// Whole-step correction applied in the last tick (the compensator's output).
  int32_t correction_steps(uint8_t a) const { return correction_[a]; }
  /// Whole-step correction the last compensation run published (the next tick applies it).
  int32_t published_correction_steps(uint8_t a) const {
    return published_[a].load(std::memory_order_relaxed);
  }
  /// Target position of the last tick: commanded + correction_steps (wrapping int32).
  int32_t target(uint8_t a) const { return target_[a]; }
  /// All axes' targets and corrections of the last tick (what the output stages take).
  const int32_t* targets() const { return target_; }
  const int32_t* corrections() const { return correction_; }
  uint64_t ticks() const { return ticks_; }
  /// Ticks since an input step was last counted on any axis (saturates).
  uint32_t idle_ticks() const { return idle_ticks_; }

 private:
  uint8_t axis_count_ = 0;
  Compensator compensator_;
  uint32_t last_counter_[table::kMaxAxes] = {};
  uint8_t counter_shift_[table::kMaxAxes] = {};           // 32 - counter bits
  std::atomic<int32_t> commanded_[table::kMaxAxes] = {};  // step path -> compensation
  int32_t reference_offset_[table::kMaxAxes] = {};
  uint32_t referenced_mask_ = 0;           // bit a: axis a referenced
  int32_t machine_[table::kMaxAxes] = {};  // the compensation's positions (its last run)
  std::atomic<int32_t> published_[table::kMaxAxes] = {};  // compensation -> step path
  int32_t correction_[table::kMaxAxes] = {};
  int32_t target_[table::kMaxAxes] = {};
  uint32_t divider_ = 1;    // ticks per compensation run
  uint32_t countdown_ = 1;  // ticks until the next compensation run is due
  uint64_t ticks_ = 0;
  uint32_t idle_ticks_ = 0xFFFFFFFFu;
  int32_t home_[table::kMaxAxes] = {};  // machine position at the reference (home_position_steps)

  // Compensate()'s walks over the axes before and after the refresh (or rebase).
  inline void SenseAxes();
  inline void LimitAndPublish();
};

__attribute__((always_inline)) inline bool ControlTick::RunSteps(const uint32_t* input_counters) {
  const uint32_t n = axis_count_;
  uint32_t moved = 0;
  for (uint32_t a = 0; a < n; ++a) {
    const uint32_t raw = input_counters[a];
    // Sign-extend the counter difference from the counter width (16 or 32 bits).
    const uint32_t shift = counter_shift_[a];
    const uint32_t diff = (raw - last_counter_[a]) << shift;
    last_counter_[a] = raw;
    moved |= diff;
    const uint32_t commanded =
        static_cast<uint32_t>(commanded_[a].load(std::memory_order_relaxed)) +
        static_cast<uint32_t>(static_cast<int32_t>(diff) >> shift);
    commanded_[a].store(static_cast<int32_t>(commanded), std::memory_order_relaxed);
    const int32_t correction = published_[a].load(std::memory_order_relaxed);
    correction_[a] = correction;
    target_[a] = static_cast<int32_t>(commanded + static_cast<uint32_t>(correction));
  }
  idle_ticks_ = moved != 0 ? 0u : idle_ticks_ + (idle_ticks_ != 0xFFFFFFFFu ? 1u : 0u);
  ++ticks_;
  const uint32_t left = countdown_ - 1u;
  const bool due = left == 0;
  countdown_ = due ? divider_ : left;
  return due;
}

__attribute__((always_inline)) inline void ControlTick::SenseAxes() {
  const uint32_t n = axis_count_;
  for (uint32_t a = 0; a < n; ++a) {
    const int32_t machine =
        static_cast<int32_t>(static_cast<uint32_t>(commanded_[a].load(std::memory_order_relaxed)) +
                             static_cast<uint32_t>(reference_offset_[a]));
    machine_[a] = machine;
    compensator_.SenseAxis(static_cast<uint8_t>(a), machine);
  }
}

__attribute__((always_inline)) inline void ControlTick::LimitAndPublish() {
  const uint32_t n = axis_count_;
  for (uint32_t a = 0; a < n; ++a) {
    published_[a].store(compensator_.LimitAxis(static_cast<uint8_t>(a)), std::memory_order_relaxed);
  }
}

__attribute__((always_inline)) inline void ControlTick::Compensate() {
  // Compensator::Run() in its three steps, fused with the machine-position work of each axis.
  SenseAxes();
  compensator_.RefreshTargets(machine_);
  LimitAndPublish();
}

__attribute__((always_inline)) inline void ControlTick::CompensateRebasing() {
  SenseAxes();
  compensator_.Rebase(machine_);
  LimitAndPublish();
}

}  // namespace volcomp
