// Step input decoding.
#include "volcomp/reference/step_decoder.hpp"

namespace volcomp {

int32_t StepDecoder::Sample(bool a, bool b) {
  int32_t delta = 0;
  switch (format_) {
    case PulseFormat::kStepDir:
      if (a && !a_) delta = (b != invert_dir_) ? 1 : -1;
      break;
    case PulseFormat::kCwCcw:
      delta = static_cast<int32_t>(a && !a_) - static_cast<int32_t>(b && !b_);
      break;
    case PulseFormat::kQuadrature: {
      // Gray sequence for +1: (A,B) = 00 -> 10 -> 11 -> 01 -> 00.
      static constexpr int8_t kDelta[4][4] = {
          // to: 00  01  10  11      (index = A*2 + B)
          {0, -1, +1, 0},  // from 00
          {+1, 0, 0, -1},  // from 01
          {-1, 0, 0, +1},  // from 10
          {0, +1, -1, 0},  // from 11
      };
      const int from = (a_ ? 2 : 0) | (b_ ? 1 : 0);
      const int to = (a ? 2 : 0) | (b ? 1 : 0);
      if (from != to && (from ^ to) == 3) ++errors_;
      delta = kDelta[from][to];
      break;
    }
  }
  a_ = a;
  b_ = b;
  count_ += delta;
  return delta;
}

}  // namespace volcomp
