// Closed forms: Snell's law, Fresnel equations, Sellmeier dispersion against catalog data.
#include <gtest/gtest.h>

#include "scene/fresnel.h"
#include "scene/ior.h"

namespace objektiv {
namespace {

TEST(Snell, RefractionObeysSnellsLaw) {
  for (float theta_deg : {0.f, 10.f, 30.f, 60.f, 85.f}) {
    float t = Radians(theta_deg);
    Vec3f wi(std::sin(t), 0, std::cos(t));
    Vec3f wt;
    float etap;
    ASSERT_TRUE(Refract(wi, Vec3f(0, 0, 1), 1.5f, &etap, &wt));
    EXPECT_NEAR(Length(wt), 1, 1e-6);
    EXPECT_LT(wt.z, 0);
    // n1 sin(theta_i) = n2 sin(theta_t), and the ray stays in the plane of incidence.
    EXPECT_NEAR(std::sin(t), 1.5f * std::sqrt(wt.x * wt.x + wt.y * wt.y), 1e-6);
    EXPECT_LE(wt.x, 0);
    EXPECT_EQ(wt.y, 0);
  }
}

TEST(Snell, TotalInternalReflectionBeyondTheCriticalAngle) {
  float critical = std::asin(1 / 1.5f);
  Vec3f below(std::sin(critical - 0.01f), 0, -std::cos(critical - 0.01f));
  Vec3f above(std::sin(critical + 0.01f), 0, -std::cos(critical + 0.01f));
  Vec3f wt;
  float etap;
  EXPECT_TRUE(Refract(below, Vec3f(0, 0, 1), 1.5f, &etap, &wt));
  EXPECT_NEAR(etap, 1 / 1.5f, 1e-6);
  EXPECT_FALSE(Refract(above, Vec3f(0, 0, 1), 1.5f, &etap, &wt));
  EXPECT_EQ(FresnelDielectric(above.z, 1.5f), 1.f);
}

TEST(Fresnel, NormalIncidenceAndBrewsterAngle) {
  for (float n : {1.33f, 1.5f, 2.4f}) {
    EXPECT_NEAR(FresnelDielectric(1.f, n), Sqr((n - 1) / (n + 1)), 1e-6);
    // At Brewster's angle p-polarised light is fully transmitted: R = Rs / 2.
    float tb = std::atan(n), ci = std::cos(tb), st = std::sin(tb) / n, ct = std::sqrt(1 - st * st);
    float rs = Sqr((ci - n * ct) / (ci + n * ct));
    EXPECT_NEAR(FresnelDielectric(ci, n), rs / 2, 1e-6);
    // Seen from inside, reflectance is the same for the refracted angle (reciprocity).
    EXPECT_NEAR(FresnelDielectric(-ct, n), FresnelDielectric(ci, n), 1e-5);
  }
  EXPECT_NEAR(FresnelDielectric(0.f, 1.5f), 1, 1e-6);  // grazing
}

// The reflectance is formed over one division (the squares' common denominator); for an
// index whose products leave single precision (a scene may give any positive index) it falls
// back to the two quotients: finite, and near 1 as the closed form says at normal incidence.
TEST(Fresnel, ExtremeIndicesStayFinite) {
  for (float n : {1e9f, 1e12f, 1e20f, 1e-9f}) {
    for (float c : {1.f, 0.7f, 0.2f}) {
      const float r = FresnelDielectric(c, n);
      EXPECT_TRUE(std::isfinite(r)) << n << " " << c;
      EXPECT_GE(r, 0.f);
      EXPECT_LE(r, 1.f);
    }
    EXPECT_NEAR(FresnelDielectric(1.f, n), Sqr((n - 1) / (n + 1)), 1e-6) << n;
  }
  EXPECT_NEAR(FresnelDielectric(1.0, 1e100), 1, 1e-12);
}

TEST(Fresnel, ConductorReducesToDielectricWithoutAbsorption) {
  for (float c : {0.1f, 0.5f, 0.9f, 1.f}) EXPECT_NEAR(FresnelComplex(c, {1.5f, 0.f}), FresnelDielectric(c, 1.5f), 1e-5);
  // A purely imaginary index reflects everything (Mitsuba's "none" conductor).
  EXPECT_NEAR(FresnelComplex(0.4f, {0.f, 1.f}), 1, 1e-5);
  // Gold-like index at normal incidence: ((n-1)^2 + k^2) / ((n+1)^2 + k^2).
  EXPECT_NEAR(FresnelComplex(1.f, {0.2f, 3.f}), (0.64f + 9) / (1.44f + 9), 1e-5);
}

TEST(Fresnel, DiffuseReflectanceMatchesKnownValue) {
  // Hemispherical average of the internal reflectance of glass (n = 1.5 inside): about 0.596.
  EXPECT_NEAR(FresnelDiffuseReflectance(1 / 1.5f), 0.5963, 2e-3);
  EXPECT_NEAR(FresnelDiffuseReflectance(1.5f), 0.0918, 2e-3);
}

TEST(Sellmeier, SchottNBK7ReproducesCatalogNdAndVd) {
  // Schott's published Sellmeier coefficients for N-BK7; catalog nd = 1.51680, vd = 64.17.
  IorModel bk7 = IorModel::Sellmeier({1.03961212, 0.231792344, 1.01046945}, {0.00600069867, 0.0200179144, 103.560653});
  double nd = bk7(587.5618), nf = bk7(486.1327), nc = bk7(656.2725);
  EXPECT_NEAR(nd, 1.51680, 1e-5);
  EXPECT_NEAR((nd - 1) / (nf - nc), 64.17, 0.05);
  EXPECT_TRUE(bk7.IsDispersive());
  // Cauchy: n = A + B / l^2.
  IorModel c = IorModel::Cauchy(1.5, 0.004);
  EXPECT_NEAR(c(500), 1.5 + 0.004 / 0.25, 1e-12);
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

// Refract a direction through a dielectric face with outward normal n_out (world space),
// entering (into glass) or leaving, using the BSDF's transmission lobe.
Vec3f ThroughFace(const Vec3f& d, const Vec3f& n_out, float n_glass) {
  Vec3f wt;
  float etap;
  // Refract takes the direction pointing away from the surface on the incident side.
  EXPECT_TRUE(Refract(-d, n_out, n_glass, &etap, &wt));
  return wt;
}

TEST(Prism, DeviationMatchesTheAnalyticFormulaPerWavelength) {
  // A 60-degree prism in the xz-plane; the ray enters face 1 at 70 degrees incidence (at 50,
  // N-SF11 would reflect totally at the second face).
  const double apex = Radians(60);
  IorModel sf11 = IorModel::Sellmeier({1.73759695, 0.313747346, 1.89878101}, {0.013188707, 0.0623068142, 155.23629});
  Vec3f n1(-std::cos(float(apex / 2)), 0, std::sin(float(apex / 2)));  // outward normals of the two faces
  Vec3f n2(std::cos(float(apex / 2)), 0, std::sin(float(apex / 2)));
  for (double lambda : {400.0, 486.1, 587.6, 656.3, 700.0}) {
    float n = float(sf11(lambda));
    double theta1 = Radians(70);
    // Incoming direction making theta1 with -n1.
    Vec3f t1 = Normalize(Cross(Vec3f(0, 1, 0), n1));
    Vec3f d = Normalize(-n1 * float(std::cos(theta1)) + t1 * float(std::sin(theta1)));
    Vec3f inside = ThroughFace(d, n1, n);
    Vec3f out = ThroughFace(inside, n2, n);
    double deviation = std::acos(Clamp(Dot(d, out), -1, 1));
    double r1 = std::asin(std::sin(theta1) / n), r2 = apex - r1;
    double expected = theta1 + std::asin(n * std::sin(r2)) - apex;
    EXPECT_NEAR(deviation, expected, 1e-5) << lambda << " nm, n = " << n;
  }
  // Dispersion: violet is bent more than red.
  EXPECT_GT(sf11(400), sf11(700));
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {
TEST(Fresnel, SpectralConductorFormulaMatchesComplexArithmetic) {
  SampledSpectrum eta, k;
  const float etas[4] = {0.2f, 1.2f, 0.f, 2.5f}, ks[4] = {3.f, 2.f, 1.f, 0.3f};
  for (int i = 0; i < 4; ++i) {
    eta[i] = etas[i];
    k[i] = ks[i];
  }
  for (float c : {0.f, 0.05f, 0.3f, 0.7f, 1.f}) {
    SampledSpectrum r = FresnelComplex(c, eta, k);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(r[i], FresnelComplex(c, {etas[i], ks[i]}), 2e-5f) << c << " " << i;
  }
}
}  // namespace
}  // namespace objektiv

#include "base/ray.h"

namespace objektiv {
namespace {
TEST(Ray, NextFloatStepsOneUlp) {
  for (float v : {1.f, -1.f, 3.5e-20f, -7.25e12f, 0.f, -0.f}) {
    EXPECT_EQ(NextFloatUp(v), std::nextafter(v == -0.f ? 0.f : v, INFINITY)) << v;
    EXPECT_EQ(NextFloatDown(v), std::nextafter(v == 0.f ? -0.f : v, -INFINITY)) << v;
  }
  EXPECT_EQ(NextFloatUp(INFINITY), INFINITY);
  EXPECT_EQ(NextFloatDown(-INFINITY), -INFINITY);
}
}  // namespace
}  // namespace objektiv
