// Duty cycles of the worn machine (issue 23 item 4): what heats it, segment by segment, over
// hours. Two are built in, deliberately different, so that a model fitted on one is checked on
// the other (docs/simulator.md "Heat balance"):
//   calibration   the drift test (in the manner of ISO 230-3): the X axis traversing, then the
//                 spindle running as well, then everything stopped to cool; the shop warms 1.5 K
//                 over the morning.
//   verification  machining: bursts of spindle and X at different speeds, stops, a long pause,
//                 and an ambient step of 3 K (a door opened onto a warmer hall).
// Within a segment the spindle fraction and the X speed are constant and the ambient temperature
// moves linearly from where the segment before ended (the cycle's start_ambient_C for the first)
// to the segment's ambient_end_C. Units: s, m/min, C.
#pragma once

#include <string>
#include <vector>

#include "volcomp/sim/heat_balance.hpp"

namespace volcomp::sim {

struct DutySegment {
  double duration_s = 0;
  double spindle_fraction = 0;
  double x_speed_m_min = 0;
  double ambient_end_C = 20;
};

struct DutyCycle {
  std::string name;
  double start_ambient_C = 20;  // the machine starts settled at this temperature (cold)
  std::vector<DutySegment> segments;

  double duration_s() const;
  /// The load at time `t_s` from the cycle's start (after the end: everything stopped at the last
  /// segment's ambient).
  ThermalLoad LoadAt(double t_s) const;
};

DutyCycle CalibrationDutyCycle();
DutyCycle VerificationDutyCycle();

}  // namespace volcomp::sim
