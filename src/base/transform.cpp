#include "base/transform.h"

#include <cmath>
#include <stdexcept>

namespace objektiv {

Matrix4 Matrix4::Identity() {
  Matrix4 r;
  for (int i = 0; i < 4; ++i) r.m[i][i] = 1;
  return r;
}

Matrix4 Matrix4::operator*(const Matrix4& o) const {
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += m[i][k] * o.m[k][j];
      r.m[i][j] = s;
    }
  return r;
}

Matrix4 Matrix4::Transposed() const {
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = m[j][i];
  return r;
}

bool Matrix4::IsIdentity() const {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (m[i][j] != (i == j ? 1.0 : 0.0)) return false;
  return true;
}

std::optional<Matrix4> Matrix4::Inverse() const {
  double a[4][8];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      a[i][j] = m[i][j];
      a[i][j + 4] = (i == j) ? 1 : 0;
    }
  for (int c = 0; c < 4; ++c) {
    int pivot = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
    if (std::abs(a[pivot][c]) < 1e-300) return std::nullopt;
    if (pivot != c)
      for (int j = 0; j < 8; ++j) std::swap(a[c][j], a[pivot][j]);
    double inv = 1.0 / a[c][c];
    for (int j = 0; j < 8; ++j) a[c][j] *= inv;
    for (int r = 0; r < 4; ++r) {
      if (r == c || a[r][c] == 0) continue;
      double f = a[r][c];
      for (int j = 0; j < 8; ++j) a[r][j] -= f * a[c][j];
    }
  }
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = a[i][j + 4];
  for (auto& row : r.m)
    for (double v : row)
      if (!std::isfinite(v)) return std::nullopt;
  return r;
}

Transform::Transform(const Matrix4& m) : m_(m) {
  auto inv = m.Inverse();
  if (!inv) throw std::invalid_argument("transform matrix is singular");
  inv_ = *inv;
}

Transform Transform::Translate(const Vec3d& d) {
  Matrix4 m = Matrix4::Identity(), inv = Matrix4::Identity();
  for (int i = 0; i < 3; ++i) {
    m.m[i][3] = d[i];
    inv.m[i][3] = -d[i];
  }
  return Transform(m, inv);
}

Transform Transform::Scale(const Vec3d& s) {
  if (s.x == 0 || s.y == 0 || s.z == 0) throw std::invalid_argument("scale factor of zero");
  Matrix4 m = Matrix4::Identity(), inv = Matrix4::Identity();
  for (int i = 0; i < 3; ++i) {
    m.m[i][i] = s[i];
    inv.m[i][i] = 1 / s[i];
  }
  return Transform(m, inv);
}

Transform Transform::Rotate(double angle_deg, Vec3d axis) {
  double len = std::sqrt(Dot(axis, axis));
  if (!(len > 0)) throw std::invalid_argument("rotation axis of zero length");
  axis = axis / len;
  double t = angle_deg * M_PI / 180.0, s = std::sin(t), c = std::cos(t);
  // Quarter turns exactly (sin and cos of pi/2 in double are 1 and 6e-17): a wall or floor
  // turned by 90 degrees stays exactly axis-aligned.
  if (double q = angle_deg / 90; q == std::round(q) && std::abs(q) < 1e9) {
    static constexpr double kSin[4] = {0, 1, 0, -1};
    int k = int(std::fmod(q, 4.0) + 4) % 4;
    s = kSin[k], c = kSin[(k + 1) % 4];
  }
  Matrix4 m = Matrix4::Identity();
  // Rodrigues' rotation formula as a matrix.
  m.m[0][0] = axis.x * axis.x + (1 - axis.x * axis.x) * c;
  m.m[0][1] = axis.x * axis.y * (1 - c) - axis.z * s;
  m.m[0][2] = axis.x * axis.z * (1 - c) + axis.y * s;
  m.m[1][0] = axis.x * axis.y * (1 - c) + axis.z * s;
  m.m[1][1] = axis.y * axis.y + (1 - axis.y * axis.y) * c;
  m.m[1][2] = axis.y * axis.z * (1 - c) - axis.x * s;
  m.m[2][0] = axis.x * axis.z * (1 - c) - axis.y * s;
  m.m[2][1] = axis.y * axis.z * (1 - c) + axis.x * s;
  m.m[2][2] = axis.z * axis.z + (1 - axis.z * axis.z) * c;
  return Transform(m, m.Transposed());
}

Transform Transform::LookAt(const Vec3d& origin, const Vec3d& target, const Vec3d& up) {
  Vec3d dir = target - origin;
  double dl = std::sqrt(Dot(dir, dir));
  if (!(dl > 0)) throw std::invalid_argument("lookat: origin and target coincide");
  dir = dir / dl;
  Vec3d left = Cross(up, dir);
  double ll = std::sqrt(Dot(left, left));
  if (!(ll > 1e-12)) throw std::invalid_argument("lookat: up vector is parallel to the view direction");
  left = left / ll;
  Vec3d new_up = Cross(dir, left);
  Matrix4 m = Matrix4::Identity();
  for (int i = 0; i < 3; ++i) {
    m.m[i][0] = left[i];
    m.m[i][1] = new_up[i];
    m.m[i][2] = dir[i];
    m.m[i][3] = origin[i];
  }
  return Transform(m);
}

bool Transform::SwapsHandedness() const {
  const auto& a = m_.m;
  double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
               a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  return det < 0;
}

Vec3d Transform::Vector(const Vec3d& v) const {
  const auto& a = m_.m;
  return {a[0][0] * v.x + a[0][1] * v.y + a[0][2] * v.z, a[1][0] * v.x + a[1][1] * v.y + a[1][2] * v.z,
          a[2][0] * v.x + a[2][1] * v.y + a[2][2] * v.z};
}

Vec3d Transform::Point(const Vec3d& p) const {
  const auto& a = m_.m;
  double x = a[0][0] * p.x + a[0][1] * p.y + a[0][2] * p.z + a[0][3];
  double y = a[1][0] * p.x + a[1][1] * p.y + a[1][2] * p.z + a[1][3];
  double z = a[2][0] * p.x + a[2][1] * p.y + a[2][2] * p.z + a[2][3];
  double w = a[3][0] * p.x + a[3][1] * p.y + a[3][2] * p.z + a[3][3];
  return w == 1 ? Vec3d(x, y, z) : Vec3d(x, y, z) / w;
}

Vec3f Transform::Point(const Vec3f& p) const { return Vec3f(Point(Vec3d(p))); }

Vec3f Transform::Vector(const Vec3f& v) const {
  const auto& a = m_.m;
  return Vec3f(float(a[0][0] * v.x + a[0][1] * v.y + a[0][2] * v.z),
               float(a[1][0] * v.x + a[1][1] * v.y + a[1][2] * v.z),
               float(a[2][0] * v.x + a[2][1] * v.y + a[2][2] * v.z));
}

Vec3f Transform::Normal(const Vec3f& n) const {
  const auto& a = inv_.m;  // transpose of the inverse
  return Vec3f(float(a[0][0] * n.x + a[1][0] * n.y + a[2][0] * n.z),
               float(a[0][1] * n.x + a[1][1] * n.y + a[2][1] * n.z),
               float(a[0][2] * n.x + a[1][2] * n.y + a[2][2] * n.z));
}

}  // namespace objektiv
