// Per-axis output step planning: each tick, the pulses (a PulsePlan, times in pulse-clock units
// from the tick start) that move the output toward its target under the drive's timing rules
// (pulse width, step space, direction setup and hold, maximum rate), across tick boundaries; what
// does not fit stays owed, so no step is lost or invented. PlanTick(): no division, O(1).
// Configure(): control context between ticks; kConfigInvalid when the tick cannot carry one pulse
// or a time is out of range. Rules and arithmetic: docs/control-path.md, "Step generator".
#pragma once

#include <cstdint>

#include "volcomp/base/interp_arith.hpp"
#include "volcomp/base/invariant_divider.hpp"
#include "volcomp/base/status.hpp"
#include "volcomp/config/board_config.hpp"

namespace volcomp {

struct PulsePlan {
  uint32_t count = 0;       // pulses this tick
  bool negative = false;    // direction of these pulses (and the direction line level after)
  bool dir_change = false;  // the direction line changes this tick, at dir_edge
  uint32_t dir_edge = 0;    // pulse-clock units after the tick start
  uint32_t first_rise = 0;  // first rising edge, pulse-clock units after the tick start
  uint32_t period = 0;      // rise-to-rise, pulse-clock units
  uint32_t width = 0;       // high time, pulse-clock units
};

/// A drive's timing in pulse-clock units, as the generators use it.
struct PulseTiming {
  uint32_t tick = 0;          // tick length
  uint32_t min_period = 1;    // minimum rise-to-rise: max(width + space, ceil(clock / max rate))
  uint32_t width = 0;         // high time (0 for quadrature: a step is a single edge)
  uint32_t setup = 0;         // direction edge to next rising edge
  uint32_t hold = 0;          // last falling edge to direction edge
  uint32_t max_per_tick = 0;  // pulses a tick can carry, at most StepGenerator::kMaxPulsesPerTick

  /// Converts `axis`'s drive timing at `tick_hz` (times rounded up to whole clock units).
  /// kConfigInvalid if the tick cannot carry even one pulse, or a time is 2^29 clock units or
  /// more (over 0.5 s at 1 GHz; StepGenerator's int32 time arithmetic needs the headroom).
  static Result<PulseTiming> FromDrive(const AxisConfig& axis,
                                       uint32_t tick_hz,
                                       uint32_t pulse_clock_hz);
};

class StepGenerator {
 public:
  /// Most pulses one tick may carry (bounds the reciprocal table).
  static constexpr uint32_t kMaxPulsesPerTick = 256;

  /// Converts the axis's drive timing to pulse-clock units. kConfigInvalid if the tick cannot
  /// carry even one pulse, a direction change never fits, or a time exceeds the int32 time
  /// arithmetic (tick, setup or hold of 2^29 pulse-clock units or more: over 0.5 s at 1 GHz).
  Status Configure(const AxisConfig& axis, uint32_t tick_hz, uint32_t pulse_clock_hz);

  /// Plans the pulses of the next tick toward `target_steps` (wrap-safe int32 positions).
  PulsePlan Plan(int32_t target_steps) {
    PulsePlan plan;
    PlanTick(target_steps, &plan);
    return plan;
  }
  /// Plan() writing into `plan`; returns the steps still owed afterwards (|backlog|). Always
  /// inlined: the tick's output stage runs it inside its walk over the axes, without a call.
  inline uint32_t PlanTick(int32_t target_steps, PulsePlan* plan);

  /// Output position after all planned pulses.
  int32_t position() const { return position_; }
  /// Sets the output position without pulses (power-up).
  void Reset(int32_t position_steps) { position_ = position_steps; }
  /// Pulses still owed after the last Plan().
  int32_t backlog(int32_t target_steps) const {
    return static_cast<int32_t>(static_cast<uint32_t>(target_steps) -
                                static_cast<uint32_t>(position_));
  }
  uint32_t tick_length() const { return tick_; }
  uint32_t min_period() const { return min_period_; }
  /// Largest pulse count of a tick without a direction change.
  uint32_t max_pulses_per_tick() const { return max_per_tick_; }

 private:
  // Times relative to the current tick start, never below kFarPast (far enough that no rule can
  // reach into the present: every time constant is below 2^29).
  static constexpr int32_t kFarPast = -(int32_t{1} << 30);

  // State, then the constants (the hot path reads them with short offsets).
  int32_t position_ = 0;
  int32_t last_rise_ = kFarPast;
  int32_t last_fall_ = kFarPast;
  bool negative_ = false;
  // PulseTiming's fields, copied here so the hot path reads them right after the state.
  uint32_t tick_ = 0;
  uint32_t min_period_ = 1;
  uint32_t width_ = 0;
  uint32_t setup_ = 0;
  uint32_t hold_ = 0;
  uint32_t max_per_tick_ = 0;
  InvariantDivider by_min_period_;
  const uint32_t* reciprocals_ = nullptr;  // the shared table (step_generator.cpp)
};

namespace step_timing {
// max(t, -2^30) for t >= -2^31 + 2^29 (one SSAT #31).
__attribute__((always_inline)) inline int32_t FloorFarPast(int32_t t) {
#if defined(__ARM_FEATURE_SAT)
  return __ssat(t, 31);
#else
  return t < -(int32_t{1} << 30) ? -(int32_t{1} << 30) : t;
#endif
}
}  // namespace step_timing

__attribute__((always_inline)) inline uint32_t StepGenerator::PlanTick(int32_t target_steps,
                                                                       PulsePlan* out) {
  const int32_t owed =
      static_cast<int32_t>(static_cast<uint32_t>(target_steps) - static_cast<uint32_t>(position_));
  const int32_t tick = static_cast<int32_t>(tick_);
  int32_t rise = last_rise_, fall = last_fall_;
  bool negative = negative_, dir_change = false;
  uint32_t count = 0, dir_edge = 0, first_rise = 0, period = 0, left = 0;
  if (owed != 0) {
    const bool want_negative = owed < 0;
    const uint32_t steps =
        want_negative ? 0u - static_cast<uint32_t>(owed) : static_cast<uint32_t>(owed);
    left = steps;
    int32_t earliest = rise + static_cast<int32_t>(min_period_);
    bool may_pulse = true;
    if (want_negative != negative) {
      int32_t edge = fall + static_cast<int32_t>(hold_);
      edge = edge < 0 ? 0 : edge;
      if (edge < tick) {
        dir_change = true;
        dir_edge = static_cast<uint32_t>(edge);
        negative = want_negative;
        const int32_t ready = edge + static_cast<int32_t>(setup_);
        earliest = ready > earliest ? ready : earliest;
      } else {
        may_pulse = false;  // the hold time runs into the next tick
      }
    }
    earliest = earliest < 0 ? 0 : earliest;
    if (may_pulse && earliest < tick) {
      const uint32_t window = tick_ - static_cast<uint32_t>(earliest);
      // The first pulse sits at `earliest`; n pulses need (n - 1) periods, all rises inside.
      uint32_t fit = by_min_period_.Divide(window - 1u).quotient + 1u;
      fit = fit > max_per_tick_ ? max_per_tick_ : fit;
      count = steps < fit ? steps : fit;
      period = MulHiU32(window, reciprocals_[count]);
      period = period < min_period_ ? min_period_ : period;
      first_rise = static_cast<uint32_t>(earliest);
      rise = earliest + static_cast<int32_t>((count - 1u) * period);
      fall = rise + static_cast<int32_t>(width_);
      position_ = static_cast<int32_t>(static_cast<uint32_t>(position_) +
                                       (want_negative ? 0u - count : count));
      left = steps - count;
    }
  }
  negative_ = negative;
  // Move the time origin to the next tick start.
  last_rise_ = step_timing::FloorFarPast(rise - tick);
  last_fall_ = step_timing::FloorFarPast(fall - tick);
  out->count = count;
  out->negative = negative;
  out->dir_change = dir_change;
  out->dir_edge = dir_edge;
  out->first_rise = first_rise;
  out->period = period;
  out->width = width_;
  return left;
}

}  // namespace volcomp
