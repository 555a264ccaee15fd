// The 21-parameter rigid-body error model of a three-axis machine (ISO 230-1 style) and its
// inverse: per axis X, Y, Z six error functions of its own position (AxisErrorTable), three
// squareness errors, a tool offset and a kinematic chain; the physical formulation (exact
// rotations or first order) or the dissertation's (dissertation.hpp). The host simulator uses it
// as its machine. Every error is actual − nominal of the tool point relative to the workpiece; the
// sign, squareness and chain conventions and the formulas are in docs/table-builders.md §2.
// Lengths mm, linear errors µm, angles µrad.
#pragma once

#include <array>
#include <string>

#include "volcomp/hosted/expected.hpp"
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
  /// carries the tool). Each of X, Y, Z exactly once; kInvalidArgument otherwise.
  static Expected<KinematicChain> Parse(const std::string& workpiece_axes,
                                        const std::string& tool_axes);
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

/// Success, or kInvalidArgument naming the problem (empty tables, bad chain, non-finite values).
Outcome ValidateModel(const Model& model);

/// The model's formulation, order and chain in words, for reports ("physical, exact rotations,
/// chain |XYZ").
std::string DescribeModel(const Model& model);

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
