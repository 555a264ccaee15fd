// The simulated CNC controller: executes moves, dwells and homing cycles and emits step pulses
// for three axes in virtual time (nanoseconds).
//
// Step generation: a linear move from A to B (steps) follows a rest-to-rest trapezoidal profile
// along the straight path (TrapezoidProfile); axis a makes |B_a - A_a| steps, step k at the time
// the path position reaches k/n of the path (so the axis position rounds down to whole steps, like
// a DDA). Each step's exact time (ns) goes to the StepSink, which plays the part of the board's
// hardware input counter: the count latched at a tick is the number of steps whose time is <= the
// tick's time. Feed and rapid speeds are capped so that no axis exceeds `max_step_rate_hz`
// (1 MHz default), acceleration is `accel_mm_s2` along the path, and every move ends at rest
// (exact stop, G61).
//
// Homing (one block for any set of axes, in parallel): jog toward the switch at home_fast_mm_s,
// stop when the switch closes, pause, back off until it opens plus home_backoff_mm, approach again
// at home_slow_mm_s and stop on the step that closes it; that position becomes
// home_position_steps in the CNC's machine coordinates. The switch is sampled at every
// AdvanceTo() (every tick/poll of the simulation); jogs start and stop without ramps (they are
// slow).
//
// Coordinates: count(a) = net steps emitted since power-up; position(a) = count + offset set by
// homing (before homing: the count itself).
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>

#include "volcomp/sim/gcode.hpp"
#include "volcomp/sim/trapezoid.hpp"

namespace volcomp::sim {

struct CncConfig {
  std::array<double, 3> step_mm = {0.001, 0.001, 0.001};
  double max_step_rate_hz = 1e6;  // per axis
  double accel_mm_s2 = 10000;     // path acceleration of moves
  std::array<int64_t, 3> home_position_steps = {0, 0, 0};
  double home_fast_mm_s = 20;
  double home_slow_mm_s = 0.1;
  double home_backoff_mm = 0.5;
  double home_pause_s = 0.02;
};

/// Receives every step the CNC emits, in time order per axis.
class StepSink {
 public:
  virtual void OnStep(int axis, uint64_t t_ns, int dir) = 0;

 protected:
  ~StepSink() = default;
};

class Cnc {
 public:
  using SwitchReader = std::function<bool(int axis)>;
  using DwellHandler = std::function<void(uint64_t end_ns)>;

  /// Preconditions: every step length, the step rate and the acceleration > 0.
  Cnc(const CncConfig& config, StepSink* sink, SwitchReader home_switch);
  ~Cnc();

  /// Queue a rapid (G0) or feed (G1, `feed_mm_s` > 0) move to a position in machine steps.
  void QueueRapid(const std::array<int64_t, 3>& target_steps);
  void QueueLinear(const std::array<int64_t, 3>& target_steps, double feed_mm_s);
  /// Precondition: seconds >= 0.
  void QueueDwell(double seconds);
  /// Homes the axes in `mask` (bit a = axis a) together: jog toward the switch at
  /// home_fast_mm_s until it closes, pause, back off until it opens plus home_backoff_mm,
  /// approach at home_slow_mm_s and stop on the step that closes it, which becomes
  /// home_position_steps. The switch is read at every AdvanceTo(); jogs have no ramps.
  void QueueHome(uint8_t mask);
  /// Queues a parsed G-code program (coordinates in mm of the machine frame).
  void QueueProgram(const Program& program);
  /// Called at the end of every dwell (G4): the simulator's cue for a measurement.
  void set_dwell_handler(DwellHandler handler) { on_dwell_ = std::move(handler); }

  /// Executes everything up to virtual time `t_ns` (non-decreasing).
  void AdvanceTo(uint64_t t_ns);
  bool idle() const { return !active_ && queue_.empty(); }

  /// Net steps emitted on `axis` since power-up.
  int64_t count(int axis) const { return count_[static_cast<size_t>(axis)]; }
  /// The CNC's machine coordinate (steps): count + the offset homing set (the count before).
  int64_t position(int axis) const {
    return count_[static_cast<size_t>(axis)] + offset_[static_cast<size_t>(axis)];
  }
  bool homed(int axis) const { return homed_[static_cast<size_t>(axis)]; }
  uint64_t steps_emitted() const { return steps_; }
  /// Highest step rate of any move planned so far (Hz, per axis).
  double peak_step_rate_hz() const { return peak_rate_hz_; }
  /// Rapid speed along `delta_steps` (mm/s): the fastest that keeps every axis within the rate.
  double RapidSpeed_mm_s(const std::array<int64_t, 3>& delta_steps) const;
  const CncConfig& config() const { return config_; }

 private:
  struct Block;
  struct Move;
  struct Homing;

  void Start(const Block& b, uint64_t t0);
  bool RunMove(uint64_t t_ns);    // true when finished (end_ns_ set)
  bool RunHoming(uint64_t t_ns);  // likewise
  void Emit(int axis, uint64_t t, int dir);

  CncConfig config_;
  StepSink* sink_;
  SwitchReader switch_;
  DwellHandler on_dwell_;
  std::deque<Block> queue_;
  std::unique_ptr<Block> active_;
  std::unique_ptr<Move> move_;
  std::unique_ptr<Homing> homing_;
  uint64_t dwell_end_ns_ = 0;
  uint64_t cursor_ns_ = 0;  // end of the last finished block
  uint64_t now_ns_ = 0;     // last AdvanceTo time
  std::array<int64_t, 3> count_ = {0, 0, 0};
  std::array<int64_t, 3> offset_ = {0, 0, 0};
  std::array<bool, 3> homed_ = {false, false, false};
  uint64_t steps_ = 0;
  double peak_rate_hz_ = 0;
};

}  // namespace volcomp::sim
