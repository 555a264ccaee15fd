// The 21-parameter rigid-body model: forward error and inverse (see rigid_body.hpp).
#include "volcomp/model/rigid_body.hpp"

#include <cmath>
#include <cstdio>

#include "volcomp/model/inverse.hpp"

namespace volcomp::model {
namespace {

constexpr double kUmPerMm = 1000.0;
constexpr double kRadPerUrad = 1e-6;

Unexpected<Failure> Invalid(const std::string& message) {
  return Fail(Error::kInvalidArgument, message);
}

int AxisIndex(char c) {
  switch (c) {
    case 'X':
    case 'x':
      return 0;
    case 'Y':
    case 'y':
      return 1;
    case 'Z':
    case 'z':
      return 2;
    default:
      return -1;
  }
}

Vec3 Unit(int axis) {
  Vec3 v;
  v[axis] = 1.0;
  return v;
}

// Nominal-plus-squareness direction of an axis (exact or first order).
Vec3 Direction(const Squareness& s, int axis, bool exact) {
  const double c0y = s.c0y_urad * kRadPerUrad;
  const double b0z = s.b0z_urad * kRadPerUrad;
  const double a0z = s.a0z_urad * kRadPerUrad;
  if (axis == 0) return {1.0, 0.0, 0.0};
  if (axis == 1) return exact ? Vec3{-std::sin(c0y), std::cos(c0y), 0.0} : Vec3{-c0y, 1.0, 0.0};
  if (exact) {
    return {std::cos(a0z) * std::sin(b0z), -std::sin(a0z), std::cos(a0z) * std::cos(b0z)};
  }
  return {b0z, -a0z, 1.0};
}

Vec3 PhysicalError_mm(const Model& m, const Vec3& q) {
  const bool exact = m.order == Order::kSecond;
  Vec3 lin_mm[3], rot_rad[3], dir[3];
  for (int a = 0; a < 3; ++a) {
    const AxisErrorSample s = m.axes[static_cast<std::size_t>(a)].Sample(q[a]);
    double sign = 1.0;
    if (m.chain.workpiece_errors == ErrorSide::kCarriage &&
        m.chain.carries_workpiece[static_cast<std::size_t>(a)]) {
      sign = -1.0;
    }
    lin_mm[a] = (sign / kUmPerMm) * s.linear_um;
    rot_rad[a] = (sign * kRadPerUrad * m.angle_scale) * s.angular_urad;
    dir[a] = Direction(m.squareness, a, exact);
  }
  const Vec3& r = m.tool_offset_mm;
  if (exact) {
    Vec3 x = r;
    for (int j = 2; j >= 0; --j) {
      const int a = m.chain.order[static_cast<std::size_t>(j)];
      x = Rotate(rot_rad[a], x) + q[a] * dir[a] + lin_mm[a];
    }
    return x - (q + r);
  }
  Vec3 e;
  Vec3 lever = r;  // nominal position of the tool point relative to the current axis's reference
  for (int j = 2; j >= 0; --j) {
    const int a = m.chain.order[static_cast<std::size_t>(j)];
    e += lin_mm[a] + Cross(rot_rad[a], lever) + q[a] * (dir[a] - Unit(a));
    lever[a] += q[a];
  }
  return e;
}

}  // namespace

Expected<KinematicChain> KinematicChain::Parse(const std::string& workpiece_axes,
                                               const std::string& tool_axes) {
  KinematicChain c;
  std::array<bool, 3> seen = {false, false, false};
  std::size_t k = 0;
  const std::string all = workpiece_axes + tool_axes;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const char ch = all[i];
    if (ch == ' ' || ch == ',') continue;
    const int a = AxisIndex(ch);
    if (a < 0) return Invalid(std::string("chain: unknown axis '") + ch + "'");
    if (seen[static_cast<std::size_t>(a)]) {
      return Invalid(std::string("chain: axis ") + "XYZ"[a] + " appears twice");
    }
    seen[static_cast<std::size_t>(a)] = true;
    c.order[k++] = a;
    c.carries_workpiece[static_cast<std::size_t>(a)] = i < workpiece_axes.size();
  }
  if (k != 3) return Invalid("chain: each of X, Y, Z must appear exactly once");
  return c;
}

std::string KinematicChain::ToString() const {
  std::string w, t;
  for (int a : order) (carries_workpiece[static_cast<std::size_t>(a)] ? w : t) += "XYZ"[a];
  return w + "|" + t;
}

Outcome ValidateModel(const Model& model) {
  for (int a = 0; a < 3; ++a) {
    if (model.axes[static_cast<std::size_t>(a)].size() < 2) {
      return Invalid(std::string("model: axis ") + "XYZ"[a] + " has no error table");
    }
  }
  std::array<bool, 3> seen = {false, false, false};
  for (int a : model.chain.order) {
    if (a < 0 || a > 2 || seen[static_cast<std::size_t>(a)]) {
      return Invalid("model: the kinematic chain must list X, Y, Z once each");
    }
    seen[static_cast<std::size_t>(a)] = true;
  }
  const double values[] = {model.squareness.c0y_urad, model.squareness.b0z_urad,
                           model.squareness.a0z_urad, model.tool_offset_mm.x,
                           model.tool_offset_mm.y,    model.tool_offset_mm.z,
                           model.angle_scale};
  for (double v : values) {
    if (!std::isfinite(v)) return Invalid("model: a parameter is not finite");
  }
  return Outcome::Ok();
}

std::string DescribeModel(const Model& m) {
  std::string s = m.formulation == Formulation::kPhysical ? "physical" : "dissertation";
  if (m.formulation == Formulation::kPhysical) {
    s += m.order == Order::kFirst ? ", first order" : ", exact rotations";
    s += ", chain " + m.chain.ToString();
  } else {
    s += m.order == Order::kFirst
             ? ", first order (3.10)"
             : (m.dissertation_case == DissertationCase::kPlus ? ", second order δ+ (3.9)"
                                                               : ", second order δ− (3.9)");
  }
  if (m.angle_scale != 1.0) {
    char scale[64];
    std::snprintf(scale, sizeof scale, "%.6g", m.angle_scale);
    s += std::string(", angle scale ") + scale;
  }
  return s;
}

Vec3 ToolPointError_um(const Model& model, const Vec3& command_mm) {
  if (model.formulation == Formulation::kDissertation) {
    DissertationOptions o;
    o.k = model.angle_scale;
    o.r_um = kUmPerMm * model.tool_offset_mm;
    o.which =
        model.order == Order::kFirst ? DissertationCase::kFirstOrder : model.dissertation_case;
    return DissertationError(PointErrorsAt(model.axes, command_mm), o).delta_um;
  }
  return kUmPerMm * PhysicalError_mm(model, command_mm);
}

CommandSolution SolveCommand(const Model& model, const Vec3& target_mm, double tolerance_um) {
  const auto error_mm = [&model](const Vec3& q) {
    return (1.0 / kUmPerMm) * ToolPointError_um(model, q);
  };
  const InverseSolution s = InvertError(error_mm, target_mm, tolerance_um / kUmPerMm);
  CommandSolution out;
  out.command_mm = s.command_mm;
  out.residual_um = s.residual_mm * kUmPerMm;
  out.iterations = s.iterations;
  out.converged = s.converged;
  return out;
}

Vec3 CommandForTarget_mm(const Model& model, const Vec3& target_mm) {
  return SolveCommand(model, target_mm).command_mm;
}

}  // namespace volcomp::model
