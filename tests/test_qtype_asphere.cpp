// Q-type aspheres (optics/forbes_asphere.h): Forbes's polynomials against their closed forms
// and their defining orthogonality, the surface's sag and slope against Forbes's formulas, the
// paraxial curvature of a Qbfs surface, a Qcon surface against the even asphere it expands to
// (traced), the batch tracer against the exact one, the pupil bounds (pass rate, all the light),
// the shipped aspheric singlet and the native reader's checks.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "base/error.h"
#include "base/rng.h"
#include "batch_agreement.h"
#include "lens_text.h"
#include "pupil_bound_checks.h"
#include "optics/forbes_asphere.h"
#include "optics/lens_file.h"
#include "optics/lens_setup.h"
#include "optics/lens_tracer.h"
#include "optics/paraxial.h"
#include "optics/pupil_bounds.h"
#include "optics/real_ray_analysis.h"
#include "sanitizer_build.h"

namespace objektiv {
namespace {

LensPrescription Parse(const std::string& text) { return test::ParseLensText(text); }
std::string ParseError(const std::string& text) { return test::LensTextError(text); }

TEST(QType, QbfsPolynomialsAreForbesOnes) {
  // Forbes (2007), eq. 3.3: Q0 = 1, Q1 = (13 - 16x) / sqrt(19), Q2 = sqrt(2/95) (29 - 4x (25 - 19x)).
  for (double x : {0.0, 0.1, 0.25, 0.5, 0.77, 1.0}) {
    EXPECT_NEAR(QbfsPolynomial(0, x), 1, 1e-13) << x;
    EXPECT_NEAR(QbfsPolynomial(1, x), (13 - 16 * x) / std::sqrt(19.0), 1e-13) << x;
    EXPECT_NEAR(QbfsPolynomial(2, x), std::sqrt(2 / 95.0) * (29 - 4 * x * (25 - 19 * x)), 1e-13) << x;
  }
}

TEST(QType, QbfsSlopesAreOrthonormal) {
  // <f_m, f_n> = (2 / pi) int_0^1 f_m'(u) f_n'(u) / sqrt(1 - u^2) du = delta_mn for f_m(u) =
  // u^2 (1 - u^2) Q_m(u^2); with u = sin(theta), the midpoint rule over theta (here 400 nodes:
  // exact for these polynomials). Q_m and dQ_m/dx from a surface whose only term is a_m = 1.
  constexpr int kTerms = ForbesAsphere::kMaxTerms, kNodes = 400;
  std::vector<std::vector<double>> slope(kTerms, std::vector<double>(kNodes));
  for (int m = 0; m < kTerms; ++m) {
    std::vector<double> terms(size_t(m) + 1, 0.0);
    terms.back() = 1;
    const ForbesAsphere q(ForbesAsphere::Kind::kBestFitSphere, 1, terms);
    for (int j = 0; j < kNodes; ++j) {
      const double u = std::sin(M_PI / 2 * (j + 0.5) / kNodes), x = u * u;
      double value, d_dt;
      ChebyshevSum(q.chebyshev().data(), int(q.chebyshev().size()), 2 * x - 1, value, d_dt);
      EXPECT_NEAR(value, QbfsPolynomial(m, x), 1e-12 * (1 + std::abs(value)));
      slope[size_t(m)][size_t(j)] = 2 * u * ((1 - 2 * x) * value + x * (1 - x) * 2 * d_dt);
    }
    EXPECT_GT(QbfsPolynomial(m, 0), 0) << m;  // Forbes's sign
  }
  double worst = 0;
  for (int m = 0; m < kTerms; ++m)
    for (int n = 0; n <= m; ++n) {
      double sum = 0;
      for (int j = 0; j < kNodes; ++j) sum += slope[size_t(m)][size_t(j)] * slope[size_t(n)][size_t(j)];
      worst = std::max(worst, std::abs(sum / kNodes - (m == n ? 1 : 0)));
    }
  EXPECT_LT(worst, 1e-10);
}

TEST(QType, QconPolynomialsAreJacobiOnes) {
  // Forbes (2007), eq. 2.4: Q0 = 1, Q1 = -(5 - 6x), Q2 = 15 - 14x (3 - 2x),
  // Q3 = -(35 - 12x (14 - x (21 - 10x))); every Q_m(1) = 1.
  for (double x : {0.0, 0.2, 0.5, 0.9, 1.0}) {
    EXPECT_NEAR(QconPolynomial(0, x), 1, 1e-13);
    EXPECT_NEAR(QconPolynomial(1, x), -(5 - 6 * x), 1e-13);
    EXPECT_NEAR(QconPolynomial(2, x), 15 - 14 * x * (3 - 2 * x), 1e-12);
    EXPECT_NEAR(QconPolynomial(3, x), -(35 - 12 * x * (14 - x * (21 - 10 * x))), 1e-12);
  }
  for (int m = 0; m < ForbesAsphere::kMaxTerms; ++m) EXPECT_NEAR(QconPolynomial(m, 1), 1, 1e-9) << m;
}

// Forbes's sag formulas written out with the polynomials.
double ForbesSag(ForbesAsphere::Kind kind, double c, double k, double rn, const std::vector<double>& a, double r) {
  const double u = r / rn, x = u * u;
  double sum = 0;
  for (size_t m = 0; m < a.size(); ++m)
    sum += a[m] * (kind == ForbesAsphere::Kind::kConic ? QconPolynomial(int(m), x) : QbfsPolynomial(int(m), x));
  const double base = c * r * r / (1 + std::sqrt(1 - (1 + k) * c * c * r * r));
  if (kind == ForbesAsphere::Kind::kConic) return base + x * x * sum;
  return base + x * (1 - x) * sum / std::sqrt(1 - c * c * r * r);
}

TEST(QType, SagAndSlopeAreForbesFormulas) {
  const std::vector<double> a = {0.31, -0.12, 0.05, 0.02, -0.011, 0.004, 0.0023, -0.001, 0.0005, 0.0002, 1e-4, -4e-5};
  for (auto kind : {ForbesAsphere::Kind::kBestFitSphere, ForbesAsphere::Kind::kConic}) {
    LensSurface s;
    s.radius = 38;
    s.conic = kind == ForbesAsphere::Kind::kConic ? -0.7 : 0;
    s.semi_diameter = 16;
    s.forbes = std::make_shared<const ForbesAsphere>(kind, 17.5, a);
    for (double r : {0.0, 2.0, 7.5, 12.25, 16.0, 17.5}) {
      const double expected = ForbesSag(kind, 1 / 38.0, s.conic, 17.5, a, r);
      EXPECT_NEAR(s.Sag(r), expected, 1e-12 * (1 + std::abs(expected))) << s.forbes->Name() << " r " << r;
      const double h = 1e-5, numeric = (s.Sag(r + h) - s.Sag(r - h)) / (2 * h);
      EXPECT_NEAR(s.SagSlope(r), numeric, 1e-8) << s.forbes->Name() << " r " << r;
    }
  }
}

TEST(QType, QbfsAddsItsVertexTermToTheParaxialCurvature) {
  // The sag near the vertex is c_paraxial r^2 / 2: Qbfs's u^2 (1 - u^2) S(u^2) adds S(0) / r_n^2.
  LensSurface s;
  s.radius = -55;
  s.semi_diameter = 12;
  s.forbes = std::make_shared<const ForbesAsphere>(ForbesAsphere::Kind::kBestFitSphere, 12.0, std::vector<double>{0.4, 0.1, -0.2});
  const double r = 1e-4;
  EXPECT_NEAR(s.ParaxialCurvature(), 2 * s.Sag(r) / (r * r), 1e-8);
  EXPECT_GT(std::abs(s.ParaxialCurvature() - s.Curvature()), 1e-3);  // the term matters here
  // Qcon starts at r^4: the conic's curvature.
  s.forbes = std::make_shared<const ForbesAsphere>(ForbesAsphere::Kind::kConic, 12.0, std::vector<double>{0.4, 0.1, -0.2});
  EXPECT_DOUBLE_EQ(s.ParaxialCurvature(), s.Curvature());
}

// The Tessar with Q-type surfaces (front Qbfs, rear Qcon), focused at infinity.
LensSystem QTessar() {
  return AtParaxialInfinityFocus(LoadLens(std::string(OBJEKTIV_TEST_DATA_DIR) + "/qtype-tessar.lens", GlassCatalog::Default()),
                                 kLambdad);
}

TEST(QType, QconIsTheEvenAsphereItExpandsTo) {
  // Q0..Q3 in powers of x: 1; 6x - 5; 15 - 42x + 28x^2; -35 + 168x - 252x^2 + 120x^3. The
  // departure x^2 sum_i c_i x^i is then sum_i c_i r^(4 + 2i) / r_n^(4 + 2i): a4..a10.
  const double a[4] = {0.05, 0.02, -0.01, 0.004}, rn = 17;
  const double c[4] = {a[0] - 5 * a[1] + 15 * a[2] - 35 * a[3], 6 * a[1] - 42 * a[2] + 168 * a[3], 28 * a[2] - 252 * a[3],
                       120 * a[3]};
  auto lens = [&](const std::string& terms) {
    return LensSystem(Parse("surface 42.97 9.8 n=1.691 19.2\nsurface -115.33 2.1 n=1.5487 19.2\n"
                            "surface 306.84 4.16 air 19.2\nstop 4.0 air 15\nsurface -59.06 1.87 n=1.6398 17.3\n"
                            "surface 40.93 10.64 air 17.3\nsurface 183.92 7.05 n=1.691 16.5\n"
                            "surface -48.91 79.8 air 16.5 k=-0.5 " + terms + "\n"));
  };
  const LensSystem q = lens(fmt::format("qcon={:.17g},{:.17g},{:.17g},{:.17g} qnorm={}", a[0], a[1], a[2], a[3], rn));
  const LensSystem even = lens(fmt::format("a4={:.17g} a6={:.17g} a8={:.17g} a10={:.17g}", c[0] / std::pow(rn, 4),
                                           c[1] / std::pow(rn, 6), c[2] / std::pow(rn, 8), c[3] / std::pow(rn, 10)));
  PCG32 rng(3, 7);
  int through = 0;
  for (int i = 0; i < 300; ++i) {
    const Vec3d o(rng.UniformFloat() * 30 - 15, rng.UniformFloat() * 20 - 10, q.FilmZ());
    const Vec3d aim(rng.UniformFloat() * 30 - 15, rng.UniformFloat() * 30 - 15, q.VertexZ(q.SurfaceCount() - 1));
    const TraceResult tq = TraceFromFilm(q, {o, Normalize(aim - o)}, 550), te = TraceFromFilm(even, {o, Normalize(aim - o)}, 550);
    ASSERT_EQ(bool(tq.ray), bool(te.ray)) << i;
    if (!tq.ray) continue;
    ++through;
    EXPECT_LT(Length(tq.ray->o - te.ray->o), 1e-9) << i;
    EXPECT_LT(Length(tq.ray->d - te.ray->d), 1e-11) << i;
  }
  EXPECT_GT(through, 60);
}

TEST(QType, BatchTracerFollowsTheExactOne) {
  const test::BatchAgreement a = test::CompareTracers(QTessar(), 4000, 20, -100, 4, 9);
  test::ExpectAgreement(a, 400, 8, 5e-3);  // mm, 100 mm in front of the lens
}

TEST(QType, PupilBoundsPassMostRaysAndHoldAllTheLight) {
  SKIP_UNDER_SANITIZERS("QType.BatchTracerFollowsTheExactOne (the same lens, traced without the camera)");
  for (int blades : {0, 6}) {
    LensSystem lens = QTessar();
    lens.SetStopShape(StopShape::Iris(blades, 0, 0.2));
    const PupilBounds bounds(lens, std::hypot(18.0, 12.0));
    PCG32 rng(8, 2);
    const test::PassRate pass = test::CameraPassRate(lens, bounds, 20000, rng, [](PCG32& g) {
      return Vec2d((2 * g.UniformFloat() - 1) * 18, (2 * g.UniformFloat() - 1) * 12);
    }, kLambdad);
    EXPECT_GT(pass.launched, 19500) << blades;
    EXPECT_GE(pass.Rate(), 0.95) << blades << " blades";
    for (Vec2d film : {Vec2d(0, 0), Vec2d(10.4, 3.3), Vec2d(-17.2, 11.5)}) {
      const test::AreaEstimates a = test::PassingArea(lens, bounds, film, 35, 30000, rng, kLambdad);
      EXPECT_NEAR(a.bound, a.brute, 4 * a.se) << blades << " blades at " << film.x << ", " << film.y;
    }
  }
}

TEST(QType, TheShippedAsphereHasNoSphericalAberration) {
  // data/lenses/asphere.50mm.lens: the singlet's Qcon front fitted (by an independent
  // meridional trace) to image the axis to a point; the spherical singlet's marginal ray
  // crosses the axis millimetres before the paraxial focus.
  const LensSystem asphere(LoadLens("asphere.50mm", GlassCatalog::Default()));
  const LensSystem singlet(LoadLens("singlet.50mm", GlassCatalog::Default()));
  for (double h : {3.0, 6.0, 9.0, 12.0}) {
    const std::optional<double> a = LongitudinalAberration(asphere, h, kLambdad);
    ASSERT_TRUE(a) << h;
    EXPECT_LT(std::abs(*a), 1e-4) << h;
  }
  const std::optional<double> s = LongitudinalAberration(singlet, 12, kLambdad);
  ASSERT_TRUE(s);
  EXPECT_LT(*s, -3);
  EXPECT_NEAR(ComputeParaxial(asphere.prescription(), kLambdad).efl, 50, 1e-3);  // Qcon keeps the curvature
}

TEST(QType, ALensThatPassesNoLightIsNamedWithItsFile) {
  // A Q-type singlet whose central obstruction is wider than the beam the stop lets in: the
  // camera's error names the file the lens came from.
  const std::string path = ::testing::TempDir() + "/no-light.lens";
  {
    std::ofstream f(path);
    f << "stop 0.5 air 5\nsurface 30 5 n=1.5 11 qbfs=0.1 obscuration=8\nsurface inf 50 air 11\n";
  }
  try {
    SetUpLens(LoadLens(path, GlassCatalog::Default()), {}, {});
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no light gets through no-light (" + path + ")"), std::string::npos) << e.what();
  }
}

TEST(QType, NativeReaderChecksTheTerms) {
  const std::string head = "stop 5 air 10\n";
  const LensPrescription ok = Parse(head + "surface 50 5 n=1.5 12 qbfs=0.1,0.02 qnorm=13\nsurface -50 40 air 12\n");
  ASSERT_TRUE(ok.surfaces[1].forbes);
  EXPECT_EQ(ok.surfaces[1].forbes->kind(), ForbesAsphere::Kind::kBestFitSphere);
  EXPECT_DOUBLE_EQ(ok.surfaces[1].forbes->norm_radius(), 13);
  EXPECT_EQ(ok.surfaces[1].forbes->terms(), (std::vector<double>{0.1, 0.02}));
  // The normalisation radius defaults to the clear semi-diameter.
  const LensPrescription plain = Parse(head + "surface 50 5 n=1.5 12 k=-1 qcon=0.1\nsurface -50 40 air 12\n");
  EXPECT_DOUBLE_EQ(plain.surfaces[1].forbes->norm_radius(), 12);
  // The same lens twice as large: r_n and the terms scale with it.
  const LensPrescription big = ok.Scaled(2);
  EXPECT_DOUBLE_EQ(big.surfaces[1].Sag(20), 2 * ok.surfaces[1].Sag(10));
  auto error = [&](const std::string& options) {
    return ParseError(head + "surface 50 5 n=1.5 12 " + options + "\nsurface -50 40 air 12\n");
  };
  EXPECT_NE(error("qbfs=0.1 k=-1").find("test.lens:2: qbfs= departs from the best-fit sphere"), std::string::npos);
  EXPECT_NE(error("qcon=0.1 a6=1e-6").find("test.lens:2: a Q-type surface takes no a4..a16"), std::string::npos);
  EXPECT_NE(error("qcon=0.1 rx=40").find("no rx="), std::string::npos);
  EXPECT_NE(error("qcon=0.1 qbfs=0.1").find("together"), std::string::npos);
  EXPECT_NE(error("qnorm=10").find("qnorm= without"), std::string::npos);
  EXPECT_NE(error("qcon=0.1 qnorm=0").find("must be positive"), std::string::npos);
  EXPECT_NE(error("qcon=").find("1 to 30 terms"), std::string::npos);
  EXPECT_NE(error("qcon=0.1,,0.2").find("test.lens:2"), std::string::npos);
  EXPECT_NE(error("qcon=0.1,1e300").find("beyond"), std::string::npos);
  std::string many = "qcon=0";
  for (int i = 0; i < 30; ++i) many += ",0";
  EXPECT_NE(error(many).find("1 to 30 terms"), std::string::npos);
  // A Qbfs surface may not reach its sphere's equator (the departure divides by zero there).
  EXPECT_NE(ParseError(head + "surface 12 5 n=1.5 12 qbfs=0.1\nsurface -50 40 air 12\n").find("equator"), std::string::npos);
}

}  // namespace
}  // namespace objektiv
