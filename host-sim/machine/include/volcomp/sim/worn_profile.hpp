// The worn-machine profile: what a 30-year-old machining centre adds to its rigid-body geometry.
// Each source can be switched off; the defaults and where they come from are in
// docs/simulator.md ("The worn machine"). Lengths mm, errors µm, times minutes unless named.
//
// Every source acts on the axes as the drives move them (the drive counts, i.e. the positions the
// board outputs), so the whole chain CNC -> board -> drives -> machine -> instruments is exercised:
//   lost motion      a dead band between the drive (screw) and the carriage: after a reversal the
//                    drive travels `lost_motion_um` before the carriage follows (play operator);
//   scatter          each time an axis comes to rest its carriage settles at a new random offset,
//                    Gaussian with `sigma_um` (repeatability);
//   screw error      short-period lead error of the screw, A·sin(2π·d/P + φ) of the drive
//                    position d (once per revolution of a screw of lead P);
//   thermal growth   first-order warm-up of the spindle head (the tool point moves toward the
//                    table, -z) and of the X screw (the carriage runs ahead by α·ΔT·(x − x_fixed)),
//                    from power-up `warmup_min` before the demo starts;
//   cross-axis sag   vertical straightness of X that depends on Y (a non-rigid deflection no
//                    21-parameter table can represent): the tool point rises relative to the
//                    workpiece by S·((x − x_c)/(X/2))²·((y − y_min)/Y)².
#pragma once

#include <array>
#include <cstdint>

namespace volcomp::sim {

struct WornMachineProfile {
  bool lost_motion = false;
  std::array<double, 3> lost_motion_um = {15, 20, 8};  // play: the drive travels it after a
                                                       // reversal before the carriage follows

  bool scatter = false;
  std::array<double, 3> scatter_sigma_um = {0.7, 0.8, 0.6};  // a new offset at every rest

  bool screw_error = false;  // A·sin(2π·d/P + φ) of the drive position d
  double screw_period_mm = 5;
  std::array<double, 3> screw_amplitude_um = {1.5, 1.5, 1.0};
  std::array<double, 3> screw_phase_rad = {0.4, 2.1, 4.0};

  bool thermal = false;
  double warmup_min = 60;         // the machine ran this long before the demo's time 0
  double spindle_growth_um = 30;  // final growth of the spindle head toward the table (-z)
  double spindle_tau_min = 60;    // its time constant
  double screw_heating_K = 4;     // final temperature rise of the X screw
  double screw_tau_min = 60;
  double screw_expansion_ppm_per_K = 11.5;  // steel
  double screw_fixed_end_mm = 0;            // X position of the screw's fixed bearing

  bool cross_axis_sag = false;
  double sag_um = 12;  // S: the tool rises by S·((x − x_c)/(X/2))²·((y − y_min)/Y)²

  uint64_t seed = 1;  // the scatter's random numbers

  bool any() const { return lost_motion || scatter || screw_error || thermal || cross_axis_sag; }
};

/// Every source on, with its default values.
WornMachineProfile DefaultWornProfile(uint64_t seed);

}  // namespace volcomp::sim
