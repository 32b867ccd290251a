// The principled BSDF (scene/principled_bxdf.h): its sampling matches its density (chi-square)
// for a metal, a plastic, clearcoat with sheen, a glass and an anisotropic sheen; it reflects
// reciprocally; its albedo is at most one over a grid of parameters and angles; and it
// reduces exactly to the project's rough dielectric (spec_trans 1), to a rough conductor of
// reflectance 1 (metallic 1, white), and to Disney's diffuse (no specular).
#include <gtest/gtest.h>

#include <cstdio>

#include <fmt/format.h>

#include "chi2.h"
#include "sanitizer_build.h"
#include "base/sampling.h"
#include "scene/bsdf.h"
#include "scene/fresnel.h"

namespace objektiv {
namespace {

constexpr double kAlpha = 1e-3;

const PrincipledTables& Tables15() {
  static const PrincipledTables t(1.5f);
  return t;
}

PrincipledBxDF Make(float roughness, float metallic, SampledSpectrum base = SampledSpectrum(0.8f),
                    const PrincipledTables& tables = Tables15()) {
  PrincipledBxDF b;
  b.tables = &tables;
  b.base = base;
  b.tint = SampledSpectrum(1.f);
  b.roughness = roughness;
  b.metallic = metallic;
  b.Prepare();
  return b;
}

// A colour that is not grey, and its tint (base / a luminance of 0.5).
SampledSpectrum Orange() {
  SampledSpectrum s;
  const float v[4] = {0.9f, 0.6f, 0.3f, 0.1f};
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = v[i % 4];
  return s;
}

struct Case {
  const char* name;
  PrincipledBxDF b;
};

std::vector<Case> Cases() {
  std::vector<Case> c;
  c.push_back({"metal", Make(0.4f, 1, Orange())});
  PrincipledBxDF plastic = Make(0.5f, 0, Orange());
  plastic.spec_tint = 0.5f;
  plastic.tint = Orange() * 2.f;
  for (int i = 0; i < kSpectrumSamples; ++i) plastic.tint[i] = std::min(1.f, plastic.tint[i]);
  c.push_back({"plastic, tinted", plastic});
  PrincipledBxDF coat = Make(0.6f, 0.2f);
  coat.clearcoat = 1;
  coat.clearcoat_gloss = 0.5f;
  coat.sheen = 1;
  coat.sheen_tint = 0.5f;
  c.push_back({"clearcoat and sheen", coat});
  PrincipledBxDF glass = Make(0.35f, 0, SampledSpectrum(0.9f));
  glass.spec_trans = 0.9f;
  glass.Prepare();
  c.push_back({"glass", glass});
  PrincipledBxDF aniso = Make(0.5f, 0.5f, Orange());
  aniso.anisotropic = 0.8f;
  aniso.sheen = 0.5f;
  aniso.Prepare();
  c.push_back({"anisotropic", aniso});
  PrincipledBxDF full = glass;
  full.sample_visible = false;
  full.clearcoat = 0.5f;
  full.spec_trans = 0.5f;
  c.push_back({"half glass, clearcoat, sampling D cos", full});
  return c;
}

std::vector<Vec3f> Outgoing(bool both_sides) {
  std::vector<Vec3f> w;
  for (float deg : {10.f, 50.f, 80.f}) {
    const float t = Radians(deg);
    w.push_back(Normalize(Vec3f(std::sin(t), 0.3f * std::sin(t), std::cos(t))));
    if (both_sides) w.push_back(Normalize(Vec3f(std::sin(t), -0.2f * std::sin(t), -std::cos(t))));
  }
  return w;
}

TEST(BsdfPrincipled, SamplingMatchesPdf) {
  double worst = 1;
  for (const Case& c : Cases()) {
    const BSDF bsdf(Frame(), c.b, false);
    for (const Vec3f& wo : Outgoing(c.b.Transmits())) {
      auto sampler = [&](PCG32& g) -> std::optional<Vec3f> {
        const float uc = g.UniformFloat();
        const Vec2f u(g.UniformFloat(), g.UniformFloat());
        const auto s = bsdf.Sample(wo, uc, u);
        if (!s) return std::nullopt;
        return s->wi;
      };
      auto pdf = [&](const Vec3f& wi) { return double(bsdf.Pdf(wo, wi)); };
      const auto r = test::Chi2TestDirections(sampler, pdf, 100000, 16, 32);
      worst = std::min(worst, r.p_value);
      EXPECT_GT(r.p_value, kAlpha) << c.name << " wo.z=" << wo.z << ": " << r.Describe();
      EXPECT_LE(r.pdf_integral, 1.02) << c.name;
    }
  }
  std::printf("smallest chi-square p-value: %.3g\n", worst);
}

TEST(BsdfPrincipled, SampleReportsTheSameValueAndPdfAsEvaluation) {
  PCG32 g(5, 6);
  for (const Case& c : Cases()) {
    const BSDF bsdf(Frame(), c.b, false);
    for (const Vec3f& wo : Outgoing(true))
      for (int i = 0; i < 300; ++i) {
        const auto s = bsdf.Sample(wo, g.UniformFloat(), {g.UniformFloat(), g.UniformFloat()});
        if (!s) continue;
        const float pdf = bsdf.Pdf(wo, s->wi);
        EXPECT_NEAR(s->pdf, pdf, 2e-3f * pdf + 1e-5f) << c.name;
        const SampledSpectrum f = bsdf.f(wo, s->wi);
        for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_NEAR(s->f[k], f[k], 2e-3f * f[k] + 1e-5f) << c.name;
        EXPECT_EQ(s->IsTransmission(), s->wi.z * wo.z < 0) << c.name;
      }
  }
}

// Without spec_trans every lobe is a reflection and each scaling is a product of one function
// at wo and at wi, so f(wo, wi) = f(wi, wo). (Transmission is left out: like any refraction
// its radiance scales by 1/eta^2 one way and not the other, and its Fresnel and colour are
// those of the outside direction, as in Mitsuba.)
TEST(BsdfPrincipled, ReflectionIsReciprocal) {
  PCG32 g(9, 9);
  for (Case c : Cases()) {
    c.b.spec_trans = 0;
    c.b.Prepare();
    for (int i = 0; i < 500; ++i) {
      const Vec3f a = SampleUniformHemisphere({g.UniformFloat(), g.UniformFloat()});
      const Vec3f b = SampleUniformHemisphere({g.UniformFloat(), g.UniformFloat()});
      const SampledSpectrum fab = c.b.f(a, b, TransportMode::kRadiance), fba = c.b.f(b, a, TransportMode::kRadiance);
      for (int k = 0; k < kSpectrumSamples; ++k)
        EXPECT_NEAR(fab[k], fba[k], 1e-4f * std::max(fab[k], fba[k]) + 1e-6f) << c.name;
    }
  }
}

// The directional albedo, by sampling (importance transport: refraction unscaled), over a grid
// of every parameter at its ends (and a middle) and three angles, from both sides where light
// passes; the bound is 1 plus four standard errors of the estimate. A white base is the worst
// case for every lobe.
TEST(BsdfPrincipled, AlbedoIsAtMostOneForEveryParameter) {
  SKIP_UNDER_SANITIZERS("BsdfPrincipled.SampleReportsTheSameValueAndPdfAsEvaluation");
  static const PrincipledTables tables25(2.5f);
  PCG32 g(2, 3);
  double highest = 0;
  std::string where;
  const int n = 3000;
  for (const PrincipledTables* tables : {&Tables15(), &tables25})
    for (float metallic : {0.f, 0.5f, 1.f})
      for (float spec_trans : {0.f, 0.5f, 1.f})
        for (float roughness : {0.05f, 0.4f, 1.f})
          for (float sheen : {0.f, 1.f})
            for (float clearcoat : {0.f, 1.f})
              for (float spec_tint : {0.f, 1.f})
                for (float aniso : {0.f, 1.f}) {
                  PrincipledBxDF b = Make(roughness, metallic, SampledSpectrum(1.f), *tables);
                  b.spec_trans = spec_trans;
                  b.sheen = sheen;
                  b.sheen_tint = 1;
                  b.clearcoat = clearcoat;
                  b.clearcoat_gloss = 0.3f;
                  b.spec_tint = spec_tint;
                  b.anisotropic = aniso;
                  b.Prepare();
                  for (float mu : {0.03f, 0.4f, 1.f})
                    for (float side : {1.f, -1.f}) {
                      if (side < 0 && !b.Transmits()) continue;
                      const Vec3f wo(std::sqrt(1 - mu * mu), 0, side * mu);
                      double sum = 0, sum2 = 0;
                      for (int i = 0; i < n; ++i) {
                        // Stratified in the lobe choice and the first direction number.
                        const auto s = b.Sample(wo, (i + g.UniformFloat()) / n, {g.UniformFloat(), g.UniformFloat()},
                                                TransportMode::kImportance);
                        if (!s) continue;
                        const double v = s->f[0] * std::abs(s->wi.z) / s->pdf;
                        sum += v;
                        sum2 += v * v;
                      }
                      const double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
                      if (mean > highest) {
                        highest = mean;
                        where = fmt::format("eta {} metallic {} spec_trans {} roughness {} sheen {} clearcoat {} "
                                            "spec_tint {} anisotropic {} cos {} (se {:.4f})",
                                            tables->eta(), metallic, spec_trans, roughness, sheen, clearcoat, spec_tint,
                                            aniso, wo.z, se);
                      }
                      // (1e-5: float rounding, where every sample weighs the same, e.g. a
                      // smooth glass: F + (1 - F) = 1 with no spread at all.)
                      EXPECT_LE(mean, 1 + 4 * se + 1e-5) << "metallic " << metallic << " spec_trans " << spec_trans
                                                  << " roughness " << roughness << " sheen " << sheen << " clearcoat "
                                                  << clearcoat << " spec_tint " << spec_tint << " aniso " << aniso
                                                  << " cos " << wo.z;
                    }
                }
  std::printf("highest albedo %.4f at %s\n", highest, where.c_str());
}

// spec_trans 1 (metallic 0, no tint, no clearcoat): exactly the project's rough dielectric of
// the same eta and GGX roughness, in reflection and refraction, from both sides, both modes.
TEST(BsdfPrincipled, FullTransmissionIsTheRoughDielectric) {
  PrincipledBxDF p = Make(0.45f, 0, SampledSpectrum(1.f));
  p.spec_trans = 1;
  p.anisotropic = 0.5f;
  p.Prepare();
  DielectricBxDF d;
  d.eta = 1.5f;
  d.distrib = TrowbridgeReitz(p.alpha_x(), p.alpha_y());
  PCG32 g(4, 4);
  int nonzero = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3f wo = SampleUniformSphere({g.UniformFloat(), g.UniformFloat()});
    const Vec3f wi = SampleUniformSphere({g.UniformFloat(), g.UniformFloat()});
    for (TransportMode mode : {TransportMode::kRadiance, TransportMode::kImportance}) {
      const float a = p.f(wo, wi, mode)[0], b = d.f(wo, wi, mode)[0];
      EXPECT_NEAR(a, b, 1e-5f * b + 1e-7f) << "wo.z " << wo.z << " wi.z " << wi.z;
      nonzero += b > 0;
    }
  }
  EXPECT_GT(nonzero, 1500);
}

// metallic 1 with a white base: Schlick's F is 1, so the lobe is a rough conductor reflecting
// everything (complex index 1 + 1000i: reflectance 1 - 4e-6), with alpha_x = r^2 / a and
// alpha_y = r^2 a, a = sqrt(1 - 0.9 anisotropic).
TEST(BsdfPrincipled, WhiteMetalIsAPerfectlyReflectingRoughConductor) {
  const float r = 0.6f, aniso = 0.7f, a = std::sqrt(1 - 0.9f * aniso);
  PrincipledBxDF p = Make(r, 1, SampledSpectrum(1.f));
  p.anisotropic = aniso;
  p.Prepare();
  const ConductorBxDF c{SampledSpectrum(1.f), SampledSpectrum(1000.f), SampledSpectrum(1.f),
                        TrowbridgeReitz(r * r / a, r * r * a)};
  PCG32 g(7, 7);
  for (int i = 0; i < 2000; ++i) {
    const Vec3f wo = SampleUniformHemisphere({g.UniformFloat(), g.UniformFloat()});
    const Vec3f wi = SampleUniformHemisphere({g.UniformFloat(), g.UniformFloat()});
    const float x = p.f(wo, wi, TransportMode::kRadiance)[0], y = c.f(wo, wi)[0];
    EXPECT_NEAR(x, y, 1e-4f * y + 1e-7f);
    EXPECT_NEAR(p.Pdf(wo, wi, TransportMode::kRadiance), c.Pdf(wo, wi), 1e-4f * c.Pdf(wo, wi) + 1e-7f);
  }
}

// With eta -> 1 the dielectric specular vanishes (R0 = 6e-10 at eta 1.0001), leaving the
// diffuse: for roughness 0 Disney's base / pi (1 - Fi/2)(1 - Fo/2) exactly (its albedo is at
// most 1, so nothing is scaled); for roughness 1 Disney's retro-reflective form times
// s(mu_o) s(mu_i) <= 1, which is below 1 (its albedo exceeds 1 toward grazing) and a product:
// the ratio for (wo, wi) times that for (wi', wo') equals the ratio for (wo, wo') times that for
// (wi, wi') whatever the azimuths.
TEST(BsdfPrincipled, WithoutSpecularItIsDisneysDiffuse) {
  static const PrincipledTables tables(1.0001f);
  auto disney = [](const Vec3f& wo, const Vec3f& wi, float r) {
    const float Fo = std::pow(1 - wo.z, 5.f), Fi = std::pow(1 - wi.z, 5.f);
    const float cd = Dot(Normalize(wo + wi), wi), rr = 2 * r * cd * cd;
    return ((1 - Fi / 2) * (1 - Fo / 2) + rr * (Fo + Fi + Fo * Fi * (rr - 1))) / kPi;
  };
  PCG32 g(8, 8);
  for (float r : {0.f, 1.f}) {
    const PrincipledBxDF p = Make(r, 0, Orange(), tables);
    auto ratio = [&](const Vec3f& wo, const Vec3f& wi) {
      return p.f(wo, wi, TransportMode::kRadiance)[1] / (Orange()[1] * disney(wo, wi, r));
    };
    // Away from grazing angles, where even eta 1.0001 reflects (F -> 1 as cos -> 0) and the
    // specular's pass Ts (from the albedo tables) takes its share from the diffuse, and from
    // the (vanishing) specular peak, whose D can still amplify a tiny F.
    auto direction = [&]() {
      const float mu = 0.1f + 0.9f * g.UniformFloat(), phi = 2 * kPi * g.UniformFloat();
      const float s = std::sqrt(1 - mu * mu);
      return Vec3f(s * std::cos(phi), s * std::sin(phi), mu);
    };
    double lo = 1e9, hi = 0, worst_product = 0;
    for (int i = 0; i < 1000; ++i) {
      const Vec3f a = direction(), b = direction();
      if (Dot(Reflect(a, Vec3f(0, 0, 1)), b) > 0.9f) continue;
      const double q = ratio(a, b);
      lo = std::min(lo, q);
      hi = std::max(hi, q);
      // Other azimuths at the same polar angles.
      const Vec3f a2(-a.y, a.x, a.z), b2(b.y, -b.x, b.z), a3(-a.x, -a.y, a.z), b3(-b.x, -b.y, b.z);
      if (Dot(Reflect(a2, Vec3f(0, 0, 1)), b2) > 0.9f || Dot(Reflect(a, Vec3f(0, 0, 1)), a3) > 0.9f ||
          Dot(Reflect(b, Vec3f(0, 0, 1)), b3) > 0.9f)
        continue;
      worst_product = std::max(worst_product, std::abs(q * ratio(a2, b2) / (ratio(a, a3) * ratio(b, b3)) - 1));
    }
    std::printf("roughness %g: f / Disney in [%.5f, %.5f], product form to %.2g\n", r, lo, hi, worst_product);
    EXPECT_LT(worst_product, 2e-3) << r;
    if (r == 0) {
      EXPECT_NEAR(lo, 1, 2e-3);
      EXPECT_NEAR(hi, 1, 2e-3);
    } else {
      EXPECT_LT(hi, 1.0005);
      EXPECT_LT(lo, 0.95);
    }
  }
}

}  // namespace
}  // namespace objektiv
