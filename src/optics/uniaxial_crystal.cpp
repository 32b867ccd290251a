#include "optics/uniaxial_crystal.h"

#include <algorithm>
#include <cmath>

namespace objektiv {

double ExtraordinaryIndex(const Vec3d& k, const WaveMedium& m) {
  const double c = Dot(k, m.axis) / Length(k), s2 = std::max(0.0, 1 - c * c);
  return 1 / std::sqrt(c * c / (m.n * m.n) + s2 / (m.ne * m.ne));
}

Vec3d ExtraordinaryRay(const Vec3d& k, const WaveMedium& m) {
  const double ka = Dot(k, m.axis);
  const Vec3d s = m.axis * (ka / (m.n * m.n)) + (k - m.axis * ka) * (1 / (m.ne * m.ne));
  return s / Length(s);
}

Vec3d ExtraordinaryWaveNormal(const Vec3d& s, const WaveMedium& m) {
  const double sa = Dot(s, m.axis);
  const Vec3d k = m.axis * (sa * m.n * m.n) + (s - m.axis * sa) * (m.ne * m.ne);
  return k / Length(k);
}

Vec3d WaveVectorOf(const Vec3d& d, const WaveMedium& m) {
  if (!m.extraordinary) return d * m.n;
  const Vec3d k = ExtraordinaryWaveNormal(d, m);
  return k * ExtraordinaryIndex(k, m);
}

Vec3d RayDirectionOf(const Vec3d& k, const WaveMedium& m) {
  return m.extraordinary ? ExtraordinaryRay(k, m) : k / Length(k);
}

std::optional<Vec3d> WaveVectorInto(const Vec3d& tangential, const Vec3d& into, const WaveMedium& m) {
  const double t2 = Dot(tangential, tangential);
  if (!m.extraordinary) {
    const double b2 = m.n * m.n - t2;
    if (b2 < 0) return std::nullopt;
    return tangential + into * std::sqrt(b2);
  }
  // k = t + beta N in (k.a)^2 u + |k|^2 / n_e^2 = 1, u = 1 / n_o^2 - 1 / n_e^2: a quadratic
  // A beta^2 + B beta + C = 0 whose derivative 2 A beta + B is proportional to S.N, so the
  // larger root is the wave whose energy flows along N.
  const double u = 1 / (m.n * m.n) - 1 / (m.ne * m.ne), ie2 = 1 / (m.ne * m.ne);
  const double ta = Dot(tangential, m.axis), na = Dot(into, m.axis);
  const double a = na * na * u + ie2, b = 2 * ta * na * u, c = ta * ta * u + t2 * ie2 - 1;
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return std::nullopt;
  return tangential + into * ((-b + std::sqrt(disc)) / (2 * a));
}

}  // namespace objektiv
