#include "base/rgb_to_spectrum.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace objektiv {

// The table, embedded by the build: [3 max-component][res z][res y][res x][3 coefficients].
extern "C" const float objektiv_rgb_table_rec709[];

float SigmoidPolynomial::MaxValue() const {
  float m = std::max((*this)(360.f), (*this)(830.f));
  if (c0 != 0) {
    float t = -c1 / (2 * c0);
    if (t >= 0 && t <= 1) m = std::max(m, (*this)(360.f + 470.f * t));
  }
  return m;
}

SigmoidPolynomial RgbToSigmoid(Vec3f rgb) {
  static const std::array<float, kRgbTableRes> zs = [] {
    std::array<float, kRgbTableRes> z{};
    for (int i = 0; i < kRgbTableRes; ++i) z[i] = RgbTableZ(i);
    return z;
  }();
  // A NaN (a texture looked up at a NaN coordinate, Inf / Inf) stays NaN in every sample
  // rather than indexing the table with it.
  if (std::isnan(rgb.x) || std::isnan(rgb.y) || std::isnan(rgb.z)) return {0, 0, NAN};
  rgb = Vec3f(Clamp(rgb.x, 0, 1), Clamp(rgb.y, 0, 1), Clamp(rgb.z, 0, 1));
  // Grey: the constant sigmoid, solved in closed form.
  if (rgb.x == rgb.y && rgb.y == rgb.z) {
    float v = rgb.x;
    if (v <= 0) return {0, 0, -INFINITY};
    if (v >= 1) return {0, 0, INFINITY};
    return {0, 0, (v - 0.5f) / std::sqrt(v * (1 - v))};
  }
  int l = (rgb.x > rgb.y) ? (rgb.x > rgb.z ? 0 : 2) : (rgb.y > rgb.z ? 1 : 2);
  float z = rgb[l];
  float x = rgb[(l + 1) % 3] * (kRgbTableRes - 1) / z;
  float y = rgb[(l + 2) % 3] * (kRgbTableRes - 1) / z;
  int xi = std::min(int(x), kRgbTableRes - 2), yi = std::min(int(y), kRgbTableRes - 2);
  int zi = int(std::upper_bound(zs.begin(), zs.end(), z) - zs.begin()) - 1;
  zi = std::clamp(zi, 0, kRgbTableRes - 2);
  float dx = x - xi, dy = y - yi, dz = (z - zs[zi]) / (zs[zi + 1] - zs[zi]);
  const int r = kRgbTableRes;
  auto at = [&](int zz, int yy, int xx, int c) {
    return objektiv_rgb_table_rec709[((((size_t(l) * r + zz) * r + yy) * r + xx) * 3) + c];
  };
  float c[3];
  for (int k = 0; k < 3; ++k) {
    auto lerp_x = [&](int zz, int yy) { return Lerp(dx, at(zz, yy, xi, k), at(zz, yy, xi + 1, k)); };
    auto lerp_y = [&](int zz) { return Lerp(dy, lerp_x(zz, yi), lerp_x(zz, yi + 1)); };
    c[k] = Lerp(dz, lerp_y(zi), lerp_y(zi + 1));
  }
  return {c[0], c[1], c[2]};
}

}  // namespace objektiv
