// The simulated machine's own rigid-body kinematics: where the tool point is for given axis
// positions, by homogeneous transforms from the ISO 230-1 error motions of each axis: axis K at q
// moves everything after it in the chain by T(q·d_K + E_lin,K(q))·R(E_ang,K(q)), d_K its direction
// with the squareness, R the rotation about the rotation vector; tables linear between rows and
// held beyond (docs/simulator.md "The machine"). Deliberately apart from tools/model's formulas,
// which tests/host-sim/machine compares it with. Lengths mm, errors µm and µrad.
// Thread-safety: const methods may be called concurrently.
#pragma once

#include <array>
#include <vector>

namespace volcomp::sim {

using Xyz = std::array<double, 3>;

/// The six error motions of axis K at one position: the tool side relative to the workpiece side.
struct ErrorMotionRow {
  double position_mm = 0;
  Xyz linear_um = {0, 0, 0};     // E_XK, E_YK, E_ZK: translation along x, y, z
  Xyz angular_urad = {0, 0, 0};  // E_AK, E_BK, E_CK: rotation about x, y, z
};

struct MachineGeometry {
  std::array<std::vector<ErrorMotionRow>, 3> axes;  // X, Y, Z; rows at increasing positions
  // Squareness: X runs along x, Y along Rz(E_C0Y)·y, Z along Ry(E_B0Z)·Rx(E_A0Z)·z.
  double c0y_urad = 0, b0z_urad = 0, a0z_urad = 0;
  // A point fixed on the tool side is p = tool offset + its own offset; it is at H_K1·H_K2·H_K3·p
  // in the workpiece frame, whose origin is where every axis is at 0.
  Xyz tool_offset_mm = {0, 0, 0};
  std::array<int, 3> chain = {0, 1, 2};  // axis indices K1, K2, K3 from the workpiece to the tool
  std::array<bool, 3> carries_workpiece = {false, false, false};
  // The tables of the axes that carry the workpiece are the carriage's own motion: their values
  // are taken with the opposite sign.
  bool workpiece_tables_are_carriage_motion = false;
  double angle_scale = 1.0;  // multiplies every rotation (1 = as tabulated)
};

class RigidBodyKinematics {
 public:
  /// Precondition (checked by the caller, Machine): every axis has >= 2 rows at increasing
  /// positions, the chain lists 0, 1, 2 once each.
  explicit RigidBodyKinematics(MachineGeometry geometry);

  const MachineGeometry& geometry() const { return geometry_; }

  /// Position (mm, workpiece frame) of the point at `offset_mm` from the tool point when the axes
  /// stand at `q_mm`.
  Xyz ToolPoint_mm(const Xyz& q_mm, const Xyz& offset_mm = {0, 0, 0}) const;

  /// The error motions of `axis` at `position_mm` (linear between rows, the end rows held beyond).
  ErrorMotionRow ErrorMotions(int axis, double position_mm) const;

 private:
  MachineGeometry geometry_;
  std::array<Xyz, 3> direction_;  // d_X, d_Y, d_Z
};

}  // namespace volcomp::sim
