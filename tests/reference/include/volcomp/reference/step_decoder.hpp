// Software model of a step-input counter: decodes step+dir, CW/CCW or A/B quadrature line levels.
//
// On the MCU a timer in encoder / clock+direction mode does this in hardware; this class is the
// same logic in software (the reference library, tests/reference), for tests that drive the tick
// from simulated input lines, and the reference the hardware is checked against. Feed it the levels
// of the two input lines after every change (or at any sample rate at which each line changes at
// most once between samples).
//   step+dir:   a = STEP, b = DIR; a rising edge of STEP counts +1 if DIR is high, else -1
//               (inverted when invert_dir).
//   CW/CCW:     a = CW, b = CCW; a rising edge on CW counts +1, on CCW -1.
//   quadrature: a = A, b = B; every edge counts; A leading B is +1. A sample in which both lines
//               changed is a decoding error (counted, no step).
#pragma once

#include <cstdint>

#include "volcomp/config/board_config.hpp"

namespace volcomp {

class StepDecoder {
 public:
  explicit StepDecoder(PulseFormat format = PulseFormat::kStepDir, bool invert_dir = false)
      : format_(format), invert_dir_(invert_dir) {}

  /// Sets the initial line levels without counting.
  void Reset(bool a, bool b) {
    a_ = a;
    b_ = b;
  }

  /// Takes the current line levels; returns the count change (-1, 0 or +1).
  int32_t Sample(bool a, bool b);

  int32_t count() const { return count_; }
  uint32_t errors() const { return errors_; }

 private:
  PulseFormat format_;
  bool invert_dir_;
  bool a_ = false;
  bool b_ = false;
  int32_t count_ = 0;
  uint32_t errors_ = 0;
};

}  // namespace volcomp
