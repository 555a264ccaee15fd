// The simulated machine tool: the 21 error functions of a model file of the table builders (the
// STAN S500 by default) on the machine's own rigid-body kinematics (rigid_body_kinematics.hpp, no
// tools/model formulas), driven by the drives' step counts, plus the worn profile's error sources
// (worn_profile.hpp; docs/simulator.md "The machine", §7). Drive position (mm) = power-up position
// + drive steps x step length; axis positions add the worn sources; home switches close below the
// travel. Lengths mm, errors µm. Thread-safety: none (the simulation's thread).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/rigid_body.hpp"
#include "volcomp/model/vec3.hpp"
#include "volcomp/sim/error_sources.hpp"
#include "volcomp/sim/heat_balance.hpp"
#include "volcomp/sim/random.hpp"
#include "volcomp/sim/rigid_body_kinematics.hpp"
#include "volcomp/sim/worn_profile.hpp"

namespace volcomp::sim {

struct MachineOptions {
  model::Model model;                                     // empty: the built-in S500
  std::array<double, 3> step_mm = {0.001, 0.001, 0.001};  // drive step length per axis
  /// Where each axis stands at power-up; NaN = 10 % into its travel.
  std::array<double, 3> power_up_mm = {NAN, NAN, NAN};
  /// The home switch closes at or below this position; NaN = 5 mm below the travel's start.
  std::array<double, 3> home_switch_mm = {NAN, NAN, NAN};
  WornMachineProfile wear;  // all off: the rigid-body machine alone
};

/// "s500" (the built-in STAN S500 model) or a model config file (tools/datasets model_config.hpp
/// format); the failure names the file and the problem.
Expected<model::Model> LoadMachineModel(const std::string& spec);

/// The error functions, squareness, tool offset and chain of a model, as the machine's data.
MachineGeometry GeometryOf(const model::Model& model);

class Machine {
 public:
  /// The machine, or kInvalidArgument naming a bad option (step length, power-up below the
  /// switch, a model in the dissertation's formulation, a model ValidateModel refuses).
  static Expected<Machine> Create(MachineOptions options);

  const model::Model& model() const { return options_.model; }
  const WornMachineProfile& wear() const { return options_.wear; }
  double step_mm(int axis) const { return options_.step_mm[static_cast<size_t>(axis)]; }
  /// The travel covered by the model's error tables (mm).
  double travel_min_mm(int axis) const;
  double travel_max_mm(int axis) const;
  double home_switch_mm(int axis) const {
    return options_.home_switch_mm[static_cast<size_t>(axis)];
  }
  double power_up_mm(int axis) const { return options_.power_up_mm[static_cast<size_t>(axis)]; }

  /// After every control tick: the drives' counts at time `t_ns`. Each axis moves monotonically
  /// within a tick (one pulse direction per tick), so following the counts tick by tick follows
  /// every reversal.
  void OnDriveTick(const std::array<int64_t, 3>& drive_steps, uint64_t t_ns);
  /// Seconds since power-up (the last OnDriveTick).
  double time_s() const { return time_s_; }

  /// The heat balance's deformation in force from now on (heat_balance.hpp; none at power-up):
  /// the X carriage runs ahead by the screw's expansion, the tool point moves by tool_um. It adds
  /// to the worn profile's closed-form warm-up (WornMachineProfile::thermal), which a run driven
  /// by a heat balance leaves off.
  void SetThermalDeformation(const ThermalDeformation& d) { deformation_ = d; }
  const ThermalDeformation& thermal_deformation() const { return deformation_; }

  /// Drive positions (mm) for drive step counts.
  model::Vec3 DrivePositions_mm(const std::array<int64_t, 3>& drive_steps) const;
  /// Axis (carriage) positions (mm) for the drives at `drive_steps` now (the counts of the last
  /// OnDriveTick, or at power-up).
  model::Vec3 AxisPositions_mm(const std::array<int64_t, 3>& drive_steps) const;
  /// Where the tool point actually is (mm) now with the axes at `q_mm`.
  model::Vec3 ToolPoint_mm(const model::Vec3& q_mm) const;
  /// Where a point rigidly attached to the tool side at `offset_mm` from the tool point actually
  /// is (the second reflector of angular optics, a level on the spindle head).
  model::Vec3 PointOnTool_mm(const model::Vec3& q_mm, const model::Vec3& offset_mm) const;
  /// True while the axis's home switch is closed.
  bool HomeSwitchClosed(int axis, int64_t drive_steps) const;

 private:
  explicit Machine(MachineOptions options);  // options checked by Create

  MachineOptions options_;
  RigidBodyKinematics kinematics_;
  std::array<int64_t, 3> switch_steps_ = {0, 0, 0};
  // Worn-profile state.
  Random rng_;
  double time_s_ = 0;
  ThermalDeformation deformation_;
  std::array<int64_t, 3> last_steps_ = {0, 0, 0};
  std::array<bool, 3> moving_ = {false, false, false};
  std::array<uint64_t, 3> last_step_ns_ = {0, 0, 0};
  std::array<LostMotion, 3> lost_motion_;
  std::array<double, 3> scatter_mm_ = {0, 0, 0};
};

}  // namespace volcomp::sim
