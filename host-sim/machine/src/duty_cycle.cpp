#include "volcomp/sim/duty_cycle.hpp"

namespace volcomp::sim {

double DutyCycle::duration_s() const {
  double t = 0;
  for (const DutySegment& s : segments) t += s.duration_s;
  return t;
}

ThermalLoad DutyCycle::LoadAt(double t_s) const {
  ThermalLoad load;
  load.ambient_C = start_ambient_C;
  double start = 0;
  for (const DutySegment& s : segments) {
    if (t_s < start + s.duration_s) {
      const double f = (t_s - start) / s.duration_s;
      load.spindle_fraction = s.spindle_fraction;
      load.x_speed_m_min = s.x_speed_m_min;
      load.ambient_C += f * (s.ambient_end_C - load.ambient_C);
      return load;
    }
    load.ambient_C = s.ambient_end_C;
    start += s.duration_s;
  }
  return load;
}

namespace {

void Add(DutyCycle* c, double minutes, double spindle, double x_m_min, double ambient_end_C) {
  c->segments.push_back({minutes * 60.0, spindle, x_m_min, ambient_end_C});
}

}  // namespace

DutyCycle CalibrationDutyCycle() {
  DutyCycle c;
  c.name = "calibration";
  c.start_ambient_C = 19.0;    // a cold machine in the morning shop
  Add(&c, 60, 0, 0, 21.0);     // standing while the shop's heating comes on (ambient alone)
  Add(&c, 90, 0, 5, 20.5);     // X traversing alone
  Add(&c, 150, 0.8, 5, 20.5);  // spindle at 80 % as well
  Add(&c, 120, 0, 0, 19.5);    // everything stopped: cooling while the shop cools
  return c;
}

DutyCycle VerificationDutyCycle() {
  DutyCycle c;
  c.name = "verification";
  c.start_ambient_C = 20.0;
  Add(&c, 25, 0.9, 6, 20.0);  // roughing
  Add(&c, 10, 0, 0, 20.0);    // tool change, measuring
  Add(&c, 40, 0.5, 3, 20.0);  // finishing
  Add(&c, 20, 0, 1, 20.0);    // setting up the next part
  Add(&c, 30, 1.0, 8, 20.0);  // heavy roughing
  Add(&c, 30, 0, 0, 23.0);    // pause; a door to a warmer hall: +3 K
  Add(&c, 35, 0.6, 4, 23.0);  // machining in the warmer shop
  Add(&c, 15, 0, 0, 23.0);
  Add(&c, 45, 0.3, 2, 23.0);  // light finishing
  Add(&c, 40, 0, 0, 23.0);    // end of the shift: standing
  return c;
}

}  // namespace volcomp::sim
