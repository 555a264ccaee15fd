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

int64_t CorrectionLimiter::Step(int64_t target_q32) {
  const int64_t e = target_q32 - pos_;
  const int32_t dir = e < 0 ? -1 : 1;
  const uint64_t dist = static_cast<uint64_t>(e < 0 ? -e : e);
  const int32_t max_k = static_cast<int32_t>(params_.max_k);
  const int32_t s = k_ * dir;  // velocity toward the target, in units of a
  int32_t next = s + 1 > max_k ? max_k : s + 1;
  if (next > 0 && !CanStopWithin(static_cast<uint32_t>(next), dist)) {
    next = (s >= 0 && s <= max_k && CanStopWithin(static_cast<uint32_t>(s), dist)) ? s : s - 1;
  }
  if (next == 0 && dist < params_.accel_q32 && s >= 0 && s <= 1) {
    pos_ = target_q32;  // residue below one acceleration step
    k_ = 0;
    return pos_;
  }
  k_ = next * dir;
  pos_ += static_cast<int64_t>(k_) * params_.accel_q32;
  return pos_;
}

}  // namespace volcomp
