// A duty cycle of hours on the worn machine's heat balance (issue 23 item 4): the bodies heat and
// cool under the cycle's loads, the machine deforms (Machine::SetThermalDeformation), the three
// sensors follow their surfaces, and at every check interval a laser reads the deviation at each
// check point of each axis, the way an ISO 230-3 drift test reads them: positions of 2 or more
// points per axis read repeatedly, the temperature channels logged with them.
//
// The deviation at a check point is the machine's own truth: where its tool point is with the
// drives at the point (the rigid-body errors, which do not change, plus the thermal deformation)
// against the point, along the axis. `correction_um` (optional) is what the board adds at that
// point at that moment: the deviation read is then that of the compensated machine.
//
// Units: s, mm, um, C; readings in 0.01 C as the channels take them.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "volcomp/model/vec3.hpp"
#include "volcomp/sim/duty_cycle.hpp"
#include "volcomp/sim/heat_balance.hpp"
#include "volcomp/sim/machine.hpp"
#include "volcomp/sim/thermal_sensors.hpp"

namespace volcomp::sim {

struct DriftCheckPoint {
  int axis = 0;      // the axis whose deviation is read (0 X, 1 Y, 2 Z)
  model::Vec3 q_mm;  // where the axes stand
};

struct DriftReading {
  double time_s = 0;
  int axis = 0;
  double position_mm = 0;  // the axis's position at the check point
  double deviation_um = 0;
  std::vector<int16_t> channels_cC;  // every sensor's reading at that moment
};

struct ThermalRunOptions {
  HeatBalanceParams machine;
  std::vector<ThermalSensorParams> sensors = {};  // empty: WornMachineSensors()
  std::vector<DriftCheckPoint> points;            // empty: DefaultDriftCheckPoints(machine)
  double check_interval_s = 300;
  double step_s = 1;  // the heat balance's and the sensors' step
  uint64_t seed = 1;
};

struct ThermalRun {
  std::string cycle;
  std::vector<std::string> channel_names;  // T_<name>_C order
  std::vector<DriftReading> readings;
  // The bodies' temperatures at every check (time, 4 bodies): the truth, for the report.
  std::vector<std::array<double, kThermalBodies + 1>> bodies_C;
};

/// Two points per linear axis, at 10 % and 90 % of its travel, the other axes mid-travel.
std::vector<DriftCheckPoint> DefaultDriftCheckPoints(const Machine& machine);

/// The correction the board applies at a check point: (axis, q_mm, the sensors' readings now) to
/// um along that axis. Empty: an uncompensated machine.
using ThermalCorrectionAt =
    std::function<double(int axis, const model::Vec3& q_mm, const std::vector<int16_t>& cC)>;

/// Runs `cycle` on `machine` (its rigid-body errors stay; its deformation is overwritten) from a
/// machine settled at the cycle's start ambient.
ThermalRun RunDutyCycle(Machine& machine,
                        const DutyCycle& cycle,
                        const ThermalRunOptions& options,
                        const ThermalCorrectionAt& correction = {});

/// Per axis the largest |drift| over the run: a reading's deviation less the same check point's
/// first reading, um (0 for an axis without readings).
std::array<double, 3> MaxDrift_um(const ThermalRun& run);

/// The drift test's CSV (docs/thermal.md "The PC tool": `volcomp evaluate thermal` and
/// `build thermal` read it): a test-conditions preamble, then
/// `time_s,axis,position_mm,deviation_um,T_<channel>_C...`.
std::string DriftTestCsv(const ThermalRun& run, const std::string& machine_name);

}  // namespace volcomp::sim
