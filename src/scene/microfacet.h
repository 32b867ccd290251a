// The Trowbridge-Reitz (GGX) microfacet distribution with visible-normal sampling
// (Heitz 2018, "Sampling the GGX Distribution of Visible Normals"). Local frame, z = normal.
#pragma once
#include "base/vec.h"

namespace objektiv {

class TrowbridgeReitz {
 public:
  TrowbridgeReitz() = default;
  TrowbridgeReitz(float alpha_x, float alpha_y) : ax_(std::max(alpha_x, 1e-4f)), ay_(std::max(alpha_y, 1e-4f)) {}

  // Below this roughness the surface is treated as perfectly smooth (a delta lobe).
  bool EffectivelySmooth() const { return std::max(ax_, ay_) < 1e-3f; }

  float D(const Vec3f& wm) const {
    float tan2 = Tan2Theta(wm);
    if (std::isinf(tan2) || std::isnan(tan2)) return 0;
    float cos4 = Sqr(Cos2Theta(wm));
    if (cos4 < 1e-16f) return 0;
    float e = (Sqr(wm.x / ax_) + Sqr(wm.y / ay_)) / Cos2Theta(wm);
    return 1 / (kPi * ax_ * ay_ * cos4 * Sqr(1 + e));
  }
  float Lambda(const Vec3f& w) const {
    float tan2 = Tan2Theta(w);
    if (std::isinf(tan2) || std::isnan(tan2)) return 0;
    float sin2 = Sin2Theta(w);
    float alpha2 = sin2 > 0 ? (Sqr(w.x * ax_) + Sqr(w.y * ay_)) / sin2 : ax_ * ay_;
    return (std::sqrt(1 + alpha2 * tan2) - 1) / 2;
  }
  float G1(const Vec3f& w) const { return 1 / (1 + Lambda(w)); }
  float G(const Vec3f& wo, const Vec3f& wi) const { return 1 / (1 + Lambda(wo) + Lambda(wi)); }
  // Density of visible normals from direction w.
  float D(const Vec3f& w, const Vec3f& wm) const {
    return G1(w) / AbsCosTheta(w) * D(wm) * std::abs(Dot(w, wm));
  }
  float PdfVisible(const Vec3f& w, const Vec3f& wm) const { return D(w, wm); }

  Vec3f SampleVisible(Vec3f w, Vec2f u) const;

 private:
  float ax_ = 1e-4f, ay_ = 1e-4f;
};

}  // namespace objektiv
