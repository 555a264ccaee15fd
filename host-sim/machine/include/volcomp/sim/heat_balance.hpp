// The worn machine's thermal state as a heat balance (issue 23 item 4; docs/simulator.md "Heat
// balance"): four lumped bodies that store heat, exchange it with each other and with the shop's
// air, and are heated by the spindle's running and the X axis's motion. Their temperatures deform
// the machine; what the board's sensors see is a separate model (thermal_sensors.hpp): the
// sensors never see this state directly.
//
//   body        heated by                       deforms
//   spindle     the spindle's losses (bearings, the spindle cartridge grows the tool toward
//               motor) at its running fraction  the table (-z) over quill_mm
//   head        the spindle, by conduction      the head casting: -z over head_mm, +y over
//                                               head_y_mm (the spindle sits in front of the
//                                               column; the bore's wall, bore_wall_share of that
//                                               path, at the cartridge's temperature)
//   x_screw     nut and bearing friction,       the X screw: the carriage runs ahead by
//               proportional to the X speed     alpha * dT * (x - screw_fixed_end_mm)
//   structure   the head, by conduction; the    column and bed: the head rises (+z) over
//               shop's air                      column_mm (the column above the table surface)
//
// Each body i:  C_i dT_i/dt = P_i - sum_j G_ij (T_i - T_j) - G_i,air (T_i - T_air)
// integrated with Heun's method (second order) in sub-steps of at most max_substep_s, far below
// every body's time constant C/G (minutes to hours). Deformations are relative to every body at
// reference_C (the state the geometric table was measured in). Units: temperatures C, time s,
// heat J, power W, capacities J/K, conductances W/K, lengths mm, deformations um.
//
// This is the simulator's own formulation: the table builder's model (thermal_model.hpp: offsets
// and slopes linear in the sensors' readings) is fitted to what it produces, never used by it.
#pragma once

#include <array>

#include "volcomp/model/vec3.hpp"

namespace volcomp::sim {

enum class ThermalBody { kSpindle = 0, kHead = 1, kXScrew = 2, kStructure = 3 };
inline constexpr int kThermalBodies = 4;

/// What heats the machine at one moment (a duty cycle's segment, duty_cycle.hpp).
struct ThermalLoad {
  double spindle_fraction = 0;  // 0 (stopped) .. 1 (full speed): the losses scale with it
  double x_speed_m_min = 0;     // the X axis's mean speed (back and forth), m/min
  double ambient_C = 20;        // the shop's air
};

struct HeatBalanceParams {
  std::array<double, kThermalBodies> capacity_J_K = {40e3, 250e3, 15e3, 3e6};
  // Conductance of each body to the air, W/K.
  std::array<double, kThermalBodies> to_air_W_K = {4, 18, 5, 150};
  double spindle_to_head_W_K = 60;
  double head_to_structure_W_K = 6;
  double spindle_power_W = 600;   // the spindle's losses at full speed
  double screw_W_per_m_min = 6;   // friction heat per m/min of X speed
  double alpha_per_K = 11.5e-6;   // steel / cast iron
  double quill_mm = 120;          // spindle cartridge, nose to its fixed bearing
  double head_mm = 300;           // head casting under the spindle's mounting
  double head_y_mm = 150;         // spindle axis in front of the head's fixed face
  double bore_wall_share = 0.3;   // of head_y_mm: the bore's wall, at the cartridge's rise
  double column_mm = 250;         // column height above the table surface
  double screw_fixed_end_mm = 0;  // X position of the screw's fixed bearing
  double reference_C = 20;        // every body at this temperature: no deformation
  double max_substep_s = 1;
};

/// The deformation the machine model applies (machine.hpp SetThermalDeformation()).
struct ThermalDeformation {
  double x_screw_ppm = 0;  // the carriage runs ahead by ppm * 1e-6 * (x - fixed end)
  double x_screw_fixed_end_mm = 0;
  model::Vec3 tool_um;  // the tool point's displacement, independent of position
};

class HeatBalance {
 public:
  /// Every body at `start_C` (a machine that stood in the shop overnight).
  HeatBalance(const HeatBalanceParams& params, double start_C);

  /// Advances `dt_s` seconds under a constant `load` (any dt; sub-stepped inside).
  void Step(double dt_s, const ThermalLoad& load);

  double temperature_C(ThermalBody b) const { return t_C_[static_cast<int>(b)]; }
  const std::array<double, kThermalBodies>& temperatures_C() const { return t_C_; }
  double time_s() const { return time_s_; }
  /// The deformation of the present state against every body at reference_C.
  ThermalDeformation Deformation() const;
  /// Energy bookkeeping since construction, J: what the loads put in, what went to the air.
  double heat_in_J() const { return heat_in_J_; }
  double heat_to_air_J() const { return heat_to_air_J_; }
  /// Heat stored now against the start, J: sum C_i (T_i - T_i,start).
  double heat_stored_J() const;
  const HeatBalanceParams& params() const { return p_; }

 private:
  // dT/dt of every body at temperatures `t` under `load`; also the power in and to the air (W).
  void Rates(const std::array<double, kThermalBodies>& t,
             const ThermalLoad& load,
             std::array<double, kThermalBodies>* dt_dt,
             double* power_in_W,
             double* power_to_air_W) const;

  HeatBalanceParams p_;
  std::array<double, kThermalBodies> t_C_;
  double start_C_;
  double time_s_ = 0;
  double heat_in_J_ = 0;
  double heat_to_air_J_ = 0;
};

}  // namespace volcomp::sim
