// The Fresnel reflectance of a dielectric interface for unpolarised light, the one
// implementation the renderer's materials (in single precision) and the lens tracer (in
// double) share; the batch lens tracer's vectorised copy is tested against it.
//
// eta = n_transmitted / n_incident for light arriving from the side the normal points to
// (cos_i > 0); cos_i < 0 means the light arrives from the other side, where the relative
// index is 1 / eta. With cos_t from Snell's law, r_parallel = (eta cos_i - cos_t) /
// (eta cos_i + cos_t), r_perpendicular = (cos_i - eta cos_t) / (cos_i + eta cos_t), and the
// reflectance is their squares' mean; 1 at total internal reflection.
#pragma once
#include <algorithm>
#include <cmath>

namespace objektiv {

template <typename T>
T FresnelDielectric(T cos_i, T eta) {
  cos_i = std::min(std::max(cos_i, T(-1)), T(1));
  if (cos_i < 0) {
    eta = 1 / eta;
    cos_i = -cos_i;
  }
  T sin2_i = 1 - cos_i * cos_i;
  T sin2_t = sin2_i / (eta * eta);
  if (sin2_t >= 1) return T(1);
  T cos_t = std::sqrt(std::max(T(0), 1 - sin2_t));
  T r_parl = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  T r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return (r_parl * r_parl + r_perp * r_perp) / 2;
}

}  // namespace objektiv
