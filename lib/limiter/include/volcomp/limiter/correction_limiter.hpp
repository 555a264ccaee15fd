// Moves the applied correction (Q32.32 steps) toward its target within a velocity and an
// acceleration limit, one Step() per limiter period: never faster than the rate, never a change of
// velocity above the acceleration, no overshoot of a fixed target. Integer only, no division per
// Step(); MakeParams() converts steps/s and steps/s^2 for the period (kConfigInvalid when they do
// not fit). The method and its reference: docs/control-path.md, "Correction limiter".
#pragma once

#include <cstdint>

#include "volcomp/base/interp_arith.hpp"
#include "volcomp/base/status.hpp"

namespace volcomp {

struct LimiterParams {
  uint32_t accel_q32 = 1;  // |dv| per step, 2^-32 steps / T^2 (T: the step period), >= 1
  uint32_t max_k = 1;      // velocity limit = max_k * accel_q32 per step, 1..65535
};

class CorrectionLimiter {
 public:
  using Params = LimiterParams;

  /// Converts limits in steps/s and steps/s^2 for a limiter stepped every `ticks_per_step` ticks
  /// of `tick_hz` (its step period T = ticks_per_step / tick_hz; the board's compensator steps at
  /// CompensationDivider(tick_hz)); kConfigInvalid when the acceleration rounds to zero, exceeds
  /// one step per T^2, or allows no velocity at all.
  static Result<Params> MakeParams(uint32_t tick_hz,
                                   uint32_t max_rate_steps_s,
                                   uint32_t max_accel_steps_s2,
                                   uint32_t ticks_per_step = 1);

  explicit CorrectionLimiter(Params p = Params()) : params_(p) {}
  void set_params(Params p) { params_ = p; }
  /// Takes limits `p` in the middle of a motion: the velocity carries over, re-expressed in the
  /// new acceleration unit as k * `k_scale_q30` / 2^30 (the old unit over the new, <= 1 when the
  /// new acceleration is at least the old), rounded toward minus infinity: the velocity changes by
  /// less than one new acceleration step, within the new limits (a velocity one step above the new
  /// rate limit is braked by Step()). Not on the per-step path (a direction switch).
  void SwitchParams(Params p, int32_t k_scale_q30) {
    params_ = p;
    k_ = static_cast<int32_t>(MulAddLong(0, k_, k_scale_q30) >> 30);  // one SMLAL
  }
  /// Jumps to `position_q32` at rest (power-up: 0).
  void Reset(int64_t position_q32 = 0) {
    pos_ = position_q32;
    k_ = 0;
  }

  /// One step period toward `target_q32`; returns the new position. Always inlined: the
  /// compensation run runs it inside its walk over the axes, without a call.
  inline int64_t Step(int64_t target_q32);

  /// True while the velocity is at its limit (|k| = max_k): the rate limit is in force.
  bool at_rate_limit() const { return static_cast<uint32_t>(k_ < 0 ? -k_ : k_) == params_.max_k; }
  int64_t position_q32() const { return pos_; }
  int32_t velocity_index() const { return k_; }
  bool at_rest() const { return k_ == 0; }
  const Params& params() const { return params_; }

 private:
  Params params_;
  int64_t pos_ = 0;
  int32_t k_ = 0;
};

// The same decisions as LimiterStepReference() (tests/reference/src/hot_path_reference.cpp),
// arranged for the Cortex-M4: both braking distances a * m(m+1)/2 the decision may need are formed
// up front (one MLA, one shift and one UMULL each; m <= max_k <= 65535 where they are used, so
// m(m+1) < 2^32) and the outcome is selected; the velocity direction is a sign flip instead of a
// multiply.
__attribute__((always_inline)) inline int64_t CorrectionLimiter::Step(int64_t target_q32) {
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
