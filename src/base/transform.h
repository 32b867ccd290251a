// Affine/projective transforms as 4x4 matrices (kept in double, applied in float).
#pragma once
#include <array>
#include <optional>

#include "base/vec.h"

namespace objektiv {

struct Matrix4 {
  std::array<std::array<double, 4>, 4> m{};

  static Matrix4 Identity();
  Matrix4 operator*(const Matrix4& o) const;
  Matrix4 Transposed() const;
  // Inverse by Gauss-Jordan elimination with partial pivoting; nullopt when singular.
  std::optional<Matrix4> Inverse() const;
  bool IsIdentity() const;
};

class Transform {
 public:
  Transform() : m_(Matrix4::Identity()), inv_(Matrix4::Identity()) {}
  Transform(const Matrix4& m, const Matrix4& inv) : m_(m), inv_(inv) {}
  // Throws std::invalid_argument when m is singular.
  explicit Transform(const Matrix4& m);

  static Transform Translate(const Vec3d& d);
  static Transform Scale(const Vec3d& s);
  static Transform Rotate(double angle_deg, Vec3d axis);
  // Camera-style look-at: maps camera space (+z forward, +y up, +x left, as Mitsuba) to world.
  static Transform LookAt(const Vec3d& origin, const Vec3d& target, const Vec3d& up);

  Transform operator*(const Transform& o) const { return Transform(m_ * o.m_, o.inv_ * inv_); }
  Transform Inverse() const { return Transform(inv_, m_); }
  const Matrix4& Matrix() const { return m_; }
  const Matrix4& InverseMatrix() const { return inv_; }
  bool IsIdentity() const { return m_.IsIdentity(); }
  // True when the upper 3x3 part flips orientation (negative determinant).
  bool SwapsHandedness() const;

  Vec3f Point(const Vec3f& p) const;
  Vec3d Point(const Vec3d& p) const;
  Vec3f Vector(const Vec3f& v) const;
  Vec3d Vector(const Vec3d& v) const;
  // Normals transform with the inverse transpose.
  Vec3f Normal(const Vec3f& n) const;

 private:
  Matrix4 m_, inv_;
};

}  // namespace objektiv
