#include "scene/fresnel.h"

#include <cmath>

namespace objektiv {

float FresnelComplex(float cos_i, std::complex<float> eta) {
  using C = std::complex<float>;
  cos_i = Clamp(cos_i, 0, 1);
  float sin2_i = 1 - cos_i * cos_i;
  C sin2_t = C(sin2_i) / (eta * eta);
  C cos_t = std::sqrt(C(1) - sin2_t);
  C r_parl = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  C r_perp = (C(cos_i) - eta * cos_t) / (C(cos_i) + eta * cos_t);
  return (std::norm(r_parl) + std::norm(r_perp)) / 2;
}

SampledSpectrum FresnelComplex(float cos_i, const SampledSpectrum& eta, const SampledSpectrum& k) {
  // The same equations in real arithmetic (no complex square roots or divisions): with
  // a^2 + b^2 = |eta_c^2 - sin^2|, a = Re sqrt(eta_c^2 - sin^2), for eta_c = eta + i k,
  //   Rs = (a^2 + b^2 + cos^2 - 2 a cos) / (a^2 + b^2 + cos^2 + 2 a cos)
  //   Rp = Rs (cos^2 (a^2 + b^2) + sin^4 - 2 a cos sin^2) / (cos^2 (a^2 + b^2) + sin^4 + 2 a cos sin^2).
  cos_i = Clamp(cos_i, 0, 1);
  float cos2 = cos_i * cos_i, sin2 = 1 - cos2;
  SampledSpectrum r;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    float eta2 = eta[i] * eta[i], k2 = k[i] * k[i];
    float t0 = eta2 - k2 - sin2;
    float a2b2 = std::sqrt(t0 * t0 + 4 * eta2 * k2);
    float a = SafeSqrt(0.5f * (a2b2 + t0));
    float t1 = a2b2 + cos2, t2 = 2 * cos_i * a;
    float rs = (t1 - t2) / (t1 + t2);
    float t3 = cos2 * a2b2 + sin2 * sin2, t4 = t2 * sin2;
    float rp = rs * (t3 - t4) / (t3 + t4);
    r[i] = t1 + t2 > 0 ? 0.5f * (rp + rs) : 1.f;
  }
  return r;
}

bool Refract(const Vec3f& wi, Vec3f n, float eta, float* etap, Vec3f* wt) {
  float cos_i = Dot(n, wi);
  if (cos_i < 0) {
    eta = 1 / eta;
    cos_i = -cos_i;
    n = -n;
  }
  float sin2_i = std::max(0.f, 1 - cos_i * cos_i);
  float sin2_t = sin2_i / (eta * eta);
  if (sin2_t >= 1) return false;
  float cos_t = SafeSqrt(1 - sin2_t);
  *wt = -wi / eta + n * (cos_i / eta - cos_t);
  if (etap) *etap = eta;
  return true;
}

float FresnelDiffuseReflectance(float eta) {
  // Midpoint rule in mu = cos(theta); F is smooth except at the critical angle.
  const int n = 2048;
  double s = 0;
  for (int i = 0; i < n; ++i) {
    float mu = (i + 0.5f) / n;
    s += FresnelDielectric(mu, eta) * mu;
  }
  return float(2 * s / n);
}

}  // namespace objektiv
