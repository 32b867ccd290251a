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
  // The squares' mean over one division: (a^2 D^2 + b^2 C^2) / (2 C^2 D^2) with r_parallel =
  // a / C, r_perpendicular = b / D (a third of the lens tracer's ghost paths' time went to
  // the divisions). Past the range of T (an index beyond about 1e9 in single precision, which a
  // scene may give), the two quotients.
  T a = eta * cos_i - cos_t, big_c = eta * cos_i + cos_t;
  T b = cos_i - eta * cos_t, big_d = cos_i + eta * cos_t;
  T c2 = big_c * big_c, d2 = big_d * big_d;
  T r = (a * a * d2 + b * b * c2) / (2 * c2 * d2);
  if (std::isfinite(r)) return r;
  return ((a / big_c) * (a / big_c) + (b / big_d) * (b / big_d)) / 2;
}

}  // namespace objektiv
