#include "optics/form_error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/rng.h"

namespace objektiv {

namespace {
constexpr int kStride = FormError::kDegree + 1;
}

FormError::FormError(double peak_to_valley, uint64_t seed, double radius)
    : peak_to_valley_(peak_to_valley), radius_(radius), seed_(seed), coef_(kStride * kStride, 0.0) {
  if (!(peak_to_valley > 0) || !(radius > 0)) throw std::invalid_argument("FormError: positive peak-to-valley and radius");
  PCG32 rng(0x6f726d6572726f72ull, seed);  // "ormerror"
  auto normal = [&] {
    const double u1 = (rng.Uniform32() + 1.0) * 0x1p-32, u2 = rng.Uniform32() * 0x1p-32;  // u1 in (0, 1]
    return std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);
  };
  for (int n = 2; n <= kDegree; ++n)
    for (int i = 0; i <= n; ++i) coef_[size_t(i * kStride + (n - i))] = normal() / double(n * n);
  // Scale to the peak-to-valley over the unit disc (in u, v: the radius is applied in Height).
  double lo = INFINITY, hi = -INFINITY;
  const double saved_radius = radius_;
  radius_ = 1;
  for (int a = 0; a <= 200; ++a)
    for (int b = 0; b <= 200; ++b) {
      const double u = -1 + a / 100.0, v = -1 + b / 100.0;
      if (u * u + v * v > 1) continue;
      const double e = Height(u, v);
      lo = std::min(lo, e), hi = std::max(hi, e);
    }
  radius_ = saved_radius;
  const double scale = peak_to_valley / (hi - lo);
  for (double& c : coef_) c *= scale;
}

double FormError::Height(double x, double y, double* gx, double* gy) const {
  const double u = x / radius_, v = y / radius_;
  // Powers of u and v, then the sum and its partial derivatives.
  double pu[kStride], pv[kStride];
  pu[0] = pv[0] = 1;
  for (int k = 1; k < kStride; ++k) pu[k] = pu[k - 1] * u, pv[k] = pv[k - 1] * v;
  double e = 0, du = 0, dv = 0;
  for (int i = 0; i <= kDegree; ++i)
    for (int j = 0; i + j <= kDegree; ++j) {
      const double a = coef_[size_t(i * kStride + j)];
      if (a == 0) continue;
      e += a * pu[i] * pv[j];
      if (i > 0) du += a * i * pu[i - 1] * pv[j];
      if (j > 0) dv += a * j * pu[i] * pv[j - 1];
    }
  if (gx) *gx = du / radius_, *gy = dv / radius_;
  return e;
}

}  // namespace objektiv
