// Correction rate/acceleration limiter.
#include "volcomp/correction_limiter.hpp"

namespace volcomp {

Result<CorrectionLimiter::Params> CorrectionLimiter::MakeParams(uint32_t tick_hz,
                                                                uint32_t max_rate_steps_s,
                                                                uint32_t max_accel_steps_s2) {
  if (tick_hz == 0 || max_rate_steps_s == 0 || max_accel_steps_s2 == 0) {
    return Error::kConfigInvalid;
  }
  const uint64_t tick2 = static_cast<uint64_t>(tick_hz) * tick_hz;
  const uint64_t accel_q32 = (static_cast<uint64_t>(max_accel_steps_s2) << 32) / tick2;
  if (accel_q32 == 0 || accel_q32 > 0xFFFFFFFFu) return Error::kConfigInvalid;
  // k_max = v_max / a = (rate / f) / (accel_q32 / 2^32) in Q32 terms.
  const uint64_t v_q32 = (static_cast<uint64_t>(max_rate_steps_s) << 32) / tick_hz;
  uint64_t k = v_q32 / accel_q32;
  if (k == 0) return Error::kConfigInvalid;
  if (k > 65535) k = 65535;
  Params p;
  p.accel_q32 = static_cast<uint32_t>(accel_q32);
  p.max_k = static_cast<uint32_t>(k);
  return p;
}

}  // namespace volcomp
