// The simulated machine tool: a rigid-body machine with the 21 error functions of a model file of
// the table builders (the STAN S500 by default), driven by the drives' output step counts, plus
// optionally the error sources of a worn machine (worn_profile.hpp). The model file is only its
// data: the tool point comes from the machine's own kinematics (rigid_body_kinematics.hpp), which
// shares no code with tools/model's formulas.
//
// Frames and units:
//   * Drive position d (mm, the model's command frame) = power-up position + drive steps x step
//     length. The drives count output steps from 0 at power-up (DriveModel), so the simulator never
//     needs to know what the CNC or the board think the position is.
//   * Axis (carriage) position q = d for a perfect machine; the worn profile adds the lost motion
//     offset, the screw's short-period error, the settling scatter and the X screw's thermal
//     growth. The 21 error functions are taken at q.
//   * Tool point (mm) = the kinematics' tool point minus the nominal tool offset (i.e. q when the
//     machine has no errors), plus the cross-axis sag and the spindle's thermal growth. The
//     model's `formulation` and `order` describe how a builder computes; the machine is always
//     the exact rigid body (a dissertation-formulation model is refused).
//   * Each axis has a home switch at its negative end, worked by the carriage (lost motion
//     included): closed while q <= home_switch_mm.
//   * Time: the world reports every tick's drive counts and time (OnDriveTick); the worn sources
//     need them (lost motion follows every drive step, scatter is drawn when an axis comes to
//     rest, thermal growth runs with time).
//
// Thread-safety: none; call from the simulation's thread.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include "volcomp/model/rigid_body.hpp"
#include "volcomp/model/vec3.hpp"
#include "volcomp/sim/error_sources.hpp"
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
/// format). Throws std::runtime_error naming the problem.
model::Model LoadMachineModel(const std::string& spec);

/// The error functions, squareness, tool offset and chain of a model, as the machine's data.
MachineGeometry GeometryOf(const model::Model& model);

class Machine {
 public:
  /// Throws std::invalid_argument naming a bad option (step length, power-up below the switch,
  /// a model in the dissertation's formulation, a model ValidateModel refuses).
  explicit Machine(MachineOptions options);

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
  MachineOptions options_;
  RigidBodyKinematics kinematics_;
  std::array<int64_t, 3> switch_steps_ = {0, 0, 0};
  // Worn-profile state.
  Random rng_;
  double time_s_ = 0;
  std::array<int64_t, 3> last_steps_ = {0, 0, 0};
  std::array<bool, 3> moving_ = {false, false, false};
  std::array<LostMotion, 3> lost_motion_;
  std::array<double, 3> scatter_mm_ = {0, 0, 0};
};

}  // namespace volcomp::sim
