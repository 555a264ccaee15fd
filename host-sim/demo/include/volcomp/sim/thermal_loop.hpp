// A duty cycle of hours with the real firmware in the loop (issue 23 item 4, docs/simulator.md
// 7.6): the heat balance deforms the machine, the three sensors' readings go to the board over CAN
// as a PLC sends them (RPDO2, 0x2150:1-4, every `reading_period_s`; the PLC is the NMT master and
// starts the node: PDOs run in Operational only), the board's main loop supervises the channels and
// moves the thermal correction of the active image at its slew limit, its compensation run adds
// that to the drives, and at every check the CNC moves to each check point and the laser reads the
// deviation of the tool point there along the axis.
//
// How hours fit into minutes: the board runs at a lower control tick (`tick_hz`, 2 kHz by default
// against the demo's 50 kHz) and main-loop rate (`poll_period_ns`); the thermal correction's
// period (100 ms) and its slew limit are unchanged, and the check moves run at a feed the slower
// tick carries without overruns. The heat balance and the sensors step every reading period.
//
// Faults can be injected into a sensor (open circuit, stuck) for a time; the result says when the
// board flagged the channel (0x2151 state, from the board), and whether the correction held.
// Units: s, mm, um, C.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/sim/duty_cycle.hpp"
#include "volcomp/sim/thermal_run.hpp"

namespace volcomp::sim {

struct SensorFaultInjection {
  int sensor = 0;  // index into the run's sensors (= board channel)
  SensorFault kind = SensorFault::kOpenCircuit;
  double at_s = 0;    // from the cycle's start
  double for_s = 30;  // then the sensor works again
};

struct ThermalLoopOptions {
  DutyCycle cycle;
  ThermalRunOptions run;       // the heat balance, sensors, check points, check interval
  std::vector<uint8_t> image;  // the table image with its THERMAL section to upload and activate
  std::string model_spec = "s500";
  /// The machine's other wear (worn_profile.hpp); its closed-form `thermal` must stay off: the
  /// heat balance is the thermal state here.
  WornMachineProfile wear;
  uint32_t tick_hz = 2000;
  uint64_t poll_period_ns = 1000000;  // the main loop every 1 ms
  double reading_period_s = 0.1;      // the PLC writes every channel at 10 Hz
  uint8_t stuck_readings = 10;        // the channels' frozen-source check: 1 s at 10 Hz
  double check_feed_mm_s = 20;        // moves between check points
  double settle_s = 0.3;              // at rest before the laser reads
  // Each check point is read as the mean of this many approaches, each from approach_mm below on
  // every axis (one direction, as a drift test repeats its readings: the lost motion is taken up
  // the same way every time, the settling scatter averages).
  int approaches = 10;
  double approach_mm = 5;
  std::vector<SensorFaultInjection> faults;
};

struct FaultOutcome {
  SensorFaultInjection injected;
  double detected_after_s = -1;  // -1: never flagged while it lasted
  // Largest change of the applied correction on any axis between the flag and the fault's end
  // (the hold: 0 while the hold time lasts), um.
  double change_while_held_um = 0;
};

struct ThermalLoopResult {
  ThermalRun run;  // the deviations the laser read with the board compensating
  // Fastest change of the applied correction at each axis's check points, sampled every second
  // (the image's slew limit bounds it), um/s.
  double max_rate_um_s[3] = {0, 0, 0};
  std::vector<FaultOutcome> faults;
  uint64_t ticks = 0;
  uint64_t lost_steps = 0;  // the step audit at rest (must stay 0)
  uint32_t overruns = 0;
  double wall_s = 0;
};

/// Runs the cycle. Fails when the board does not start, home, take or activate the image, or a
/// check move does not finish (the reason says which).
Expected<ThermalLoopResult> RunThermalLoop(const ThermalLoopOptions& options, std::ostream& log);

}  // namespace volcomp::sim
