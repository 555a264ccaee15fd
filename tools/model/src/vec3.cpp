// 3x3 algebra: products, a pivoting solve, exact rotations.
#include "volcomp/model/vec3.hpp"

#include <utility>

namespace volcomp::model {

Mat3 operator*(const Mat3& a, const Mat3& b) {
  Mat3 r;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      r(i, j) = a(i, 0) * b(0, j) + a(i, 1) * b(1, j) + a(i, 2) * b(2, j);
    }
  }
  return r;
}

bool Solve(const Mat3& a, const Vec3& b, Vec3* x) {
  double m[3][4];
  double scale = 0.0;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      m[r][c] = a(r, c);
      scale = std::fmax(scale, std::fabs(a(r, c)));
    }
    m[r][3] = b[r];
  }
  if (!(scale > 0.0) || !std::isfinite(scale)) return false;
  for (int col = 0; col < 3; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 3; ++r) {
      if (std::fabs(m[r][col]) > std::fabs(m[pivot][col])) pivot = r;
    }
    if (std::fabs(m[pivot][col]) <= 1e-14 * scale) return false;
    if (pivot != col) {
      for (int c = 0; c < 4; ++c) std::swap(m[pivot][c], m[col][c]);
    }
    for (int r = col + 1; r < 3; ++r) {
      const double f = m[r][col] / m[col][col];
      for (int c = col; c < 4; ++c) m[r][c] -= f * m[col][c];
    }
  }
  Vec3 out;
  for (int r = 2; r >= 0; --r) {
    double s = m[r][3];
    for (int c = r + 1; c < 3; ++c) s -= m[r][c] * out[c];
    out[r] = s / m[r][r];
  }
  *x = out;
  return true;
}

Mat3 RotationFromVector(const Vec3& rotation_rad) {
  const double angle = Norm(rotation_rad);
  if (angle == 0.0) return Mat3::Identity();
  const Vec3 k = (1.0 / angle) * rotation_rad;
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  return {{t * k.x * k.x + c, t * k.x * k.y - s * k.z, t * k.x * k.z + s * k.y,
           t * k.x * k.y + s * k.z, t * k.y * k.y + c, t * k.y * k.z - s * k.x,
           t * k.x * k.z - s * k.y, t * k.y * k.z + s * k.x, t * k.z * k.z + c}};
}

Vec3 Rotate(const Vec3& rotation_rad, const Vec3& v) {
  const double angle = Norm(rotation_rad);
  if (angle == 0.0) return v;
  const Vec3 k = (1.0 / angle) * rotation_rad;
  const double c = std::cos(angle), s = std::sin(angle);
  // Rodrigues' rotation formula.
  return c * v + s * Cross(k, v) + ((1.0 - c) * Dot(k, v)) * k;
}

}  // namespace volcomp::model
