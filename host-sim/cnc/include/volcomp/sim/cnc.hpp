// The simulated CNC controller: moves, dwells and homing cycles for three axes, emitted as step
// times in virtual time (ns) to a StepSink, which plays the board's hardware input counter (the
// count a tick latches is the number of steps whose time is <= the tick's). Moves follow a
// rest-to-rest trapezoid along the straight path with no axis above `max_step_rate_hz`; an arc
// (G2/G3) and the feed moves joined to it tangentially (within 1 degree, same feed) run as one
// move with one trapezoid over the chain (PathMotion), at most sqrt(accel * r) on an arc; other
// junctions stop (exact stop). Homing stops on the step that closes the switch
// (docs/simulator.md "CNC and the input counter").
// Lengths mm, speeds mm/s, positions in steps. Thread-safety: none (the simulation's thread).
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
  /// What the CNC executes at the last AdvanceTo().
  enum class Activity { kIdle, kRapid, kFeed, kDwell, kHome };
  Activity activity() const;
  /// The program line of the block being executed at the last AdvanceTo() (0: none, or a block
  /// not from a program).
  int active_line() const;
  /// The path of the move being executed (the segment of a chain it is on), if any.
  std::optional<PathSegment> active_segment() const;
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
  struct Chain;

  void Start(const Block& b, uint64_t t0);
  bool StartChain(const Block& b, uint64_t t0);  // true when `b` runs as a PathMotion
  std::array<int64_t, 3> TargetOf(const Block& b, const std::array<int64_t, 3>& from) const;
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
  std::unique_ptr<Chain> chain_;
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
