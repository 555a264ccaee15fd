// Division by a constant without a divide instruction: floor(n / d) for any uint32 n.
//
// Init(d) computes r = floor((2^32 - 1) / d) once. Then q' = (n * r) >> 32 is floor(n / d) or one
// less (the error n * (2^32/d - r) / 2^32 is below 1 for n < 2^32), and one compare of the
// remainder corrects it: a 32x32->64 multiply, a multiply-subtract and a compare, branch-free.
#pragma once

#include <cstdint>

namespace volcomp {

struct QuotientRemainder {
  uint32_t quotient;
  uint32_t remainder;
};

class InvariantDivider {
 public:
  /// `divisor` >= 1 (may divide; call at configuration time).
  void Init(uint32_t divisor) {
    divisor_ = divisor;
    recip_ = 0xFFFFFFFFu / divisor;
  }
  QuotientRemainder Divide(uint32_t n) const {
    uint32_t q = static_cast<uint32_t>((static_cast<uint64_t>(n) * recip_) >> 32);
    uint32_t r = n - q * divisor_;
    const uint32_t low = 0u - static_cast<uint32_t>(r >= divisor_);
    q -= low;
    r -= divisor_ & low;
    return {q, r};
  }
  uint32_t divisor() const { return divisor_; }

 private:
  uint32_t divisor_ = 1;
  uint32_t recip_ = 0xFFFFFFFFu;
};

}  // namespace volcomp
