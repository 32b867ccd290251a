// BSDFs: sampling matches the density each one reports (chi-square), the reported densities
// integrate to at most one, reflection is reciprocal, and no BSDF creates energy.
#include <gtest/gtest.h>

#include "chi2.h"
#include "base/sampling.h"
#include "sanitizer_build.h"
#include "scene/bsdf.h"
#include "scene/fresnel.h"

namespace objektiv {
namespace {

constexpr double kAlpha = 1e-3;

struct Case {
  const char* name;
  BSDF bsdf;
};

SampledSpectrum S(float v) { return SampledSpectrum(v); }

std::vector<Case> NonSpecularCases() {
  Frame f;
  std::vector<Case> c;
  c.push_back({"diffuse", BSDF(f, DiffuseBxDF{S(0.7f)}, false)});
  c.push_back({"diffuse two-sided", BSDF(f, DiffuseBxDF{S(0.7f)}, true)});
  ConductorBxDF rc{S(0.2f), S(3.f), S(1.f), TrowbridgeReitz(0.3f, 0.3f)};
  c.push_back({"rough conductor", BSDF(f, rc, false)});
  ConductorBxDF ac{S(1.2f), S(2.f), S(1.f), TrowbridgeReitz(0.1f, 0.5f)};
  c.push_back({"anisotropic rough conductor", BSDF(f, ac, false)});
  DielectricBxDF rd;
  rd.eta = 1.5f;
  rd.distrib = TrowbridgeReitz(0.25f, 0.25f);
  c.push_back({"rough dielectric", BSDF(f, rd, true)});
  rd.distrib = TrowbridgeReitz(0.6f, 0.6f);
  c.push_back({"very rough dielectric", BSDF(f, rd, true)});
  PlasticBxDF pl;
  pl.eta = 1.49f;
  pl.fdr_int = FresnelDiffuseReflectance(1 / 1.49f);
  pl.diffuse = S(0.5f);
  pl.specular = S(1.f);
  pl.specular_sampling_weight = 0.5f;
  c.push_back({"plastic (diffuse lobe)", BSDF(f, pl, false)});
  c.push_back({"phong", BSDF(f, PhongBxDF{S(0.5f), S(0.4f), 30}, false)});
  c.push_back({"phong, broad lobe", BSDF(f, PhongBxDF{S(0.3f), S(0.6f), 2}, false)});
  c.push_back({"phong, sharp lobe only", BSDF(f, PhongBxDF{S(0), S(0.9f), 300}, false)});
  static const RoughCoat coat_smooth(0.05f, 1.49f), coat_mid(0.3f, 1.5f), coat_rough(0.9f, 1.8f);
  RoughPlasticBxDF rp;
  rp.coat = &coat_mid;
  rp.diffuse = S(0.5f);
  c.push_back({"rough plastic", BSDF(f, rp, false)});
  rp.coat = &coat_smooth;
  rp.specular_sampling_weight = 0.7f;
  c.push_back({"rough plastic, nearly smooth coat", BSDF(f, rp, false)});
  rp.coat = &coat_rough;
  rp.diffuse = S(0.9f);
  rp.nonlinear = true;
  rp.specular_sampling_weight = 0.2f;
  c.push_back({"rough plastic, very rough, nonlinear", BSDF(f, rp, false)});
  c.push_back({"blend of rough conductor and diffuse", BSDF::Blend(f, BSDF(f, rc, false), BSDF(f, DiffuseBxDF{S(0.6f)}, false), 0.3f)});
  c.push_back({"blend of phong and rough plastic",
               BSDF::Blend(f, BSDF(f, PhongBxDF{S(0.2f), S(0.5f), 80}, false), BSDF(f, rp, false), 0.6f)});
  c.push_back({"blend of rough dielectric and two-sided diffuse",
               BSDF::Blend(f, BSDF(f, rd, true), BSDF(f, DiffuseBxDF{S(0.5f)}, true), 0.4f)});
  c.push_back({"blend of plastic and a blend", BSDF::Blend(f, BSDF(f, pl, false),
                                                           BSDF::Blend(f, BSDF(f, rc, false), BSDF(f, rp, false), 0.5f), 0.5f)});
  return c;
}

std::vector<Vec3f> Outgoing(bool both_sides) {
  std::vector<Vec3f> w;
  for (float deg : {5.f, 40.f, 75.f}) {
    float t = Radians(deg);
    w.push_back(Normalize(Vec3f(std::sin(t), 0.3f * std::sin(t), std::cos(t))));
    if (both_sides) w.push_back(Normalize(Vec3f(std::sin(t), -0.2f * std::sin(t), -std::cos(t))));
  }
  return w;
}

TEST(Bsdf, SamplingMatchesPdf) {
  for (const Case& c : NonSpecularCases()) {
    for (const Vec3f& wo : Outgoing(c.bsdf.Flags() & kTransmission)) {
      auto sampler = [&](PCG32& g) -> std::optional<Vec3f> {
        float uc = g.UniformFloat();
        Vec2f u(g.UniformFloat(), g.UniformFloat());
        auto s = c.bsdf.Sample(wo, uc, u);
        if (!s || s->IsSpecular()) return std::nullopt;
        return s->wi;
      };
      auto pdf = [&](const Vec3f& wi) { return double(c.bsdf.Pdf(wo, wi)); };
      auto r = test::Chi2TestDirections(sampler, pdf, 300000, 16, 32);
      EXPECT_GT(r.p_value, kAlpha) << c.name << " wo=(" << wo.x << "," << wo.y << "," << wo.z << "): " << r.Describe();
      EXPECT_LE(r.pdf_integral, 1.02) << c.name;
    }
  }
}

TEST(Bsdf, SampleReportsTheSameValueAndPdfAsEvaluation) {
  PCG32 g(5, 6);
  for (const Case& c : NonSpecularCases())
    for (const Vec3f& wo : Outgoing(true))
      for (int i = 0; i < 200; ++i) {
        auto s = c.bsdf.Sample(wo, g.UniformFloat(), {g.UniformFloat(), g.UniformFloat()});
        if (!s || s->IsSpecular()) continue;
        float pdf = c.bsdf.Pdf(wo, s->wi);
        EXPECT_NEAR(s->pdf, pdf, 2e-3f * pdf + 1e-5f) << c.name;
        SampledSpectrum f = c.bsdf.f(wo, s->wi);
        EXPECT_NEAR(s->f[0], f[0], 2e-3f * f[0] + 1e-5f) << c.name;
      }
}

TEST(Bsdf, ReflectionIsReciprocal) {
  PCG32 g(9, 9);
  for (const Case& c : NonSpecularCases())
    for (int i = 0; i < 500; ++i) {
      Vec3f a = SampleUniformHemisphere({g.UniformFloat(), g.UniformFloat()});
      Vec3f b = SampleUniformHemisphere({g.UniformFloat(), g.UniformFloat()});
      float fab = c.bsdf.f(a, b)[0], fba = c.bsdf.f(b, a)[0];
      EXPECT_NEAR(fab, fba, 1e-4f * std::max(fab, fba) + 1e-6f) << c.name;
    }
}

TEST(Bsdf, NoBsdfCreatesEnergy) {
  // Directional albedo by sampling (including specular parts) is at most one.
  Frame f;
  std::vector<Case> cases = NonSpecularCases();
  DielectricBxDF smooth;
  smooth.eta = 1.5f;
  cases.push_back({"smooth dielectric", BSDF(f, smooth, true)});
  ThinDielectricBxDF thin;
  thin.eta = S(1.7f);
  cases.push_back({"thin dielectric", BSDF(f, thin, true)});
  cases.push_back({"smooth conductor", BSDF(f, ConductorBxDF{S(0.2f), S(3.f), S(1.f), TrowbridgeReitz(0, 0)}, false)});
  PCG32 g(2, 3);
  for (const Case& c : cases)
    for (const Vec3f& wo : Outgoing(false)) {
      double sum = 0;
      const int n_samples = 100000;
      for (int i = 0; i < n_samples; ++i) {
        auto s = c.bsdf.Sample(wo, g.UniformFloat(), {g.UniformFloat(), g.UniformFloat()});
        if (!s) continue;
        // Radiance transport scales refraction by 1/eta^2; undo it to count energy.
        float scale = s->IsTransmission() ? Sqr(s->eta) : 1.f;
        sum += s->f[0] * std::abs(s->wi.z) / s->pdf * scale;
      }
      EXPECT_LE(sum / n_samples, 1.01) << c.name << " at cos " << wo.z;
    }
}

TEST(Bsdf, SmoothDielectricSplitsByFresnel) {
  DielectricBxDF d;
  d.eta = 1.5f;
  BSDF b(Frame(), d, true);
  Vec3f wo = Normalize(Vec3f(0.5f, 0, 1));
  float F = FresnelDielectric(wo.z, 1.5f);
  auto r = b.Sample(wo, 0.5f * F, {0.5f, 0.5f});
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->flags & kReflection);
  EXPECT_NEAR(r->wi.x, -wo.x, 1e-6);
  EXPECT_NEAR(r->pdf, F, 1e-5);
  auto t = b.Sample(wo, 0.5f + 0.5f * F, {0.5f, 0.5f});
  ASSERT_TRUE(t);
  EXPECT_TRUE(t->flags & kTransmission);
  EXPECT_NEAR(t->pdf, 1 - F, 1e-5);
  EXPECT_NEAR(std::sqrt(1 - wo.z * wo.z), 1.5f * std::sqrt(1 - t->wi.z * t->wi.z), 1e-5);
}

// The normalised Blinn-Phong lobe reflects exactly ks at normal incidence (its normalisation's
// closed form) and less elsewhere, whatever the exponent.
TEST(Bsdf, PhongLobeReflectsKsAtNormalIncidenceAndLessElsewhere) {
  for (float exponent : {1.f, 10.f, 100.f, 1000.f}) {
    const BSDF b(Frame(), PhongBxDF{S(0), S(0.8f), exponent}, false);
    PCG32 g(3, uint64_t(exponent));
    double previous = 1e9;
    for (float deg : {0.f, 30.f, 60.f, 85.f}) {
      const Vec3f wo(std::sin(Radians(deg)), 0, std::cos(Radians(deg)));
      double sum = 0, sum2 = 0;
      const int n = 200000;
      for (int i = 0; i < n; ++i) {
        auto s = b.Sample(wo, g.UniformFloat(), {g.UniformFloat(), g.UniformFloat()});
        const double v = s ? s->f[0] * std::abs(s->wi.z) / s->pdf : 0;
        sum += v;
        sum2 += v * v;
      }
      const double albedo = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - albedo * albedo) / n);
      if (deg == 0) {
        EXPECT_NEAR(albedo, 0.8, 4 * se + 1e-4) << "exponent " << exponent;
      }
      EXPECT_LE(albedo, 0.8 + 4 * se) << "exponent " << exponent << " at " << deg << " degrees";
      EXPECT_LT(albedo, previous + 4 * se) << "exponent " << exponent << " at " << deg << " degrees";
      previous = albedo;
    }
  }
}

// The delta lobes a Whitted tracer follows carry what sampling them carries (f |cos| of the
// sample), and a smooth dielectric's two add up to all the light (R + T = 1 before the 1/eta^2
// of radiance), with total internal reflection from inside beyond the critical angle.
TEST(Bsdf, SpecularLobesCarryFresnelsShares) {
  DielectricBxDF d;
  d.eta = 1.5f;
  const BSDF glass(Frame(), d, true);
  SpecularLobe lobes[kMaxSpecularLobes];
  for (float deg : {0.f, 30.f, 60.f, 89.f}) {
    const Vec3f wo(std::sin(Radians(deg)), 0, std::cos(Radians(deg)));
    ASSERT_EQ(glass.SpecularLobes(wo, lobes), 2) << deg;
    const float F = FresnelDielectric(wo.z, 1.5f);
    EXPECT_FALSE(lobes[0].transmission);
    EXPECT_NEAR(lobes[0].weight[0], F, 1e-6);
    EXPECT_NEAR(lobes[0].wi.x, -wo.x, 1e-6);
    EXPECT_TRUE(lobes[1].transmission);
    EXPECT_NEAR(lobes[1].weight[0] * 1.5f * 1.5f, 1 - F, 1e-5) << deg;  // radiance: T / eta^2 going in
    EXPECT_NEAR(std::sin(Radians(deg)), 1.5f * std::sqrt(1 - Sqr(lobes[1].wi.z)), 1e-5);
    // The same as sampling each lobe.
    auto t = glass.Sample(wo, 0.999f, {0.5f, 0.5f});
    ASSERT_TRUE(t);
    EXPECT_NEAR(t->f[0] * std::abs(t->wi.z), lobes[1].weight[0], 1e-5);
  }
  // From inside the glass: beyond asin(1/1.5) = 41.8 degrees all of it reflects.
  const Vec3f inside(std::sin(Radians(50.f)), 0, -std::cos(Radians(50.f)));
  ASSERT_EQ(glass.SpecularLobes(inside, lobes), 1);
  EXPECT_NEAR(lobes[0].weight[0], 1, 1e-6);
  EXPECT_LT(lobes[0].wi.z, 0);

  const SampledSpectrum eta = S(0.2f), k = S(3.f);
  const BSDF mirror(Frame(), ConductorBxDF{eta, k, S(1.f), TrowbridgeReitz(0, 0)}, false);
  const Vec3f wo = Normalize(Vec3f(0.3f, 0.2f, 1));
  ASSERT_EQ(mirror.SpecularLobes(wo, lobes), 1);
  EXPECT_NEAR(lobes[0].weight[0], FresnelComplex(wo.z, eta, k)[0], 1e-6);
  // Rough and diffuse surfaces have none; Phong has none.
  EXPECT_EQ(BSDF(Frame(), ConductorBxDF{eta, k, S(1.f), TrowbridgeReitz(0.3f, 0.3f)}, false).SpecularLobes(wo, lobes), 0);
  EXPECT_EQ(BSDF(Frame(), DiffuseBxDF{S(0.5f)}, false).SpecularLobes(wo, lobes), 0);
  EXPECT_EQ(BSDF(Frame(), PhongBxDF{S(0.5f), S(0.4f), 30}, false).SpecularLobes(wo, lobes), 0);
  // Plastic: its coat's reflection, and behind a one-sided plastic nothing.
  PlasticBxDF pl;
  pl.eta = 1.49f;
  pl.specular = S(0.9f);
  ASSERT_EQ(BSDF(Frame(), pl, false).SpecularLobes(wo, lobes), 1);
  EXPECT_NEAR(lobes[0].weight[0], 0.9f * FresnelDielectric(wo.z, 1.49f), 1e-6);
  EXPECT_EQ(BSDF(Frame(), pl, false).SpecularLobes(-wo, lobes), 0);
}

// A thin sheet reflects 2R / (1 + R) of Fresnel's R at each face and lets the rest through
// undeviated, from either side; sampling chooses by that share, and the lobes carry it.
TEST(Bsdf, ThinDielectricSumsTheReflectionsBetweenItsFaces) {
  ThinDielectricBxDF t;
  t.eta = S(1.5f);
  const BSDF sheet(Frame(), t, true);
  SpecularLobe lobes[kMaxSpecularLobes];
  for (float deg : {0.f, 40.f, 80.f})
    for (float side : {1.f, -1.f}) {
      const Vec3f wo(std::sin(Radians(deg)), 0, side * std::cos(Radians(deg)));
      const float R = FresnelDielectric(std::cos(Radians(deg)), 1.5f), sheet_R = 2 * R / (1 + R);
      auto r = sheet.Sample(wo, 0.5f * sheet_R, {0.5f, 0.5f});
      ASSERT_TRUE(r);
      EXPECT_TRUE(r->flags & kReflection);
      EXPECT_NEAR(r->pdf, sheet_R, 1e-6);
      EXPECT_NEAR(r->wi.z, wo.z, 1e-6);
      EXPECT_NEAR(r->f[0] * std::abs(r->wi.z) / r->pdf, 1, 1e-5);
      auto tr = sheet.Sample(wo, 0.5f + 0.5f * sheet_R, {0.5f, 0.5f});
      ASSERT_TRUE(tr);
      EXPECT_TRUE(tr->flags & kTransmission);
      EXPECT_NEAR(tr->wi.x, -wo.x, 1e-6);
      EXPECT_NEAR(tr->wi.z, -wo.z, 1e-6);
      EXPECT_NEAR(tr->pdf, 1 - sheet_R, 1e-6);
      ASSERT_EQ(sheet.SpecularLobes(wo, lobes), 2);
      EXPECT_NEAR(lobes[0].weight[0], sheet_R, 1e-6);
      EXPECT_NEAR(lobes[1].weight[0], 1 - sheet_R, 1e-6);
    }
}

TEST(Bsdf, DiffuseReflectanceIsTheDiffusePartsAlbedo) {
  const Vec3f wo = Normalize(Vec3f(0.3f, 0, 1));
  EXPECT_NEAR(BSDF(Frame(), DiffuseBxDF{S(0.6f)}, false).DiffuseReflectance(wo)[0], 0.6f, 1e-6);
  EXPECT_NEAR(BSDF(Frame(), PhongBxDF{S(0.3f), S(0.5f), 20}, false).DiffuseReflectance(wo)[0], 0.3f, 1e-6);
  EXPECT_TRUE(BSDF(Frame(), DiffuseBxDF{S(0.6f)}, false).DiffuseReflectance(-wo).IsBlack());
  EXPECT_NEAR(BSDF(Frame(), DiffuseBxDF{S(0.6f)}, true).DiffuseReflectance(-wo)[0], 0.6f, 1e-6);
  DielectricBxDF d;
  EXPECT_TRUE(BSDF(Frame(), d, true).DiffuseReflectance(wo).IsBlack());
}

TEST(Bsdf, OneSidedOpaqueBsdfsAreBlackFromBehind) {
  BSDF one(Frame(), DiffuseBxDF{S(0.5f)}, false);
  BSDF two(Frame(), DiffuseBxDF{S(0.5f)}, true);
  Vec3f below(0.1f, 0, -1), below2(0, 0.2f, -1);
  EXPECT_TRUE(one.f(Normalize(below), Normalize(below2)).IsBlack());
  EXPECT_NEAR(two.f(Normalize(below), Normalize(below2))[0], 0.5f / kPi, 1e-6);
  EXPECT_FALSE(one.Sample(Normalize(below), 0.5f, {0.3f, 0.3f}).has_value());
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {
TEST(Bsdf, EvalWithPdfEqualsSeparateCalls) {
  PCG32 g(4, 4);
  for (const Case& c : NonSpecularCases())
    for (int i = 0; i < 200; ++i) {
      Vec3f wo = SampleUniformSphere({g.UniformFloat(), g.UniformFloat()});
      Vec3f wi = SampleUniformSphere({g.UniformFloat(), g.UniformFloat()});
      BSDF::Evaluation e = c.bsdf.EvalWithPdf(wo, wi);
      EXPECT_EQ(e.f[0], c.bsdf.f(wo, wi)[0]) << c.name;
      EXPECT_EQ(e.pdf, c.bsdf.Pdf(wo, wi)) << c.name;
    }
}
// --- roughplastic -------------------------------------------------------------------------

// Directional albedo by sampling the BSDF (mean and its standard error).
struct Albedo {
  double mean, se;
};
Albedo SampledAlbedo(const BSDF& b, const Vec3f& wo, int n, PCG32& g) {
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    auto s = b.Sample(wo, g.UniformFloat(), {g.UniformFloat(), g.UniformFloat()});
    const double v = s ? s->f[0] * std::abs(s->wi.z) / s->pdf : 0;
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

// Over roughnesses, indices and views from head-on to grazing: a white base under a clear coat
// reflects all the light that arrives (the internal reflectance RoughCoat derives), so any
// other base reflects at most that. The table's interpolation is good to 1e-3 (stated margin).
TEST(Bsdf, RoughPlasticAlbedoIsOneForAWhiteBaseAndAtMostOneOtherwise) {
  SKIP_UNDER_SANITIZERS("Bsdf.NoBsdfCreatesEnergy and Bsdf.SamplingMatchesPdf");
  PCG32 g(11, 12);
  for (float alpha : {0.002f, 0.02f, 0.1f, 0.3f, 0.6f, 1.f})
    for (float eta : {1.2f, 1.5f, 2.2f}) {
      const RoughCoat coat(alpha, eta);
      for (float mu : {1.f, 0.8f, 0.5f, 0.3f, 0.15f, 0.06f}) {
        const Vec3f wo(std::sqrt(1 - mu * mu), 0, mu);
        for (float d : {1.f, 0.6f, 0.f}) {
          RoughPlasticBxDF rp;
          rp.coat = &coat;
          rp.diffuse = S(d);
          rp.specular_sampling_weight = 0.5f;
          const Albedo a = SampledAlbedo(BSDF(Frame(), rp, false), wo, 40000, g);
          EXPECT_LE(a.mean, 1 + 4 * a.se + 1e-3) << "alpha " << alpha << " eta " << eta << " mu " << mu << " base " << d;
          if (d == 1) {
            EXPECT_NEAR(a.mean, 1, 4 * a.se + 1e-3) << "alpha " << alpha << " eta " << eta << " mu " << mu;
          }
          // The coat alone reflects its table's R(mu).
          if (d == 0) {
            EXPECT_NEAR(a.mean, coat.Reflectance(mu), 4 * a.se + 1e-3) << "alpha " << alpha << " mu " << mu;
          }
        }
      }
    }
}

// As alpha -> 0 rough plastic becomes plastic: the coat reflects Fresnel's F(mu), the internal
// reflectance becomes the smooth coat's, and away from the mirror direction f is plastic's.
TEST(Bsdf, RoughPlasticBecomesPlasticAsTheCoatGetsSmooth) {
  const float eta = 1.49f;
  const RoughCoat coat(0.002f, eta);
  for (float mu : {1.f, 0.7f, 0.4f, 0.2f}) EXPECT_NEAR(coat.Reflectance(mu), FresnelDielectric(mu, eta), 2e-3) << mu;
  EXPECT_NEAR(coat.InternalReflectance(), FresnelDiffuseReflectance(1 / eta), 2e-3);
  PlasticBxDF pl;
  pl.eta = eta;
  pl.fdr_int = FresnelDiffuseReflectance(1 / eta);
  pl.diffuse = S(0.7f);
  RoughPlasticBxDF rp;
  rp.coat = &coat;
  rp.diffuse = S(0.7f);
  for (bool nonlinear : {false, true}) {
    pl.nonlinear = rp.nonlinear = nonlinear;
    PCG32 g(3, 4);
    for (int i = 0; i < 200; ++i) {
      const Vec3f wo = SampleUniformHemisphere({g.UniformFloat(), g.UniformFloat()});
      const Vec3f wi = SampleUniformHemisphere({g.UniformFloat(), g.UniformFloat()});
      if (Dot(Vec3f(-wo.x, -wo.y, wo.z), wi) > 0.99f) continue;  // inside the narrow highlight
      // The rough coat nears the smooth one where alpha tan(theta) is small: at a fixed alpha
      // grazing directions come last (at cos 0.02, alpha 0.002 still reflects 1% less than F).
      if (wo.z < 0.1f || wi.z < 0.1f) continue;
      const float a = pl.f(wo, wi)[0], b = rp.f(wo, wi)[0];
      EXPECT_NEAR(b, a, 0.01f * a) << "wo.z " << wo.z << " wi.z " << wi.z;
    }
  }
  // And the whole albedo (specular included) is plastic's.
  PCG32 g(5, 6);
  for (float mu : {0.9f, 0.5f, 0.25f}) {
    const Vec3f wo(std::sqrt(1 - mu * mu), 0, mu);
    const Albedo smooth = SampledAlbedo(BSDF(Frame(), pl, false), wo, 40000, g);
    const Albedo rough = SampledAlbedo(BSDF(Frame(), rp, false), wo, 40000, g);
    EXPECT_NEAR(rough.mean, smooth.mean, 4 * std::hypot(smooth.se, rough.se) + 2e-3) << mu;
  }
}

TEST(Bsdf, RoughPlasticHasNoDeltaLobeAndItsBaseIsItsDiffuseReflectance) {
  const RoughCoat coat(0.2f, 1.5f);
  RoughPlasticBxDF rp;
  rp.coat = &coat;
  rp.diffuse = S(0.4f);
  const BSDF b(Frame(), rp, false);
  const Vec3f wo = Normalize(Vec3f(0.3f, 0.1f, 1));
  SpecularLobe lobes[kMaxSpecularLobes];
  EXPECT_EQ(b.SpecularLobes(wo, lobes), 0);
  EXPECT_EQ(b.Flags(), kReflection | kDiffuse | kGlossy);
  EXPECT_NEAR(b.DiffuseReflectance(wo)[0], kPi * rp.DiffusePart(wo, Vec3f(0, 0, 1))[0], 1e-6f);
  EXPECT_GT(b.DiffuseReflectance(wo)[0], 0.2f);
  rp.diffuse = S(0);
  EXPECT_EQ(BSDF(Frame(), rp, false).Flags(), kReflection | kGlossy);
}

// --- blendbsdf ----------------------------------------------------------------------------

TEST(Bsdf, BlendIsTheWeightedSumOfItsParts) {
  const Frame f;
  const RoughCoat coat(0.3f, 1.5f);
  RoughPlasticBxDF rp;
  rp.coat = &coat;
  rp.diffuse = S(0.3f);
  const BSDF a(f, ConductorBxDF{S(0.2f), S(3.f), S(1.f), TrowbridgeReitz(0.2f, 0.2f)}, false);
  const BSDF b(f, rp, false);
  PCG32 g(1, 2);
  for (float w : {0.f, 0.25f, 1.f}) {
    const BSDF m = BSDF::Blend(f, a, b, w);
    for (int i = 0; i < 100; ++i) {
      const Vec3f wo = SampleUniformHemisphere({g.UniformFloat(), g.UniformFloat()});
      const Vec3f wi = SampleUniformHemisphere({g.UniformFloat(), g.UniformFloat()});
      const float want = (1 - w) * a.f(wo, wi)[0] + w * b.f(wo, wi)[0];
      EXPECT_NEAR(m.f(wo, wi)[0], want, 1e-5f * want + 1e-7f) << w;
      const float want_pdf = (1 - w) * a.Pdf(wo, wi) + w * b.Pdf(wo, wi);
      EXPECT_NEAR(m.Pdf(wo, wi), want_pdf, 1e-5f * want_pdf + 1e-7f) << w;
      // Weights 0 and 1 sample as the part does (same numbers, same directions).
      if (w == 0 || w == 1) {
        const BSDF& part = w == 0 ? a : b;
        const float uc = g.UniformFloat();
        const Vec2f u(g.UniformFloat(), g.UniformFloat());
        auto sm = m.Sample(wo, uc, u), sp = part.Sample(wo, uc, u);
        ASSERT_EQ(bool(sm), bool(sp));
        if (sm) {
          EXPECT_NEAR(Length(sm->wi - sp->wi), 0, 1e-6f);
          EXPECT_NEAR(sm->pdf, sp->pdf, 1e-5f * sp->pdf);
          EXPECT_NEAR(sm->f[0], sp->f[0], 1e-5f * sp->f[0]);
        }
      }
    }
  }
  EXPECT_EQ(BSDF::Blend(f, a, b, 0).Flags(), a.Flags());
  EXPECT_EQ(BSDF::Blend(f, a, b, 1).Flags(), b.Flags());
  EXPECT_EQ(BSDF::Blend(f, a, b, 0.5f).Flags(), a.Flags() | b.Flags());
}

// A blend's delta lobes are its parts', weighted; sampling one returns the part's f / pdf.
TEST(Bsdf, BlendKeepsItsPartsDeltaLobesWeighted) {
  const Frame f;
  DielectricBxDF glass;
  glass.eta = 1.5f;
  const BSDF a(f, glass, true), b(f, DiffuseBxDF{S(0.5f)}, false);
  const BSDF m = BSDF::Blend(f, a, b, 0.3f);
  const Vec3f wo = Normalize(Vec3f(0.4f, 0, 1));
  SpecularLobe la[kMaxSpecularLobes], lm[kMaxSpecularLobes];
  const int na = a.SpecularLobes(wo, la);
  ASSERT_EQ(na, 2);
  ASSERT_EQ(m.SpecularLobes(wo, lm), na);
  for (int i = 0; i < na; ++i) EXPECT_NEAR(lm[i].weight[0], 0.7f * la[i].weight[0], 1e-6f);
  EXPECT_NEAR(m.DiffuseReflectance(wo)[0], 0.3f * 0.5f, 1e-6f);
  // uc from 0.3 up picks the glass (the first part, weight 0.7), its rest (uc - 0.3) / 0.7 the
  // glass's lobe: its reflection's f|cos|/pdf of 1 is kept.
  const float F = FresnelDielectric(wo.z, 1.5f);
  auto s = m.Sample(wo, 0.3f + 0.7f * F * 0.5f, {0.5f, 0.5f});
  ASSERT_TRUE(s && s->IsSpecular());
  EXPECT_NEAR(s->f[0] * s->wi.z / s->pdf, 1.f, 1e-5f);
  EXPECT_NEAR(s->pdf, 0.7f * F, 1e-5f);
}

// A part with its own (bump-mapped) normal keeps its own cosine: f |wi . n_blend| of the blend
// is the parts' f |wi . n_part|, weighted.
TEST(Bsdf, BlendOfDifferentlyTiltedPartsKeepsEachPartsCosine) {
  const Frame flat;
  const Frame tilted = Frame::FromZ(Normalize(Vec3f(0.3f, 0, 1)));
  const BSDF a(tilted, DiffuseBxDF{S(0.8f)}, false), b(flat, DiffuseBxDF{S(0.4f)}, false);
  const BSDF m = BSDF::Blend(flat, a, b, 0.5f);
  PCG32 g(4, 4);
  for (int i = 0; i < 100; ++i) {
    const Vec3f wo = SampleUniformHemisphere({g.UniformFloat(), g.UniformFloat()});
    const Vec3f wi = SampleUniformHemisphere({g.UniformFloat(), g.UniformFloat()});
    const float want = 0.5f * a.f(wo, wi)[0] * AbsDot(wi, tilted.n) + 0.5f * b.f(wo, wi)[0] * wi.z;
    EXPECT_NEAR(m.f(wo, wi)[0] * wi.z, want, 1e-5f * want + 1e-7f);
  }
  // Its albedo is at most one and matches the sampled density.
  for (const Vec3f& wo : Outgoing(false)) {
    auto sampler = [&](PCG32& rng) -> std::optional<Vec3f> {
      auto s = m.Sample(wo, rng.UniformFloat(), {rng.UniformFloat(), rng.UniformFloat()});
      if (!s) return std::nullopt;
      return s->wi;
    };
    auto pdf = [&](const Vec3f& wi) { return double(m.Pdf(wo, wi)); };
    const auto r = test::Chi2TestDirections(sampler, pdf, 200000, 16, 32);
    EXPECT_GT(r.p_value, kAlpha) << r.Describe();
    const Albedo al = SampledAlbedo(m, wo, 40000, g);
    EXPECT_LE(al.mean, 1 + 4 * al.se);
  }
}

}  // namespace
}  // namespace objektiv
