// Gradient-index media (optics/gradient_index.h, optics/gradient_propagation.h): rays through a
// SELFOC rod against the closed form of its meridional rays (sinusoids whose period depends on
// the ray's invariant), the paraxial data of a radial GRIN slab (a Wood lens) against GRIN
// paraxial theory's closed form, the paraxial tracer against the exact one's rays near the axis
// for axial and spherical profiles on curved surfaces, the invariants of skew rays, the batch
// tracer against the exact one, the pupil bounds, scaling and the reader's checks.
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "base/rng.h"
#include "batch_agreement.h"
#include "lens_text.h"
#include "pupil_bound_checks.h"
#include "optics/focusing.h"
#include "optics/gradient_propagation.h"
#include "optics/lens_system.h"
#include "optics/lens_tracer.h"
#include "optics/paraxial.h"
#include "optics/pupil_bounds.h"
#include "sanitizer_build.h"

namespace objektiv {
namespace {

LensPrescription Parse(const std::string& text) { return test::ParseLensText(text); }
std::string ParseError(const std::string& text) { return test::LensTextError(text); }

// A SELFOC rod with flat faces, n^2 = n_v^2 (1 - (g r)^2) (h4 = h6 = 0), `length` mm long.
constexpr double kRodIndex = 1.6, kRodG = 0.3;
LensSystem Rod(double length) {
  return LensSystem(Parse(fmt::format("stop 1 air 2.5\nsurface inf {} n={} 2.5 selfoc={}\nsurface inf 10 air 2.5\n", length,
                                      kRodIndex, kRodG)));
}

// In that profile a meridional ray obeys d^2 x / dz^2 = (1 / 2 beta^2) d(n^2)/dx = -(n_v g / beta)^2 x,
// beta = n dz/ds its invariant: a sinusoid of period 2 pi beta / (n_v g) at every amplitude. A
// ray entering the flat face parallel to the axis at height x0 has beta = n(x0) and leaves at
// x0 cos(W L), W = n_v g / beta, into air with direction x-component beta dx/dz = -x0 n_v g sin(W L).
TEST(GradientIndex, SelfocRodRaysFollowTheClosedForm) {
  for (double length : {5.0, 17.0, 31.0}) {
    const LensSystem rod = Rod(length);
    for (double x0 : {0.05, 0.6, 1.2, 1.9}) {
      const TraceResult r = TraceFromObject(rod, {Vec3d(x0, 0, -1), Vec3d(0, 0, 1)}, 550);
      ASSERT_TRUE(r.ray) << length << " " << x0;
      const double beta = kRodIndex * std::sqrt(1 - kRodG * kRodG * x0 * x0), w = kRodIndex * kRodG / beta;
      EXPECT_NEAR(r.ray->o.x, x0 * std::cos(w * length), 1e-8) << length << " " << x0;
      EXPECT_NEAR(r.ray->o.z, 1 + length, 1e-12);
      EXPECT_NEAR(r.ray->d.x, -x0 * kRodIndex * kRodG * std::sin(w * length), 1e-9) << length << " " << x0;
      EXPECT_NEAR(r.ray->o.y, 0, 1e-12);
      EXPECT_NEAR(r.ray->d.y, 0, 1e-12);
    }
  }
  // The period depends on the amplitude: a rod one paraxial period long (2 pi / g) returns a
  // ray near the axis to its height and direction, a steep one not.
  const LensSystem period = Rod(2 * M_PI / kRodG);
  const TraceResult near = TraceFromObject(period, {Vec3d(0.01, 0, -1), Vec3d(0, 0, 1)}, 550);
  const TraceResult far = TraceFromObject(period, {Vec3d(1.9, 0, -1), Vec3d(0, 0, 1)}, 550);
  ASSERT_TRUE(near.ray && far.ray);
  EXPECT_NEAR(near.ray->o.x, 0.01, 1e-5);
  EXPECT_GT(std::abs(far.ray->o.x - 1.9), 0.1);
}

// A skew ray in a profile that does not vary along z keeps n dz/ds (the medium is the same
// along z) and the angular momentum about the axis x T_y - y T_x (the medium is the same
// turned about it); both measured from the points and directions the exact tracer reports just
// inside each face, through an intermediate plane (a surface between equal media).
TEST(GradientIndex, SkewRaysKeepTheirInvariants) {
  const LensSystem rod(Parse("stop 1 air 2.5\nsurface inf 7.3 n=1.6 2.5 selfoc=0.3,0.4,-0.2\n"
                             "surface inf 10 air 2.5\n"));
  PCG32 rng(3, 9);
  for (int k = 0; k < 40; ++k) {
    const Vec3d o(rng.UniformFloat() * 2 - 1, rng.UniformFloat() * 2 - 1, -1);
    const Vec3d d = Normalize(Vec3d(rng.UniformFloat() * 0.3 - 0.15, rng.UniformFloat() * 0.3 - 0.15, 1));
    // Inside: refracted at the front face, then carried to the back face.
    const SurfaceCrossing front = CrossSurface(rod, 1, {o, d}, 550, true);
    ASSERT_EQ(front.failure, TraceFailure::kNone);
    const std::optional<LensRay> in = Refracted(front, front.d);
    ASSERT_TRUE(in);
    const GradientArrival back = PropagateThroughGradient(rod, 1, true, *in, 550);
    ASSERT_EQ(back.failure, TraceFailure::kNone) << k;
    const double n_in = IndexInGap(rod, 1, in->o, 550), n_out = IndexInGap(rod, 1, back.p, 550);
    EXPECT_NEAR(n_in * in->d.z, n_out * back.d.z, 1e-9) << k;
    EXPECT_NEAR(n_in * (in->o.x * in->d.y - in->o.y * in->d.x), n_out * (back.p.x * back.d.y - back.p.y * back.d.x), 1e-9) << k;
    EXPECT_GT(back.steps, 3);
  }
}

// A radial GRIN slab with flat faces, n = n_v + nr2 r^2 (a Wood lens): paraxially y'' = -g^2 y,
// g^2 = -2 nr2 / n_v, so a ray parallel to the axis at height 1 leaves at cos(g L) with reduced
// angle -n_v g sin(g L): EFL = 1 / (n_v g sin(g L)), BFL = cos(g L) EFL. The paraxial tracer
// against that, and the exact tracer's rays near the axis against the paraxial data.
TEST(GradientIndex, WoodLensParaxialDataFollowGrinTheory) {
  const double n_v = 1.5, nr2 = -0.0008, length = 8;
  const LensPrescription rx = Parse(fmt::format("stop 0.5 air 6\nsurface inf {} n={} 6 grin_r={}\nsurface inf 100 air 6\n",
                                                length, n_v, nr2));
  const double g = std::sqrt(-2 * nr2 / n_v), efl = 1 / (n_v * g * std::sin(g * length));
  const ParaxialData p = ComputeParaxial(rx, 550);
  EXPECT_NEAR(p.efl / efl, 1, 1e-11);
  EXPECT_NEAR(p.bfl / (std::cos(g * length) * efl), 1, 1e-11);
  const LensSystem lens(rx);
  for (double h : {1e-3, 3e-3}) {
    const TraceResult r = TraceFromObject(lens, {Vec3d(0, h, -1), Vec3d(0, 0, 1)}, 550);
    ASSERT_TRUE(r.ray);
    // The exact ray's focal length (height over the angle) and where it crosses the axis.
    EXPECT_NEAR(-h / (r.ray->d.y / r.ray->d.z) / efl, 1, 1e-6) << h;
    EXPECT_NEAR(-r.ray->o.y / (r.ray->d.y / r.ray->d.z) / p.bfl, 1, 1e-6) << h;
  }
}

// Axial and spherical profiles between curved surfaces: the paraxial tracer (its GRIN
// transfer, and each surface refracting with the index on the axis where the gap meets it)
// against the exact tracer's rays near the axis, from the front (EFL, BFL) and the back (FFL).
TEST(GradientIndex, ParaxialDataMatchTheExactRaysNearTheAxis) {
  for (const char* options : {"grin_z=-0.01,0.0006", "grin_z=0.02 grin_r=-0.001,1e-6", "grin_sphere=-40,0.004,1e-4",
                              "grin_sphere=60,-0.003"}) {
    const LensPrescription rx = Parse(fmt::format(
        "stop 0.5 air 8\nsurface 30 6 n=1.62 9 {}\nsurface -80 2 n=1.7 9\nsurface 200 40 air 9\n", options));
    const ParaxialData p = ComputeParaxial(rx, 550);
    const LensSystem lens(rx);
    const double h = 1e-3;
    const TraceResult r = TraceFromObject(lens, {Vec3d(0, h, -1), Vec3d(0, 0, 1)}, 550);
    ASSERT_TRUE(r.ray) << options;
    const double slope = r.ray->d.y / r.ray->d.z;
    EXPECT_NEAR(-h / slope / p.efl, 1, 2e-6) << options;
    EXPECT_NEAR(-r.ray->o.y / slope / p.bfl, 1, 2e-6) << options;
    // From the film side: a ray parallel to the axis behind the lens focuses at the front focus.
    const TraceResult b = TraceFromFilm(lens, {Vec3d(0, h, lens.FilmZ()), Vec3d(0, 0, -1)}, 550);
    ASSERT_TRUE(b.ray) << options;
    const double front_focus = b.ray->o.z - b.ray->o.y * b.ray->d.z / b.ray->d.y;
    EXPECT_NEAR(front_focus, p.ffl, 2e-6 * std::abs(p.ffl)) << options;
  }
}

// Focused on a near object, the paraxial back focus (the camera's focusing) is where the exact
// tracer's rays from the object point near the axis cross it, for a radial and a spherical
// gradient (the finite-distance paraxial trace carries the gradient's power too).
TEST(GradientIndex, FiniteFocusMatchesTheExactRays) {
  for (const char* options : {"grin_r=-0.002", "grin_sphere=-40,-0.002,1e-4"}) {
    const LensPrescription rx =
        Parse(fmt::format("stop 1 air 8\nsurface inf 5 n=1.6 10 {}\nsurface -200 49 air 10\n", options));
    const double distance = 2500;  // film to object
    const std::optional<FocusSolution> f = FocusAtDistance(rx, distance, 550);
    ASSERT_TRUE(f) << options;
    LensSystem lens(rx);
    lens.SetBackFocus(f->back_focus);
    const Vec3d object(0, 0, lens.FilmZ() - distance);
    const TraceResult r = TraceFromObject(lens, {object, Normalize(Vec3d(0, 1e-5, 1))}, 550);
    ASSERT_TRUE(r.ray) << options;
    const double crossing = r.ray->o.z - r.ray->o.y * r.ray->d.z / r.ray->d.y;
    EXPECT_NEAR(crossing, lens.FilmZ(), 1e-5 * f->back_focus) << options;
  }
}

// A ray that curves out to the element's edge between its faces leaves the glass there: in a
// rod 1.2 periods long every ray that gets through stays within its radius all the way.
TEST(GradientIndex, RaysThatReachTheEdgeLeaveTheElement) {
  const LensSystem rod(Parse(fmt::format("stop 0.01 air 0.5\nsurface inf {} n=1.6 1 selfoc=0.3\nsurface inf 1 air 1\n",
                                         1.2 * 2 * M_PI / 0.3)));
  int passed = 0, edge = 0;
  for (int k = 0; k <= 200; ++k) {
    const double sin_u = 0.9 * k / 200;
    const LensRay ray{Vec3d(0, 0, rod.FilmZ()), Vec3d(0, sin_u, -std::sqrt(1 - sin_u * sin_u))};
    const SurfaceCrossing back = CrossSurface(rod, 2, ray, 550, false);
    if (back.failure != TraceFailure::kNone) continue;  // beyond the back face's rim
    const std::optional<LensRay> in = Refracted(back, back.d);
    if (!in) continue;
    std::vector<Vec3d> points;
    const GradientArrival a = PropagateThroughGradient(rod, 1, false, *in, 550, kGradientTolerance, &points);
    double widest = 0;
    for (const Vec3d& q : points) widest = std::max(widest, std::hypot(q.x, q.y));
    if (a.failure == TraceFailure::kNone) {
      ++passed;
      EXPECT_LE(widest, 1.0) << sin_u;
    } else {
      edge += a.failure == TraceFailure::kClipped;
    }
  }
  EXPECT_GT(passed, 20);
  EXPECT_GT(edge, 20);
}

// The same lens in a homogeneous glass and with a gradient of zero terms trace alike.
TEST(GradientIndex, ZeroGradientIsTheGlassItself) {
  const std::string head = "stop 0.5 air 8\nsurface 30 6 N-BK7 9";
  const LensSystem plain(Parse(head + "\nsurface -80 40 air 9\n"));
  const LensSystem graded(Parse(head + " grin_r=0\nsurface -80 40 air 9\n"));
  PCG32 rng(1, 2);
  for (int k = 0; k < 50; ++k) {
    const LensRay ray{Vec3d(rng.UniformFloat() * 12 - 6, rng.UniformFloat() * 12 - 6, -1),
                      Normalize(Vec3d(rng.UniformFloat() * 0.2 - 0.1, rng.UniformFloat() * 0.2 - 0.1, 1))};
    const double lambda = 400 + 300 * rng.UniformFloat();
    const TraceResult a = TraceFromObject(plain, ray, lambda), b = TraceFromObject(graded, ray, lambda);
    ASSERT_EQ(bool(a.ray), bool(b.ray)) << k;
    if (!a.ray) continue;
    EXPECT_NEAR(Length(a.ray->o - b.ray->o), 0, 1e-9) << k;
    EXPECT_NEAR(Length(a.ray->d - b.ray->d), 0, 1e-10) << k;
    EXPECT_NEAR(a.internal_transmittance, b.internal_transmittance, 1e-12) << k;
    EXPECT_NEAR(a.surface_transmittance, b.surface_transmittance, 1e-12) << k;
  }
}

LensSystem GradedDoublet() {
  LensSystem lens(Parse("stop 2 air 7\nsurface 25 5 N-BK7 8 grin_r=-0.0015,2e-6 grin_z=0.004 coating=MgF2\n"
                        "surface -60 1.5 N-SF5 8\nsurface -200 38 air 8\n"));
  return lens;
}

TEST(GradientIndex, BatchTracerFollowsTheExactOne) {
  const LensSystem lens = GradedDoublet();
  const test::BatchAgreement a = test::CompareTracers(lens, 1500, 8, -60, 4, 1);
  test::ExpectAgreement(a, 300, 3, 1e-4);
}

TEST(GradientIndex, PupilBoundsHoldAllTheLight) {
  SKIP_UNDER_SANITIZERS("GradientIndex.BatchTracerFollowsTheExactOne");
  const LensSystem lens = GradedDoublet();
  const PupilBounds bounds(lens, std::hypot(18.0, 12.0));
  PCG32 rng(5, 5);
  const test::PassRate pass = test::CameraPassRate(lens, bounds, 4000, rng, [](PCG32& g) {
    return Vec2d((2 * g.UniformFloat() - 1) * 18, (2 * g.UniformFloat() - 1) * 12);
  }, kLambdad);
  EXPECT_GE(pass.Rate(), 0.9);
  for (Vec2d film : {Vec2d(0, 0), Vec2d(8.3, -5.2), Vec2d(17.5, 11.6)}) {
    const test::AreaEstimates a = test::PassingArea(lens, bounds, film, 12, 6000, rng, kLambdad);
    ASSERT_TRUE(a.has_bound);
    EXPECT_NEAR(a.bound, a.brute, 4 * a.se) << film.x << ", " << film.y;
  }
}

TEST(GradientIndex, ScaledLensHasTheScaledFocalLength) {
  const LensPrescription rx = GradedDoublet().prescription();
  EXPECT_NEAR(ComputeParaxial(rx.Scaled(2.5), 550).efl / ComputeParaxial(rx, 550).efl, 2.5, 1e-10);
  const LensPrescription sphere = Parse("stop 0.5 air 8\nsurface 30 6 n=1.62 9 grin_sphere=-40,0.004,1e-4\nsurface -80 40 air 9\n");
  EXPECT_NEAR(ComputeParaxial(sphere.Scaled(0.5), 550).efl / ComputeParaxial(sphere, 550).efl, 0.5, 1e-10);
  EXPECT_NEAR(ComputeParaxial(Rod(17).prescription().Scaled(3), 550).efl / ComputeParaxial(Rod(17).prescription(), 550).efl,
              3, 1e-10);
}

TEST(GradientIndex, ReaderChecksTheMedium) {
  const std::string head = "stop 1 air 5\n";
  auto error = [&](const std::string& row, const std::string& next = "surface -40 30 air 6") {
    return ParseError(head + row + "\n" + next + "\n");
  };
  EXPECT_EQ(error("surface 40 5 n=1.6 6 grin_r=-0.001,1e-6 grin_z=0.01"), "accepted");
  EXPECT_NE(error("surface 40 5 air 6 grin_r=-0.001").find("test.lens:2: a gradient-index medium needs its glass"),
            std::string::npos);
  EXPECT_NE(error("surface 40 5 n=1.6 6 grin_r=-0.001 selfoc=0.1").find("one gradient profile"), std::string::npos);
  EXPECT_NE(error("surface 40 5 n=1.6 6 selfoc=0").find("selfoc g 0 per mm"), std::string::npos);
  EXPECT_NE(error("surface 40 5 n=1.6 6 grin_sphere=3").find("R,S1[,S2]"), std::string::npos);
  EXPECT_NE(error("surface 40 5 n=1.6 6 grin_r=1,2,3,4").find("NR2[,NR4[,NR6]]"), std::string::npos);
  EXPECT_NE(error("surface 40 5 n=1.6 6 grin_sphere=2,0.01").find("lies inside the element"), std::string::npos);
  // The index must stay a glass's over the whole element: here it falls below 1 at the rim.
  EXPECT_NE(error("surface 40 5 n=1.6 6 grin_r=-0.02").find("test.lens:2: the gradient's index reaches"), std::string::npos);
  EXPECT_NE(error("surface 40 5 n=1.6 6 selfoc=0.2").find("the gradient's index reaches 0"), std::string::npos);
  EXPECT_NE(ParseError("surface 40 5 n=1.6 6 grin_r=-0.001\nstop 1 n=1.6 5\nsurface -40 30 air 6\n").find("test.lens:2: the stop lies inside"),
            std::string::npos);
  EXPECT_NE(ParseError("stop 1 air 5\nsurface 40 5 n=1.6 6 grin_r=-0.001\nsurface -40 30 air 6\nmirror -100 -20 10\n"
                       "mirror -100 40 10\n")
                .find("with mirrors is not modelled"),
            std::string::npos);
  EXPECT_NE(error("surface 40 5 n=1.6 6 grin_r=-0.001", "surface -40 30 air 6 zones=1").find("Fresnel surface"),
            std::string::npos);
}

}  // namespace
}  // namespace objektiv
