// The board's step I/O on HAL bit pins, sampled once per invocation of LinuxCNC's base thread.
//
// Input: each base period the STEP and DIR levels of every axis (written by stepgen earlier in the
// same thread) go through the firmware's StepDecoder, which plays the hardware input counter.
// stepgen with step_type 0 and steplen, stepspace, dirsetup, dirhold >= 1 base period changes each
// line at most once per period, so sampling every period sees every edge.
//
// Output: Apply() turns a tick's PulsePlans into line edges at absolute times (ns); Render() sets
// each output pin to the level its line has at the current sampling instant. The drives (encoder
// counters later in the same thread) therefore see the board's ideal output waveform sampled at
// the base period. That loses no pulse when every high and every low phase lasts at least one base
// period (an interval of length >= P always contains a multiple of P): the board's drive timing is
// configured so (pulse width, step space, direction setup and hold >= one base period), which is
// why the control tick is two base periods (StepGenerator needs a whole pulse per tick).
//
// Single-threaded: everything runs in the base thread function.
#pragma once

#include <cstdint>

#include "volcomp/step_decoder.hpp"
#include "volcomp/step_generator.hpp"
#include "volcomp/table_format.hpp"

namespace volcomp::linuxcnc {

class HalStepIo {
 public:
  static constexpr uint8_t kAxes = 3;

  /// Input decoding per axis; output direction level for a negative move (`dir_negative_high`).
  void Configure(bool invert_input_dir, bool dir_negative_high);

  /// One base period's input sample (levels of STEP and DIR per axis).
  void SampleInputs(const bool* step, const bool* dir);

  // StepIo (volcomp/hal/step_io.hpp), called from BoardApp::Tick().
  void ReadCounters(uint32_t* counters) const;
  void Apply(const PulsePlan* plans);

  /// Starts the tick whose plans the next Apply() gets, at absolute time `now_ns`.
  void BeginTick(int64_t now_ns) { tick_start_ns_ = now_ns; }
  /// The output levels at absolute time `now_ns` (applies every edge at or before it).
  void Render(int64_t now_ns, bool* step, bool* dir);

  /// Pulses rendered so far per axis (rising edges on the step line), and edge queue overflows
  /// (must stay 0: an overflow would lose pulses).
  int64_t rendered_pulses(uint8_t a) const { return rendered_[a]; }
  uint32_t queue_overflows() const { return overflows_; }
  uint32_t decode_errors() const;

 private:
  struct Edge {
    int64_t t_ns;
    bool dir_line;  // false: step line
    bool level;
  };
  static constexpr uint32_t kQueue = 32;  // per axis; a tick queues at most 3 edges at 1 pulse/tick

  void Push(uint8_t a, const Edge& e);

  StepDecoder decoder_[kAxes];
  uint32_t counter_[kAxes] = {};
  bool dir_negative_high_ = true;
  int64_t tick_start_ns_ = 0;
  Edge queue_[kAxes][kQueue] = {};
  uint32_t head_[kAxes] = {}, tail_[kAxes] = {};
  bool step_level_[kAxes] = {}, dir_level_[kAxes] = {};
  int64_t rendered_[kAxes] = {};
  uint32_t overflows_ = 0;
};

}  // namespace volcomp::linuxcnc
