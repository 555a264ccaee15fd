// Small fixed-size linear algebra for the error models: 3-vectors and 3x3 matrices in double.
//
// Units are whatever the caller's names say (`_mm`, `_um`, `_rad`); nothing here converts.
#pragma once

#include <array>
#include <cmath>

namespace volcomp::model {

/// A 3-vector; components are x, y, z (or axis 0, 1, 2).
struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;

  double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
};

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
inline Vec3 operator*(double s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline Vec3 operator*(const Vec3& a, double s) { return s * a; }
inline Vec3& operator+=(Vec3& a, const Vec3& b) {
  a = a + b;
  return a;
}
inline Vec3& operator-=(Vec3& a, const Vec3& b) {
  a = a - b;
  return a;
}
inline double Dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 Cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double Norm(const Vec3& a) { return std::sqrt(Dot(a, a)); }
/// Largest absolute component.
inline double MaxAbs(const Vec3& a) {
  return std::fmax(std::fabs(a.x), std::fmax(std::fabs(a.y), std::fabs(a.z)));
}

/// A 3x3 matrix, row-major: m[r * 3 + c].
struct Mat3 {
  std::array<double, 9> m = {0, 0, 0, 0, 0, 0, 0, 0, 0};

  double operator()(int r, int c) const { return m[static_cast<std::size_t>(r * 3 + c)]; }
  double& operator()(int r, int c) { return m[static_cast<std::size_t>(r * 3 + c)]; }

  static Mat3 Identity() { return {{1, 0, 0, 0, 1, 0, 0, 0, 1}}; }
  /// The matrix whose columns are a, b, c.
  static Mat3 FromColumns(const Vec3& a, const Vec3& b, const Vec3& c) {
    return {{a.x, b.x, c.x, a.y, b.y, c.y, a.z, b.z, c.z}};
  }
  Vec3 Column(int c) const { return {(*this)(0, c), (*this)(1, c), (*this)(2, c)}; }
  Mat3 Transposed() const { return {{m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]}}; }
};

inline Vec3 operator*(const Mat3& a, const Vec3& v) {
  return {a.m[0] * v.x + a.m[1] * v.y + a.m[2] * v.z, a.m[3] * v.x + a.m[4] * v.y + a.m[5] * v.z,
          a.m[6] * v.x + a.m[7] * v.y + a.m[8] * v.z};
}
Mat3 operator*(const Mat3& a, const Mat3& b);

/// Solves a·x = b by Gaussian elimination with partial pivoting. Returns false (x untouched) when
/// a is singular to working precision.
bool Solve(const Mat3& a, const Vec3& b, Vec3* x);

/// Rotation matrix of the rotation vector `rotation_rad` (axis = direction, angle = length in rad;
/// the exponential map, exact for any angle). Zero vector gives the identity.
Mat3 RotationFromVector(const Vec3& rotation_rad);

/// Applies the rotation of `rotation_rad` (as RotationFromVector) to v without forming the matrix.
Vec3 Rotate(const Vec3& rotation_rad, const Vec3& v);

}  // namespace volcomp::model
