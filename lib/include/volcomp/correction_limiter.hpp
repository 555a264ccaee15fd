// Moves the applied correction toward its target within a velocity and an acceleration limit.
//
// State: position p (Q32.32 steps, int64) and velocity v = k * a, where a is the acceleration per
// tick squared (Q32) and k an integer in [-k_max, k_max]. Each tick k changes by at most one, so
// |dv| <= a and |v| <= k_max * a always hold: the step rate the correction adds never exceeds the
// configured rate, and its change never exceeds the configured acceleration. The largest k toward
// the target is taken for which braking a*k*(k+1)/2 still stops at the target, so a fixed target
// is reached without overshoot; a residue below one acceleration step is taken in one tick.
// Integer only, no division per tick. LimiterStepReference() (tests/reference,
// hot_path_reference.hpp) is the clear version; Step() decides identically.
#pragma once

#include <cstdint>

#include "volcomp/status.hpp"

namespace volcomp {

struct LimiterParams {
  uint32_t accel_q32 = 1;  // |dv| per tick, 2^-32 steps / tick^2, >= 1
  uint32_t max_k = 1;      // velocity limit = max_k * accel_q32 per tick, 1..65535
};

class CorrectionLimiter {
 public:
  using Params = LimiterParams;

  /// Converts limits in steps/s and steps/s^2 at `tick_hz`; kConfigInvalid when the acceleration
  /// rounds to zero, exceeds one step per tick^2, or allows no velocity at all.
  static Result<Params> MakeParams(uint32_t tick_hz,
                                   uint32_t max_rate_steps_s,
                                   uint32_t max_accel_steps_s2);

  explicit CorrectionLimiter(Params p = Params()) : params_(p) {}
  void set_params(Params p) { params_ = p; }
  /// Jumps to `position_q32` at rest (power-up: 0).
  void Reset(int64_t position_q32 = 0) {
    pos_ = position_q32;
    k_ = 0;
  }

  /// One tick toward `target_q32`; returns the new position.
  int64_t Step(int64_t target_q32);

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

}  // namespace volcomp
