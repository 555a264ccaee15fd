// The 21-parameter rigid-body error model of a three-axis machine (ISO 230-1 style) and its
// inverse.
//
// Per axis K (X, Y, Z): three linear error functions E_XK, E_YK, E_ZK and three angular ones
// E_AK, E_BK, E_CK of that axis's own position (AxisErrorTable); three squareness errors; a tool
// offset; a kinematic chain. This is the model the table builders invert and the host simulator
// uses as its machine.
//
// Sign conventions (documented in docs/table-builders.md):
//   * Every error is "actual minus nominal" of the tool point relative to the workpiece.
//   * An axis's error functions describe the motion of the tool side relative to the workpiece side
//     produced by that axis alone ("relative", as a laser interferometer between spindle and table
//     measures them). With KinematicChain::workpiece_errors = kCarriage, the functions of the
//     workpiece-carrying axes are the table carriage's own motion instead and are negated.
//   * Squareness: X is the reference. C0Y = rotation of the Y axis line about +z, so the Y
//   direction
//     is (−sin C0Y, cos C0Y, 0) and the X–Y angle is 90° + C0Y. B0Z and A0Z rotate the Z line about
//     +y and +x: Z direction = Ry(B0Z)·Rx(A0Z)·(0,0,1) ≈ (B0Z, −A0Z, 1).
//   * The angular errors of an axis act on everything the chain puts after it (toward the tool):
//     lever arm = nominal positions of the later axes + tool offset, measured from the common
//     reference point where all commands are 0 (where the error tables were measured).
//
// Physical formulation (default): P(q) = M_1(M_2(M_3(r))), M_j(x) = R_j·x + q_j·d_j + δ_j, in chain
// order from the workpiece to the tool; nominal P = q + r; error = P − (q + r). kSecond uses exact
// finite rotations (exponential map of (E_A, E_B, E_C)) and exact squareness directions; kFirst
// keeps only terms linear in the errors: Σ_j [δ_j + ε_j × a_j] + Σ_j q_j·(d_j − e_j).
// Dissertation formulation: see dissertation.hpp (tool vector r = tool_offset).
#pragma once

#include <array>
#include <string>

#include "volcomp/model/axis_table.hpp"
#include "volcomp/model/dissertation.hpp"
#include "volcomp/model/vec3.hpp"

namespace volcomp::model {

enum class Formulation { kPhysical, kDissertation };
/// kFirst: first order (small angles). kSecond: physical = exact finite rotations; dissertation =
/// the second-order formula (3.9) with the sign case of Model::dissertation_case.
enum class Order { kFirst, kSecond };
enum class ErrorSide { kRelative, kCarriage };

/// Out-of-squareness of Y and Z relative to X, µrad (see the sign convention above).
struct Squareness {
  double c0y_urad = 0.0;
  double b0z_urad = 0.0;
  double a0z_urad = 0.0;
};

/// The order of the axes from the workpiece to the tool and which of them carry the workpiece.
struct KinematicChain {
  std::array<int, 3> order = {0, 1, 2};  // axis indices, workpiece side first
  std::array<bool, 3> carries_workpiece = {false, false, false};  // per axis index
  ErrorSide workpiece_errors = ErrorSide::kRelative;

  /// Builds a chain from axis letters: `workpiece_axes` from the workpiece down to the base
  /// (first letter carries the workpiece), `tool_axes` from the base up to the tool (last letter
  /// carries the tool). Each of X, Y, Z exactly once; throws std::invalid_argument otherwise.
  static KinematicChain Parse(const std::string& workpiece_axes, const std::string& tool_axes);
  /// The chain written back as "workpiece_axes|tool_axes" letters, e.g. "Y|XZ".
  std::string ToString() const;
};

struct Model {
  std::string name;
  std::array<AxisErrorTable, 3> axes;  // X, Y, Z
  Squareness squareness;
  Vec3 tool_offset_mm;
  KinematicChain chain;
  Formulation formulation = Formulation::kPhysical;
  Order order = Order::kSecond;
  DissertationCase dissertation_case = DissertationCase::kPlus;  // used when kDissertation+kSecond
  double angle_scale = 1.0;  // multiplies every angular error (the dissertation's k)
};

/// Throws std::invalid_argument naming the problem (empty tables, bad chain, non-finite values).
void ValidateModel(const Model& model);

/// Error of the tool point (actual − nominal, µm) when the machine is commanded to `command_mm`.
/// Cheap: three table lookups and a few dozen flops (plus 3 sin/cos pairs for kSecond).
Vec3 ToolPointError_um(const Model& model, const Vec3& command_mm);

struct CommandSolution {
  Vec3 command_mm;         // the command that lands the tool on the target
  double residual_um = 0;  // ‖command + error(command) − target‖
  int iterations = 0;
  bool converged = false;
};

/// Inverse of the model: solves q + error(q) = target by fixed-point iteration (the error's
/// Jacobian is ~1e-3, so each iteration gains about three digits) until the step is below
/// `tolerance_um`. converged is false when 100 iterations did not get there.
CommandSolution SolveCommand(const Model& model, const Vec3& target_mm, double tolerance_um = 1e-5);

/// Shorthand: SolveCommand(...).command_mm.
Vec3 CommandForTarget_mm(const Model& model, const Vec3& target_mm);

}  // namespace volcomp::model
