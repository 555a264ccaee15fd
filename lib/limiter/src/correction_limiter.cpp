// Correction rate/acceleration limiter.
#include "volcomp/limiter/correction_limiter.hpp"

namespace volcomp {
namespace {

// (r << 32) / d for r < d (a Q32 fraction below 1) without a 96-bit intermediate: restoring
// division, one quotient bit per step (configuration time only).
uint64_t FractionQ32(uint64_t r, uint64_t d) {
  uint64_t q = 0;
  for (int i = 0; i < 32; ++i) {
    const bool carry = (r >> 63) != 0;
    r <<= 1;
    q <<= 1;
    if (carry || r >= d) {
      r -= d;
      q |= 1u;
    }
  }
  return q;
}

}  // namespace

Result<CorrectionLimiter::Params> CorrectionLimiter::MakeParams(uint32_t tick_hz,
                                                                uint32_t max_rate_steps_s,
                                                                uint32_t max_accel_steps_s2,
                                                                uint32_t ticks_per_step) {
  if (tick_hz == 0 || max_rate_steps_s == 0 || max_accel_steps_s2 == 0 || ticks_per_step == 0 ||
      ticks_per_step > 65535u) {
    return Error::kConfigInvalid;
  }
  // Per limiter step T = n / f: a = accel * n^2 / f^2 (Q32), v = rate * n / f (Q32).
  const uint64_t n = ticks_per_step;
  const uint64_t accel_n2 = max_accel_steps_s2 * n * n;  // < 2^32 * 2^32
  const uint64_t tick2 = static_cast<uint64_t>(tick_hz) * tick_hz;
  if (accel_n2 >= tick2) return Error::kConfigInvalid;  // one step per T^2 or more
  const uint64_t accel_q32 = FractionQ32(accel_n2, tick2);
  if (accel_q32 == 0) return Error::kConfigInvalid;
  // k_max = v_max / a = (rate * n / f) / (accel_q32 / 2^32) in Q32 terms.
  const uint64_t rate_n = max_rate_steps_s * n;  // < 2^48
  const uint64_t whole = rate_n / tick_hz;       // < 2^48: saturate beyond 2^31 steps per step
  const uint64_t v_q32 = whole >= (uint64_t{1} << 31)
                             ? ~uint64_t{0}
                             : (whole << 32) + FractionQ32(rate_n % tick_hz, tick_hz);
  uint64_t k = v_q32 / accel_q32;
  if (k == 0) return Error::kConfigInvalid;
  if (k > 65535) k = 65535;
  Params p;
  p.accel_q32 = static_cast<uint32_t>(accel_q32);
  p.max_k = static_cast<uint32_t>(k);
  return p;
}

}  // namespace volcomp
