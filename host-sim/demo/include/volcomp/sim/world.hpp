// The simulated installation: machine + CNC + the real firmware (BoardApp on the mock HAL) + the
// drives (DriveModel checkers) + the CAN bus with the PC's endpoint, advanced together from event
// to event in virtual time (ns), with the step audit (zero lost steps, drive = board output every
// tick) and the latency meter (docs/simulator.md "Virtual time", "Drives and the step audit").
// The PC's SDO client (tools/canopen) reaches the board through SdoLink(), a blocking FrameLink
// whose receive() advances the whole simulation. Thread-safety: none (one thread).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>

#include "volcomp/canopen_client/sdo_runner.hpp"
#include "volcomp/config/board_settings.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/vec3.hpp"
#include "volcomp/sim/cnc.hpp"
#include "volcomp/sim/latency_meter.hpp"
#include "volcomp/sim/machine.hpp"
#include "volcomp/sim/sim_bus.hpp"
#include "volcomp/sim/simulated_board.hpp"

namespace volcomp::sim {

struct WorldOptions {
  MachineOptions machine;
  CncConfig cnc;        // step_mm and home_position_steps are taken from the machine and the board
  BoardSettings board;  // axes X, Y, Z; home positions are set to the switch positions
  uint32_t can_bitrate = 1000000;
  uint64_t poll_period_ns = 100000;
};

struct StepAudit {
  uint64_t rest_checks = 0;
  uint64_t lost_steps = 0;       // sum over rest checks of |drive - (CNC steps + correction)|
  uint64_t owed_at_rest = 0;     // sum over rest checks of |backlog|
  uint64_t tick_mismatches = 0;  // ticks where a drive's count differs from the board's output
  uint64_t timing_violations = 0;
  uint32_t overruns = 0;  // ticks whose backlog exceeded one tick's pulse capacity
  uint32_t max_backlog = 0;
  uint64_t input_steps = 0;
  uint64_t output_steps = 0;
  uint64_t ticks = 0;
};

class World final : private StepSink {
 public:
  /// The installation; fails when the machine refuses its options (Machine::Create).
  static Expected<std::unique_ptr<World>> Create(const WorldOptions& options);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Starts the firmware. Fails if the board rejects its configuration.
  Outcome Start();

  uint64_t now_ns() const { return now_ns_; }
  uint64_t tick_ns() const { return tick_ns_; }
  /// Runs until the CNC has executed everything queued; false if `limit_ns` more virtual time
  /// passed first.
  bool RunUntilCncIdle(uint64_t limit_ns);
  void RunFor(uint64_t duration_ns);
  /// The installation's clocked side (a PLC writing frames, a heat balance): `fn(now_ns)` is called
  /// after the first event at or past every multiple of `period_ns` from now, whichever call runs
  /// the world (RunFor, RunUntilCncIdle, a blocking SDO transfer). nullptr: none.
  void SetClocked(uint64_t period_ns, std::function<void(uint64_t now_ns)> fn);

  /// Blocking frame link for canopen_client::RunToCompletion & co.
  const canopen_client::FrameLink& SdoLink() const { return link_; }

  Machine& machine() { return *machine_; }
  Cnc& cnc() { return *cnc_; }
  SimulatedBoard& board() { return *board_; }
  SimBus& bus() { return bus_; }
  const LatencyMeter& latency() const { return latency_; }
  LatencyMeter& latency() { return latency_; }
  const WorldOptions& options() const { return options_; }
  uint8_t node_id() const { return options_.board.node_id; }

  /// Output steps counted by each drive since power-up.
  std::array<int64_t, 3> DriveSteps() const;
  /// Axis positions in the machine model's frame at the drives' positions (mm).
  model::Vec3 AxisPositions_mm() const;
  /// The CNC's commanded point (its machine coordinates, mm).
  model::Vec3 CommandedPoint_mm() const;
  /// Compares drives with input + correction (call at rest). Returns false on any difference.
  bool CheckAtRest();
  StepAudit Audit() const;

 private:
  World(const WorldOptions& options, Machine machine);
  void OnStep(int axis, uint64_t t_ns, int dir) override;
  void StepOnce(uint64_t limit_ns);
  void StepEvent(uint64_t limit_ns);
  void AfterTick(uint64_t t_ns);

  WorldOptions options_;
  SimBus bus_;
  std::unique_ptr<SimulatedBoard> board_;
  Endpoint* pc_ = nullptr;
  std::unique_ptr<Machine> machine_;
  std::unique_ptr<Cnc> cnc_;
  LatencyMeter latency_;
  canopen_client::FrameLink link_;
  uint64_t tick_ns_ = 20000;
  uint64_t now_ns_ = 0;
  uint64_t pulse_clock_hz_ = 1000000000;
  std::array<int64_t, 3> output_ = {0, 0, 0};  // pulses expanded from the plans
  StepAudit audit_;
  std::function<void(uint64_t)> clocked_;
  uint64_t clocked_period_ns_ = 0;
  uint64_t next_clocked_ns_ = 0;
};

/// Board settings for a machine: three linear axes at the machine's step lengths, default
/// drive timing and limits, home position = the home switch position (in steps).
BoardSettings BoardSettingsFor(const Machine& machine);

}  // namespace volcomp::sim
