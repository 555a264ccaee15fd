// Eqs. (3.5)-(3.10) of the dissertation as printed (see dissertation.hpp for the quirks).
#include "volcomp/model/dissertation.hpp"

namespace volcomp::model {

DissertationResult DissertationError(const PointErrors& errors,
                                     const DissertationOptions& options) {
  double e[3][3];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) e[i][j] = options.k * errors.eps_um_per_mm[i][j];
  }
  const double exx = e[0][0], exy = e[0][1], exz = e[0][2];
  const double eyx = e[1][0], eyy = e[1][1], eyz = e[1][2];
  const double ezx = e[2][0], ezy = e[2][1], ezz = e[2][2];

  double a = 1e-3 * (exx + eyx + ezx);
  double b = 1e-3 * (exy + eyy + ezy);
  double c = 1e-3 * (exz + eyz + ezz);
  double l = 1.0;
  const bool second = options.which != DissertationCase::kFirstOrder;
  if (second) {
    // Products exactly as printed in (3.5); note B's ε_xz·ε_zy (see the header).
    const double sa = exy * eyz + exz * eyy + exy * ezz + eyy * ezz + exz * ezy + eyz * ezy +
                      exy * exz + eyy * eyz + ezy * ezz;
    const double sb = exx * eyz + exz * eyx + exx * ezz + eyx * ezz + exz * ezx + exz * ezy +
                      exx * exz + eyx * eyz + ezx * ezz;
    const double sc = exx * eyy + exy * eyx + exx * ezy + eyx * ezy + exy * ezx + eyy * ezx +
                      exx * exy + eyx * eyy + ezx * ezy;
    const double s = options.which == DissertationCase::kPlus ? 1.0 : -1.0;
    a += s * 1e-6 * 0.5 * sa;
    b += s * 1e-6 * 0.5 * sb;
    c += s * 1e-6 * 0.5 * sc;
    l = 1.0 / (1.0 + 0.25 * (a * a + b * b + c * c));
  }

  const double r1 = options.r_um.x, r2 = options.r_um.y, r3 = options.r_um.z;
  Vec3 dr = {b * r3 - c * r2, c * r1 - a * r3, a * r2 - b * r1};  // E″ × r
  if (second) {
    dr.x += 0.5 * b * (a * r2 - b * r1) - 0.5 * c * (c * r1 - a * r3);
    dr.y += 0.5 * c * (b * r3 - c * r2) - 0.5 * a * (a * r2 - b * r1);
    dr.z += 0.5 * a * (c * r1 - a * r3) - 0.5 * b * (b * r3 - c * r2);
    dr = l * dr;
  }

  const auto& d = errors.delta_um;
  Vec3 rho;
  if (options.group_linear_by_direction) {
    rho = {d[0][0] + d[1][0] + d[2][0], d[0][1] + d[1][1] + d[2][1], d[0][2] + d[1][2] + d[2][2]};
  } else {  // (3.8) as printed: grouped by the moving axis
    rho = {d[0][0] + d[0][1] + d[0][2], d[1][0] + d[1][1] + d[1][2], d[2][0] + d[2][1] + d[2][2]};
  }

  DissertationResult out;
  out.delta_um = dr + rho;
  out.norm_um = Norm(out.delta_um);
  out.a_rad = a;
  out.b_rad = b;
  out.c_rad = c;
  out.l = l;
  return out;
}

PointErrors PointErrorsAt(const std::array<AxisErrorTable, 3>& axes, const Vec3& position_mm) {
  PointErrors p{};
  for (int i = 0; i < 3; ++i) {
    const AxisErrorSample s = axes[static_cast<std::size_t>(i)].Sample(position_mm[i]);
    for (int j = 0; j < 3; ++j) {
      p.delta_um[i][j] = s.linear_um[j];
      p.eps_um_per_mm[i][j] = s.angular_urad[j] * 1e-3;
    }
  }
  return p;
}

}  // namespace volcomp::model
