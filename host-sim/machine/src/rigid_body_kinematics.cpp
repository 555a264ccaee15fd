// The simulated machine's rigid-body kinematics by homogeneous transforms (see the header).
#include "volcomp/sim/rigid_body_kinematics.hpp"

#include <cmath>
#include <utility>

namespace volcomp::sim {
namespace {

// A rigid homogeneous transform [R t; 0 1], stored as its 3x3 rotation and translation.
struct Htm {
  double r[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Xyz t = {0, 0, 0};

  Xyz Apply(const Xyz& p) const {
    Xyz out;
    for (int i = 0; i < 3; ++i) {
      out[i] = r[i][0] * p[0] + r[i][1] * p[1] + r[i][2] * p[2] + t[i];
    }
    return out;
  }
};

Htm Compose(const Htm& a, const Htm& b) {  // a·b
  Htm c;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      c.r[i][j] = a.r[i][0] * b.r[0][j] + a.r[i][1] * b.r[1][j] + a.r[i][2] * b.r[2][j];
    }
    c.t[i] = a.r[i][0] * b.t[0] + a.r[i][1] * b.t[1] + a.r[i][2] * b.t[2] + a.t[i];
  }
  return c;
}

// Rotation by the rotation vector w (rad) through the unit quaternion (cos θ/2, sin θ/2 · w/θ).
Htm Rotation(const Xyz& w) {
  const double theta = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  // sin(θ/2)/θ, with its series where θ is too small to divide by.
  const double k = theta > 1e-6 ? std::sin(0.5 * theta) / theta : 0.5 - theta * theta / 48.0;
  const double qw = std::cos(0.5 * theta), qx = k * w[0], qy = k * w[1], qz = k * w[2];
  Htm h;
  h.r[0][0] = 1 - 2 * (qy * qy + qz * qz);
  h.r[0][1] = 2 * (qx * qy - qz * qw);
  h.r[0][2] = 2 * (qx * qz + qy * qw);
  h.r[1][0] = 2 * (qx * qy + qz * qw);
  h.r[1][1] = 1 - 2 * (qx * qx + qz * qz);
  h.r[1][2] = 2 * (qy * qz - qx * qw);
  h.r[2][0] = 2 * (qx * qz - qy * qw);
  h.r[2][1] = 2 * (qy * qz + qx * qw);
  h.r[2][2] = 1 - 2 * (qx * qx + qy * qy);
  return h;
}

// Elementary rotation by `angle` (rad) about coordinate axis `axis`.
Htm AboutAxis(int axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Htm h;
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  h.r[i][i] = c;
  h.r[i][j] = -s;
  h.r[j][i] = s;
  h.r[j][j] = c;
  return h;
}

}  // namespace

RigidBodyKinematics::RigidBodyKinematics(MachineGeometry geometry)
    : geometry_(std::move(geometry)) {
  const double urad = 1e-6;
  direction_[0] = {1, 0, 0};
  direction_[1] = AboutAxis(2, geometry_.c0y_urad * urad).Apply({0, 1, 0});
  direction_[2] =
      Compose(AboutAxis(1, geometry_.b0z_urad * urad), AboutAxis(0, geometry_.a0z_urad * urad))
          .Apply({0, 0, 1});
}

ErrorMotionRow RigidBodyKinematics::ErrorMotions(int axis, double position_mm) const {
  const std::vector<ErrorMotionRow>& rows = geometry_.axes[static_cast<size_t>(axis)];
  ErrorMotionRow out;
  out.position_mm = position_mm;
  if (!(position_mm > rows.front().position_mm)) {
    out.linear_um = rows.front().linear_um;
    out.angular_urad = rows.front().angular_urad;
    return out;
  }
  if (!(position_mm < rows.back().position_mm)) {
    out.linear_um = rows.back().linear_um;
    out.angular_urad = rows.back().angular_urad;
    return out;
  }
  size_t hi = 1;
  while (rows[hi].position_mm < position_mm) ++hi;
  const ErrorMotionRow& a = rows[hi - 1];
  const ErrorMotionRow& b = rows[hi];
  const double f = (position_mm - a.position_mm) / (b.position_mm - a.position_mm);
  for (size_t i = 0; i < 3; ++i) {
    out.linear_um[i] = (1 - f) * a.linear_um[i] + f * b.linear_um[i];
    out.angular_urad[i] = (1 - f) * a.angular_urad[i] + f * b.angular_urad[i];
  }
  return out;
}

Xyz RigidBodyKinematics::ToolPoint_mm(const Xyz& q_mm, const Xyz& offset_mm) const {
  Htm chain;
  for (int k = 0; k < 3; ++k) {
    const int a = geometry_.chain[static_cast<size_t>(k)];
    const size_t i = static_cast<size_t>(a);
    const ErrorMotionRow e = ErrorMotions(a, q_mm[i]);
    const bool negate =
        geometry_.workpiece_tables_are_carriage_motion && geometry_.carries_workpiece[i];
    const double sign = negate ? -1.0 : 1.0;
    Xyz w;
    Htm motion;
    for (size_t c = 0; c < 3; ++c) {
      w[c] = sign * geometry_.angle_scale * 1e-6 * e.angular_urad[c];
      motion.t[c] = q_mm[i] * direction_[i][c] + sign * 1e-3 * e.linear_um[c];
    }
    const Htm rotated = Rotation(w);
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) motion.r[r][c] = rotated.r[r][c];
    }
    chain = Compose(chain, motion);
  }
  const Xyz& t = geometry_.tool_offset_mm;
  return chain.Apply({t[0] + offset_mm[0], t[1] + offset_mm[1], t[2] + offset_mm[2]});
}

}  // namespace volcomp::sim
