// The worn-machine profile: what a 30-year-old machining centre adds to its rigid-body geometry
// (lost motion, settling scatter, short-period screw error, thermal growth, cross-axis sag), each
// acting on the axes as the drives move them and each switchable. The models, the defaults and
// where they come from: docs/simulator.md §7.1. Lengths mm, errors µm, times minutes unless named.
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
  // An axis is at rest once its drive has made no step for this long (20 ms: slower than
  // 7.5 mm/min at 2.5 µm per step). The gaps between the steps of a slow axis along a contour are
  // not stops; the near-standstill where a contour reverses the axis is one.
  double scatter_standstill_ms = 20;

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
