// The simulated machine's own rigid-body kinematics: where the tool point is for given axis
// positions, computed from the definitions of the error motions (ISO 230-1 names) by homogeneous
// transforms. It is written apart from the table builders' model (tools/model rigid_body.hpp)
// and this library does not link tools/model: the demo's truth must not be the formula the
// builders invert, so a sign or convention error on either side shows as a disagreement
// (tests/sim_demo/kinematics_test.cpp compares both on the pure 21-parameter case).
//
// Definitions (frames right-handed, lengths mm):
//   * Each linear axis K of X, Y, Z has six error motions, functions of its own position
//     (ISO 230-1): E_XK, E_YK, E_ZK, the translation of the tool side relative to the workpiece
//     side along x, y, z (µm), and E_AK, E_BK, E_CK, its rotation about x, y, z (µrad). They are
//     given at rows of increasing position; linear between rows, the end rows hold outside.
//   * Axis directions with the squareness (location) errors: X along x; Y along Rz(E_C0Y)·y;
//     Z along Ry(E_B0Z)·Rx(E_A0Z)·z (Rx, Ry, Rz: rotations about x, y, z).
//   * Axis K at position q moves everything after it in the chain by the homogeneous transform
//         H_K(q) = T(q·d_K + E_lin,K(q)) · R(E_ang,K(q)),
//     T a translation, R(w) the rotation by the angle |w| about the axis w/|w|.
//   * Chain from the workpiece to the tool, axes K1, K2, K3: a point p fixed on the tool side
//     (p = tool offset + the point's own offset) is at H_K1·H_K2·H_K3·p in the workpiece frame,
//     whose origin is where every axis is at 0.
//   * Tables of axes that carry the workpiece may be given as the carriage's own motion
//     (`workpiece_tables_are_carriage_motion`): their values are then taken with the opposite sign.
//   * `angle_scale` multiplies every rotation (1 = as tabulated).
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
