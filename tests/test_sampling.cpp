// Sampling routines: each warp's samples follow its stated density (chi-square), the
// densities integrate to one, and the Sobol' sampler's points form (0,m,2)-nets.
#include <gtest/gtest.h>

#include "base/lowdiscrepancy.h"
#include "base/sampling.h"
#include "chi2.h"
#include "render/sampler.h"

namespace objektiv {
namespace {

using test::Chi2TestDirections;
using test::Chi2TestPoints;
constexpr double kAlpha = 1e-3;  // significance level of each goodness-of-fit test

Vec2f U2(PCG32& r) {
  float a = r.UniformFloat();
  return {a, r.UniformFloat()};
}

TEST(Chi2, GammaQMatchesKnownValues) {
  // Q(1, x) = exp(-x); Q(k/2, x/2) for chi-square with 2 dof is exp(-x/2).
  EXPECT_NEAR(test::GammaQ(1, 2.0), std::exp(-2.0), 1e-12);
  EXPECT_NEAR(test::GammaQ(1, 0.3), std::exp(-0.3), 1e-12);
  // Chi-square, 10 dof, x = 18.307: p = 0.05 (tables).
  EXPECT_NEAR(test::GammaQ(5, 18.307 / 2), 0.05, 1e-4);
}

TEST(Sampling, CosineHemisphere) {
  auto r = Chi2TestDirections([](PCG32& g) { return std::optional<Vec3f>(SampleCosineHemisphere(U2(g))); },
                              [](const Vec3f& w) { return w.z > 0 ? CosineHemispherePdf(w.z) : 0.0; });
  EXPECT_GT(r.p_value, kAlpha) << r.Describe();
  EXPECT_NEAR(r.pdf_integral, 1, 1e-3);
}

TEST(Sampling, UniformSphereAndHemisphere) {
  auto r = Chi2TestDirections([](PCG32& g) { return std::optional<Vec3f>(SampleUniformSphere(U2(g))); },
                              [](const Vec3f&) { return double(UniformSpherePdf()); });
  EXPECT_GT(r.p_value, kAlpha) << r.Describe();
  EXPECT_NEAR(r.pdf_integral, 1, 1e-3);
  auto h = Chi2TestDirections([](PCG32& g) { return std::optional<Vec3f>(SampleUniformHemisphere(U2(g))); },
                              [](const Vec3f& w) { return w.z > 0 ? double(UniformHemispherePdf()) : 0.0; });
  EXPECT_GT(h.p_value, kAlpha) << h.Describe();
}

TEST(Sampling, UniformCone) {
  const float cos_max = 0.7f;
  auto r = Chi2TestDirections([&](PCG32& g) { return std::optional<Vec3f>(SampleUniformCone(U2(g), cos_max)); },
                              [&](const Vec3f& w) { return w.z >= cos_max ? double(UniformConePdf(cos_max)) : 0.0; },
                              200000, 40, 20);
  EXPECT_GT(r.p_value, kAlpha) << r.Describe();
  EXPECT_NEAR(r.pdf_integral, 1, 2e-2);  // the cone edge cuts bins: coarse quadrature
}

TEST(Sampling, ConcentricDiskIsUniform) {
  auto r = Chi2TestPoints([](PCG32& g) { return SampleUniformDiskConcentric(U2(g)); },
                          [](Vec2f p) { return p.x * p.x + p.y * p.y <= 1 ? 1 / M_PI : 0.0; }, {-1, -1}, {1, 1});
  EXPECT_GT(r.p_value, kAlpha) << r.Describe();
}

TEST(Sampling, RegularPolygonIsUniform) {
  for (int blades : {3, 5, 6, 9}) {
    const float rot = 0.3f;
    auto inside = [&](Vec2f p) {
      // Inside the polygon iff on the inner side of every edge.
      for (int k = 0; k < blades; ++k) {
        float a0 = rot + 2 * kPi * k / blades, a1 = rot + 2 * kPi * (k + 1) / blades;
        Vec2f c0{std::cos(a0), std::sin(a0)}, c1{std::cos(a1), std::sin(a1)};
        float cross = (c1.x - c0.x) * (p.y - c0.y) - (c1.y - c0.y) * (p.x - c0.x);
        if (cross < 0) return false;
      }
      return true;
    };
    auto r = Chi2TestPoints([&](PCG32& g) { return SampleRegularPolygon(blades, rot, U2(g)); },
                            [&](Vec2f p) { return inside(p) ? 1 / double(RegularPolygonArea(blades)) : 0.0; }, {-1, -1},
                            {1, 1}, 400000, 24);
    EXPECT_GT(r.p_value, kAlpha) << blades << " blades: " << r.Describe();
    EXPECT_NEAR(r.pdf_integral, 1, 2e-2);
  }
}

TEST(Sampling, TriangleIsUniform) {
  auto r = Chi2TestPoints([](PCG32& g) { return SampleUniformTriangle(U2(g)); },
                          [](Vec2f b) { return (b.x >= 0 && b.y >= 0 && b.x + b.y <= 1) ? 2.0 : 0.0; }, {0, 0}, {1, 1});
  EXPECT_GT(r.p_value, kAlpha) << r.Describe();
}

TEST(Sampling, TentMatchesDensity) {
  auto r = Chi2TestPoints([](PCG32& g) { return Vec2f(SampleTent(g.UniformFloat(), 1.5f), SampleTent(g.UniformFloat(), 1.5f)); },
                          [](Vec2f p) {
                            auto t = [](float x) { return std::max(0.f, 1.5f - std::abs(x)) / (1.5f * 1.5f); };
                            return double(t(p.x) * t(p.y));
                          },
                          {-1.5f, -1.5f}, {1.5f, 1.5f});
  EXPECT_GT(r.p_value, kAlpha) << r.Describe();
  EXPECT_NEAR(r.pdf_integral, 1, 1e-3);
}

TEST(Sampling, Distribution2DMatchesItsPdf) {
  const int nu = 7, nv = 5;
  std::vector<float> f(nu * nv);
  for (int i = 0; i < nu * nv; ++i) f[i] = float((i * 37) % 11);  // includes zeros
  Distribution2D d(f, nu, nv);
  PCG32 g(1, 2);
  for (int i = 0; i < 1000; ++i) {
    float pdf;
    Vec2f p = d.Sample(U2(g), &pdf);
    EXPECT_NEAR(pdf, d.Pdf(p), 1e-4 * pdf);
    EXPECT_GT(pdf, 0);
  }
  auto r = Chi2TestPoints([&](PCG32& g2) {
    float pdf;
    return d.Sample(U2(g2), &pdf);
  }, [&](Vec2f p) { return double(d.Pdf(p)); }, {0, 0}, {1, 1}, 200000, 35);
  EXPECT_GT(r.p_value, kAlpha) << r.Describe();
  EXPECT_NEAR(r.pdf_integral, 1, 1e-3);
}

TEST(Sobol, FirstPowerOfTwoPointsAreNets) {
  // For spp = 2^m, every dimension pair of a pixel's first spp samples must put exactly
  // one point in each elementary interval of area 1/spp (all shapes 2^a x 2^(m-a)).
  const int m = 6, n = 1 << m;
  Sampler s(SamplerKind::kSobol, n, 17);
  for (int dimpair = 0; dimpair < 4; ++dimpair) {
    std::vector<Vec2f> pts;
    for (int i = 0; i < n; ++i) {
      s.StartPixelSample({3, 9}, i);
      for (int d = 0; d < dimpair; ++d) s.Get2D();
      pts.push_back(s.Get2D());
    }
    for (int a = 0; a <= m; ++a) {
      int nx = 1 << a, ny = 1 << (m - a);
      std::vector<int> count(n, 0);
      for (const Vec2f& p : pts) ++count[int(p.y * ny) * nx + int(p.x * nx)];
      for (int c : count) ASSERT_EQ(c, 1) << "dimension pair " << dimpair << ", elementary intervals " << nx << "x" << ny;
    }
  }
}

TEST(Samplers, DeterministicPerPixelAndIndex) {
  for (int kind = 0; kind < 3; ++kind) {
    std::unique_ptr<Sampler> a, b;
    a = std::make_unique<Sampler>(SamplerKind(kind), 16, 5);
    b = a->Clone();
    // Different visiting orders give the same numbers for the same (pixel, index, dimension).
    a->StartPixelSample({4, 2}, 7);
    float a1 = a->Get1D();
    Vec2f a2 = a->Get2D();
    b->StartPixelSample({9, 9}, 3);
    b->Get2D();
    b->StartPixelSample({4, 2}, 7);
    EXPECT_EQ(a1, b->Get1D());
    EXPECT_EQ(a2, b->Get2D());
  }
}

TEST(Sobol, ReversedFormulationGivesTheSamePoints) {
  PCG32 g(8, 8);
  for (int i = 0; i < 2000; ++i) {
    uint32_t index = g.Uniform32() & 0xffff;
    uint64_t seed = (uint64_t(g.Uniform32()) << 32) | g.Uniform32();
    EXPECT_EQ(Sobol1Reversed(ReverseBits32(index)), ReverseBits32(Sobol1(index)));
    EXPECT_EQ(ScrambledSobol2DReversed(ReverseBits32(index), seed), ScrambledSobol2D(index, seed));
    EXPECT_EQ(ScrambledSobol1DReversed(ReverseBits32(index), seed), ScrambledSobol1D(index, seed));
  }
}

TEST(Samplers, StratifiedFillsEveryStratum) {
  Sampler s(SamplerKind::kStratified, 16, 3);
  std::vector<int> count(16, 0);
  for (int i = 0; i < 16; ++i) {
    s.StartPixelSample({1, 1}, i);
    Vec2f p = s.Get2D();
    ++count[int(p.y * 4) * 4 + int(p.x * 4)];
  }
  for (int c : count) EXPECT_EQ(c, 1);
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {
TEST(Distribution1D, SmallAndLargeDistributionsPickTheSameCells) {
  // The linear scan used for short tables must agree with the binary search.
  for (int n : {2, 5, 8, 9, 40}) {
    std::vector<float> f(n);
    for (int i = 0; i < n; ++i) f[i] = float((i * 7) % 5);  // includes zero cells
    Distribution1D d(f);
    for (int k = 0; k < 1000; ++k) {
      float u = (k + 0.5f) / 1000;
      int i = d.SampleDiscrete(u);
      EXPECT_LE(d.CdfAt(i), u);
      EXPECT_GT(d.CdfAt(i + 1), u);
      EXPECT_GT(f[i], 0);
    }
  }
}
}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

TEST(Sampling, ConcentricDiskMatchesTheTrigonometricMapping) {
  // The polynomial cos/sin in the concentric mapping against the library's, on a grid.
  double worst = 0;
  for (int i = 0; i <= 200; ++i)
    for (int j = 0; j <= 200; ++j) {
      Vec2f u(i / 200.f, j / 200.f);
      double ox = 2.0 * u.x - 1, oy = 2.0 * u.y - 1;
      if (ox == 0 && oy == 0) continue;
      double r = std::abs(ox) > std::abs(oy) ? ox : oy;
      double theta = std::abs(ox) > std::abs(oy) ? M_PI / 4 * (oy / ox) : M_PI / 2 - M_PI / 4 * (ox / oy);
      Vec2f d = SampleUniformDiskConcentric(u);
      worst = std::max({worst, std::abs(d.x - r * std::cos(theta)), std::abs(d.y - r * std::sin(theta))});
    }
  EXPECT_LT(worst, 3e-7);
}

}  // namespace
}  // namespace objektiv
