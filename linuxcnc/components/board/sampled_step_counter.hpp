// Step/dir input counter for lines sampled at a fixed rate: the HAL-pin backend's stand-in for
// the board's hardware input counter (a timer in clock+direction mode on the MCU).
//
// Contract: Sample() gets the STEP and DIR levels once per sampling period (the LinuxCNC base
// thread: once per invocation). A step is counted in the sample that first sees STEP high after a
// sample that saw it low; its direction is the DIR level of that same sample: DIR high = +1,
// low = -1, swapped by `invert_dir` (AxisConfig::invert_input_dir). Nothing is lost when every
// STEP high and low phase spans at least one sample and DIR is stable from at least one sample
// before the rising edge (direction setup >= one period; LinuxCNC stepgen with step_type 0 and
// steplen, stepspace, dirsetup >= one base period).
//
// A DIR change seen in the same sample as a STEP rise means the direction of that step is
// uncertain (the setup time was shorter than one period): the step is counted with the new level,
// and the event is counted in setup_violations() so that it stays visible.
//
// The count wraps at 32 bits (ControlTick takes the low input_counter_bits). Not thread-safe; one
// context samples and reads.
#pragma once

#include <cstdint>

namespace volcomp::linuxcnc {

class SampledStepCounter {
 public:
  /// Sets the direction convention and the line levels the next sample is compared with; the
  /// count and the violation counter are kept (a hardware counter keeps counting).
  void Reset(bool invert_dir, bool step_level, bool dir_level) {
    invert_dir_ = invert_dir;
    step_ = step_level;
    dir_ = dir_level;
  }

  /// One sample of the two lines.
  void Sample(bool step, bool dir) {
    const bool rise = step && !step_;
    // Branch-free: +1 or -1 on a rise, 0 otherwise.
    const uint32_t positive = (dir != invert_dir_) ? 1u : 0u;
    count_ += static_cast<uint32_t>(rise) * (2u * positive - 1u);
    violations_ += static_cast<uint32_t>(rise && dir != dir_);
    step_ = step;
    dir_ = dir;
  }

  /// Steps counted so far (signed count modulo 2^32).
  uint32_t count() const { return count_; }
  /// Steps whose DIR level changed in the sample of their rising edge.
  uint32_t setup_violations() const { return violations_; }

 private:
  uint32_t count_ = 0;
  uint32_t violations_ = 0;
  bool invert_dir_ = false;
  bool step_ = false;
  bool dir_ = false;
};

}  // namespace volcomp::linuxcnc
