// The rough coat's reflectance, integrated once per material by sampling visible normals:
// with m drawn from the visible normals of wo (density D_wo(m) = G1(wo) D(m) |wo.m| / wo.z)
// and wi = reflect(wo, m), the estimator of int f_r cos(theta_i) dw_i for
// f_r = F D G / (4 cos_o cos_i) is F(wo.m) G(wo, wi) / G1(wo), which varies little, so a
// 256 x 256 grid of stratified samples gives R to a few 1e-4 (64 x 64 left errors of 3e-3 where
// a sharp lobe meets grazing light).
#include "scene/rough_coat.h"

#include <algorithm>
#include <cmath>

#include "scene/fresnel.h"

namespace objektiv {

namespace {

constexpr int kTableSize = 96;
constexpr int kGrid = 256;

float NodeMu(int i) { return Sqr(float(i) / (kTableSize - 1)); }

float IntegrateReflectance(const TrowbridgeReitz& d, float eta, float mu) {
  mu = std::max(mu, 1e-4f);
  const Vec3f wo(std::sqrt(std::max(0.f, 1 - mu * mu)), 0, mu);
  const float g1 = d.G1(wo);
  double sum = 0;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const Vec2f u((i + 0.5f) / kGrid, (j + 0.5f) / kGrid);
      const Vec3f wm = d.SampleVisible(wo, u);
      const Vec3f wi = Reflect(wo, wm);
      if (wi.z <= 0) continue;
      sum += FresnelDielectric(Dot(wo, wm), eta) * d.G(wo, wi) / g1;
    }
  return float(sum / (kGrid * kGrid));
}

}  // namespace

RoughCoat::RoughCoat(float alpha, float eta) : distrib_(alpha, alpha), eta_(eta), table_(kTableSize) {
  for (int i = 0; i < kTableSize; ++i) table_[i] = IntegrateReflectance(distrib_, eta_, NodeMu(i));
  // (1/eta^2) 2 int T(mu) mu dmu by the midpoint rule over the interpolated table.
  const int n = 4096;
  double s = 0;
  for (int i = 0; i < n; ++i) {
    const float mu = (i + 0.5f) / n;
    s += Transmittance(mu) * mu;
  }
  internal_reflectance_ = float(1 - 2 * s / n / (double(eta_) * eta_));
}

float RoughCoat::Reflectance(float mu) const {
  const float x = std::sqrt(std::clamp(mu, 0.f, 1.f)) * (kTableSize - 1);
  const int i = std::min(int(x), kTableSize - 2);
  const float t = x - i;
  return table_[i] * (1 - t) + table_[i + 1] * t;
}

}  // namespace objektiv
