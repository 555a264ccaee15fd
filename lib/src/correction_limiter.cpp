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

// The same decisions as LimiterStepReference() (tests/reference/src/hot_path_reference.cpp),
// arranged for the Cortex-M4: both braking distances a * m(m+1)/2 the decision may need are formed
// up front (one MLA, one shift and one UMULL each; m <= max_k <= 65535 where they are used, so
// m(m+1) < 2^32) and the outcome is selected; the velocity direction is a sign flip instead of a
// multiply.
int64_t CorrectionLimiter::Step(int64_t target_q32) {
  const int64_t e = target_q32 - pos_;
  const bool toward_negative = e < 0;
  const uint64_t dist = toward_negative ? 0u - static_cast<uint64_t>(e) : static_cast<uint64_t>(e);
  const uint32_t a = params_.accel_q32;
  const int32_t max_k = static_cast<int32_t>(params_.max_k);
  const int32_t s = toward_negative ? -k_ : k_;  // velocity toward the target, in units of a
  const int32_t up = s + 1 > max_k ? max_k : s + 1;
  // Braking distances (only meaningful where they are used: up > 0, 0 <= s <= max_k).
  const uint32_t mu = static_cast<uint32_t>(up), ms = static_cast<uint32_t>(s);
  const uint64_t brake_up = static_cast<uint64_t>(a) * ((mu * (mu + 1u)) >> 1);
  const uint64_t brake_s = static_cast<uint64_t>(a) * ((ms * (ms + 1u)) >> 1);
  const bool hold_ok = ms <= static_cast<uint32_t>(max_k) && brake_s <= dist;  // 0 <= s <= max_k
  const int32_t slow = hold_ok ? s : s - 1;
  const int32_t next = (up > 0 && brake_up > dist) ? slow : up;
  if (next == 0 && dist < a && ms <= 1u) {
    pos_ = target_q32;  // residue below one acceleration step
    k_ = 0;
    return target_q32;
  }
  k_ = toward_negative ? -next : next;
  pos_ += static_cast<int64_t>(k_) * a;
  return pos_;
}

}  // namespace volcomp
