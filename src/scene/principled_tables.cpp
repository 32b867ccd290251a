// The principled BSDF's albedo tables (see the header): stratified grids of samples per node,
// bilinear interpolation between nodes spaced in sqrt(mu) (denser toward grazing, where the
// albedos change fastest) and in sqrt(alpha / 3.2).
#include "scene/principled_tables.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <mutex>

#include "base/fresnel_dielectric.h"
#include "base/sampling.h"
#include "scene/microfacet.h"
#include "scene/principled_bxdf.h"

namespace objektiv {

namespace {

constexpr int kMu = 32, kAlpha = 24, kGloss = 16, kRough = 17;
constexpr float kAlphaMax = 3.2f;
constexpr int kQuadratureSide = 48;  // kQuadratureSide^2 samples per node

float MuNode(int i) { return Sqr(float(i) / (kMu - 1)); }
float AlphaNode(int j) { return std::max(1e-4f, kAlphaMax * Sqr(float(j) / (kAlpha - 1))); }
Vec3f Outgoing(float mu) {
  mu = std::max(mu, 1e-4f);
  return Vec3f(std::sqrt(std::max(0.f, 1 - mu * mu)), 0, mu);
}

// Bilinear lookup in a table [row][mu node]; x in [0, 1] picks the row continuously.
float Lookup(const std::vector<float>& t, int rows, float row_x, float mu) {
  const float xm = std::sqrt(std::clamp(mu, 0.f, 1.f)) * (kMu - 1);
  const int i = std::min(int(xm), kMu - 2);
  const float fi = xm - i;
  const float xr = std::clamp(row_x, 0.f, 1.f) * (rows - 1);
  const int j = std::min(int(xr), rows - 2);
  const float fj = xr - j;
  auto at = [&](int r, int c) { return t[size_t(r) * kMu + c]; };
  return (1 - fj) * ((1 - fi) * at(j, i) + fi * at(j, i + 1)) + fj * ((1 - fi) * at(j + 1, i) + fi * at(j + 1, i + 1));
}

// The mean of F(wo.m) G / G1 over visible normals, for three F at once: the exact dielectric
// (eta > 0; skipped where eta = 0), Schlick's scale and bias parts.
std::array<float, 3> GgxAlbedos(float mu, float alpha, float eta) {
  const TrowbridgeReitz d(alpha, alpha);
  const Vec3f wo = Outgoing(mu);
  const float g1 = d.G1(wo);
  double diel = 0, scale = 0, bias = 0;
  for (int i = 0; i < kQuadratureSide; ++i)
    for (int j = 0; j < kQuadratureSide; ++j) {
      const Vec3f m = d.SampleVisible(wo, Vec2f((i + 0.5f) / kQuadratureSide, (j + 0.5f) / kQuadratureSide));
      const Vec3f wi = Reflect(wo, m);
      if (wi.z <= 0) continue;
      const float c = Dot(wo, m), g = d.G(wo, wi) / g1, w = principled::SchlickWeight(c);
      if (eta > 0) diel += FresnelDielectric(c, eta) * g;
      scale += (1 - w) * g;
      bias += w * g;
    }
  const double n = double(kQuadratureSide) * kQuadratureSide;
  return {float(diel / n), float(scale / n), float(bias / n)};
}

struct GlobalTables {
  std::vector<float> scale, bias, clearcoat, diffuse, sheen;

  GlobalTables()
      : scale(size_t(kAlpha) * kMu), bias(size_t(kAlpha) * kMu), clearcoat(size_t(kGloss) * kMu),
        diffuse(size_t(kRough) * kMu), sheen(2 * kMu) {
    for (int j = 0; j < kAlpha; ++j)
      for (int i = 0; i < kMu; ++i) {
        const std::array<float, 3> a = GgxAlbedos(MuNode(i), AlphaNode(j), 0);
        scale[size_t(j) * kMu + i] = a[1];
        bias[size_t(j) * kMu + i] = a[2];
      }
    for (int j = 0; j < kGloss; ++j)
      for (int i = 0; i < kMu; ++i) clearcoat[size_t(j) * kMu + i] = Clearcoat(MuNode(i), float(j) / (kGloss - 1));
    // The albedos of the white diffuse (every roughness node at once) and of the sheen, by
    // cosine sampling (the estimator is pi f).
    for (int i = 0; i < kMu; ++i) {
      const Vec3f wo = Outgoing(MuNode(i));
      std::array<double, kRough> d{};
      double s = 0;
      for (int a = 0; a < kQuadratureSide; ++a)
        for (int b = 0; b < kQuadratureSide; ++b) {
          const Vec3f wi = SampleCosineHemisphere(Vec2f((a + 0.5f) / kQuadratureSide, (b + 0.5f) / kQuadratureSide));
          if (wi.z <= 0) continue;
          for (int r = 0; r < kRough; ++r) d[r] += principled::DisneyDiffuse(wo, wi, float(r) / (kRough - 1));
          s += kPi * principled::SheenWeight(wo, wi);
        }
      const double n = double(kQuadratureSide) * kQuadratureSide;
      for (int r = 0; r < kRough; ++r) diffuse[size_t(r) * kMu + i] = float(d[r] / n);
      sheen[i] = sheen[kMu + i] = float(s / n);  // two equal rows, for Lookup
    }
  }

  // The unit clearcoat lobe's albedo, sampled by GTR1's D cos: the estimator f cos_i / pdf is
  // F G_cc |wo.m| / (cos_o cos_m).
  static float Clearcoat(float mu, float gloss) {
    const float alpha = principled::ClearcoatAlpha(gloss);
    const Vec3f wo = Outgoing(mu);
    double sum = 0;
    for (int i = 0; i < kQuadratureSide; ++i)
      for (int j = 0; j < kQuadratureSide; ++j) {
        const Vec3f m = principled::Gtr1Sample(alpha, Vec2f((i + 0.5f) / kQuadratureSide, (j + 0.5f) / kQuadratureSide));
        const Vec3f wi = Reflect(wo, m);
        const float c = Dot(wo, m);
        if (wi.z <= 0 || c <= 0 || m.z <= 0) continue;
        const float F = 0.04f + 0.96f * principled::SchlickWeight(c);
        const float G = principled::SmithGgx1(wo, m, 0.25f) * principled::SmithGgx1(wi, m, 0.25f);
        sum += F * G * c / (wo.z * m.z);
      }
    return float(sum / (double(kQuadratureSide) * kQuadratureSide));
  }
};

const GlobalTables& Global() {
  static const GlobalTables tables;
  return tables;
}

float AlphaX(float alpha) { return std::sqrt(std::clamp(alpha / kAlphaMax, 0.f, 1.f)); }

}  // namespace

PrincipledTables::PrincipledTables(float eta) : eta_(eta), dielectric_(size_t(kAlpha) * kMu) {
  Global();
  for (int j = 0; j < kAlpha; ++j)
    for (int i = 0; i < kMu; ++i) dielectric_[size_t(j) * kMu + i] = GgxAlbedos(MuNode(i), AlphaNode(j), eta)[0];
}

std::shared_ptr<const PrincipledTables> PrincipledTables::For(float eta) {
  static std::mutex mutex;
  static std::map<float, std::weak_ptr<const PrincipledTables>> made;
  const std::lock_guard<std::mutex> lock(mutex);
  std::shared_ptr<const PrincipledTables> t = made[eta].lock();
  if (!t) made[eta] = t = std::make_shared<const PrincipledTables>(eta);
  return t;
}

float PrincipledTables::DielectricAlbedo(float mu, float alpha) const { return Lookup(dielectric_, kAlpha, AlphaX(alpha), mu); }
float PrincipledTables::SchlickScale(float mu, float alpha) const { return Lookup(Global().scale, kAlpha, AlphaX(alpha), mu); }
float PrincipledTables::SchlickBias(float mu, float alpha) const { return Lookup(Global().bias, kAlpha, AlphaX(alpha), mu); }
float PrincipledTables::ClearcoatAlbedo(float mu, float gloss) { return Lookup(Global().clearcoat, kGloss, gloss, mu); }

float PrincipledTables::DiffuseScale(float mu, float roughness, float sheen) {
  const GlobalTables& g = Global();
  // (Linear in the roughness, between nodes: the albedo is convex in it, so this overestimates.)
  const float albedo = Lookup(g.diffuse, kRough, roughness, mu) + std::max(sheen, 0.f) * Lookup(g.sheen, 2, 0, mu);
  return albedo > 1 ? 1 / albedo : 1.f;
}

}  // namespace objektiv
