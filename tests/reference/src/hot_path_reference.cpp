// The clear reference versions of the optimised tick routines (see hot_path_reference.hpp).
#include "volcomp/reference/hot_path_reference.hpp"

namespace volcomp {
namespace {

bool CanStopWithin(const LimiterParams& p, uint32_t m, uint64_t distance_q32) {
  return static_cast<uint64_t>(p.accel_q32) * (static_cast<uint64_t>(m) * (m + 1u) / 2u) <=
         distance_q32;
}

}  // namespace

Status StepGeneratorReference::Configure(const AxisConfig& axis,
                                         uint32_t tick_hz,
                                         uint32_t pulse_clock_hz) {
  const Result<PulseTiming> t = PulseTiming::FromDrive(axis, tick_hz, pulse_clock_hz);
  if (!t.ok()) return t.error();
  t_ = *t;
  return Status::Ok();
}

PulsePlan StepGeneratorReference::Plan(int32_t target_steps) {
  PulsePlan plan;
  plan.width = t_.width;
  const int32_t owed =
      static_cast<int32_t>(static_cast<uint32_t>(target_steps) - static_cast<uint32_t>(position_));
  const bool want_negative = owed < 0;
  const uint32_t steps = static_cast<uint32_t>(want_negative ? -static_cast<int64_t>(owed) : owed);
  int64_t earliest = last_rise_ + t_.min_period;
  plan.negative = negative_;
  if (steps != 0 && want_negative != negative_) {
    int64_t edge = last_fall_ + t_.hold;
    if (edge < 0) edge = 0;
    if (edge < t_.tick) {  // otherwise wait: the hold time runs into the next tick
      plan.dir_change = true;
      plan.dir_edge = static_cast<uint32_t>(edge);
      plan.negative = negative_ = want_negative;
      if (edge + t_.setup > earliest) earliest = edge + t_.setup;
    } else {
      earliest = t_.tick;  // no pulses this tick
    }
  }
  if (earliest < 0) earliest = 0;
  if (steps != 0 && plan.negative == want_negative && earliest < t_.tick) {
    const uint32_t window = t_.tick - static_cast<uint32_t>(earliest);
    // The first pulse sits at `earliest`; n pulses need (n - 1) periods, all rises inside the tick.
    uint32_t fit = (window - 1u) / t_.min_period + 1u;
    if (fit > t_.max_per_tick) fit = t_.max_per_tick;
    const uint32_t n = steps < fit ? steps : fit;
    uint32_t period =
        static_cast<uint32_t>((static_cast<uint64_t>(window) * (0xFFFFFFFFu / n)) >> 32);
    if (period < t_.min_period) period = t_.min_period;
    plan.count = n;
    plan.first_rise = static_cast<uint32_t>(earliest);
    plan.period = period;
    last_rise_ = earliest + static_cast<int64_t>(n - 1) * period;
    last_fall_ = last_rise_ + t_.width;
    position_ =
        static_cast<int32_t>(static_cast<uint32_t>(position_) +
                             (want_negative ? static_cast<uint32_t>(-static_cast<int64_t>(n)) : n));
  }
  // Move the time origin to the next tick start; keep far-past values bounded.
  last_rise_ -= t_.tick;
  last_fall_ -= t_.tick;
  if (last_rise_ < -(int64_t{1} << 40)) last_rise_ = -(int64_t{1} << 40);
  if (last_fall_ < -(int64_t{1} << 40)) last_fall_ = -(int64_t{1} << 40);
  return plan;
}

int64_t LimiterStepReference(const LimiterParams& p,
                             int64_t& pos_q32,
                             int32_t& k,
                             int64_t target_q32) {
  const int64_t e = target_q32 - pos_q32;
  const int32_t dir = e < 0 ? -1 : 1;
  const uint64_t dist = static_cast<uint64_t>(e < 0 ? -e : e);
  const int32_t max_k = static_cast<int32_t>(p.max_k);
  const int32_t s = k * dir;  // velocity toward the target, in units of a
  int32_t next = s + 1 > max_k ? max_k : s + 1;
  if (next > 0 && !CanStopWithin(p, static_cast<uint32_t>(next), dist)) {
    next = (s >= 0 && s <= max_k && CanStopWithin(p, static_cast<uint32_t>(s), dist)) ? s : s - 1;
  }
  if (next == 0 && dist < p.accel_q32 && s >= 0 && s <= 1) {
    pos_q32 = target_q32;  // residue below one acceleration step
    k = 0;
    return pos_q32;
  }
  k = next * dir;
  pos_q32 += static_cast<int64_t>(k) * p.accel_q32;
  return pos_q32;
}

}  // namespace volcomp
