// The board's step I/O (hal/step_io.hpp: Configure, ReadCounters, Apply) on HAL bit pins, sampled
// once per invocation of LinuxCNC's base thread (period `period_ns`).
//
// Input: each base period the STEP and DIR levels of every axis (written by stepgen earlier in the
// same thread) go to a SampledStepCounter per axis, which plays the hardware input counter.
// stepgen with step_type 0 and steplen, stepspace, dirsetup, dirhold >= 1 base period changes each
// line at most once per period, so sampling every period sees every edge.
//
// Output: Apply() turns a tick's PulsePlans into line edges at absolute times (ns); Render() sets
// each output pin to the level its line has at the current sampling instant. The drives (counters
// later in the same thread) therefore see the board's ideal output waveform sampled at the base
// period. That loses no pulse when every high and every low phase lasts at least one base period
// (an interval of length >= P always contains a multiple of P): Configure() refuses drive timing
// shorter than one period, which is why the control tick is at least two base periods
// (StepGenerator needs a whole pulse per tick).
//
// Configure() refuses (kConfigInvalid) what this backend cannot do: more than kAxes axes, a pulse
// format other than step/dir, a pulse clock other than 1 GHz (plans are read as ns), a pulse
// width, step space, direction setup or hold shorter than one base period, or a tick that carries
// more pulses than the edge queue holds.
//
// Single-threaded: everything runs in the base thread function.
#pragma once

#include <cstdint>

#include "board/sampled_step_counter.hpp"
#include "volcomp/base/status.hpp"
#include "volcomp/config/board_config.hpp"
#include "volcomp/output/step_generator.hpp"

namespace volcomp::linuxcnc {

class HalStepIo {
 public:
  static constexpr uint8_t kAxes = 3;

  /// `period_ns`: the base thread's period (> 0); `dir_negative_high`: the output DIR level for a
  /// negative move (how the drives are wired).
  HalStepIo(uint32_t period_ns, bool dir_negative_high)
      : period_ns_(period_ns), dir_negative_high_(dir_negative_high) {}

  // StepIo (volcomp/hal/step_io.hpp). Configure() keeps the input counts (a hardware counter
  // keeps counting) and drops the output edges not yet rendered (the output stage restarts).
  Status Configure(const BoardConfig& config);
  void ReadCounters(uint32_t* counters) const;
  void Apply(const PulsePlan* plans);

  /// One base period's input sample (levels of STEP and DIR per axis).
  void SampleInputs(const bool* step, const bool* dir);
  /// Starts the tick whose plans the next Apply() gets, at absolute time `now_ns`.
  void BeginTick(int64_t now_ns) { tick_start_ns_ = now_ns; }
  /// The output levels at absolute time `now_ns` (applies every edge at or before it).
  void Render(int64_t now_ns, bool* step, bool* dir);

  uint32_t period_ns() const { return period_ns_; }
  /// Pulses rendered so far per axis (rising edges on the step line), and edge queue overflows
  /// (must stay 0: an overflow would lose pulses).
  int64_t rendered_pulses(uint8_t a) const { return rendered_[a]; }
  uint32_t queue_overflows() const { return overflows_; }
  /// Input steps whose direction was uncertain (SampledStepCounter::setup_violations), all axes.
  uint32_t decode_errors() const;

 private:
  struct Edge {
    int64_t t_ns;
    bool dir_line;  // false: step line
    bool level;
  };
  static constexpr uint32_t kQueue = 32;  // edges per axis

  void Push(uint8_t a, const Edge& e);

  uint32_t period_ns_;
  bool dir_negative_high_;
  uint8_t axis_count_ = 0;
  uint32_t counter_mask_[kAxes] = {};
  bool in_step_[kAxes] = {}, in_dir_[kAxes] = {};  // the last input sample
  SampledStepCounter counter_[kAxes];
  int64_t tick_start_ns_ = 0;
  Edge queue_[kAxes][kQueue] = {};
  uint32_t head_[kAxes] = {}, tail_[kAxes] = {};
  bool step_level_[kAxes] = {}, dir_level_[kAxes] = {};
  int64_t rendered_[kAxes] = {};
  uint32_t overflows_ = 0;
};

}  // namespace volcomp::linuxcnc
