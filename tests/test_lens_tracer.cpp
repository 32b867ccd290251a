// Exact tracing through lenses against first-order optics and exact geometry.
#include <gtest/gtest.h>

#include "optics/lens_file.h"
#include "optics/lens_tracer.h"
#include "optics/paraxial.h"
#include "base/vec.h"

namespace objektiv {
namespace {

LensPrescription Parse(const std::string& text) { return ParseNativeLens(text, "test.lens", GlassCatalog::Default()); }

TEST(LensSystem, PlaneParallelPlateDeviatesNoRay) {
  LensSystem plate(Parse("stop 1 air 20\nsurface inf 10 N-SF11 20\nsurface inf 5 air 20\n"));
  for (double angle : {0.0, 5.0, 20.0, 40.0}) {
    double a = angle * M_PI / 180;
    LensRay in{{1, -2, -10}, Normalize(Vec3d(std::sin(a), 0.3 * std::sin(a), std::cos(a)))};
    for (double lambda : {450.0, 550.0, 650.0}) {
      TraceResult r = TraceFromObject(plate, in, lambda);
      ASSERT_TRUE(r.ray);
      EXPECT_NEAR(r.ray->d.x, in.d.x, 1e-14);
      EXPECT_NEAR(r.ray->d.y, in.d.y, 1e-14);
      EXPECT_NEAR(r.ray->d.z, in.d.z, 1e-14);
    }
  }
}

TEST(LensSystem, SmallHeightRaysMeetTheParaxialFocus) {
  for (const char* name : {"dgauss.50mm", "wide.22mm", "fisheye.10mm", "telephoto.250mm", "tessar.brendel.100mm"}) {
    LensPrescription lens = LoadLens(name, GlassCatalog::Default());
    ParaxialData p = ComputeParaxial(lens, 587.5618);
    LensSystem tracer(lens);
    // A ray parallel to the axis at a height far below the aperture: aberrations ~ h^2 vanish.
    double h = 1e-4;
    TraceResult r = TraceFromObject(tracer, {{h, 0, -20}, {0, 0, 1}}, 587.5618);
    ASSERT_TRUE(r.ray) << name;
    double z_cross = r.ray->o.z - r.ray->o.x * r.ray->d.z / r.ray->d.x;
    double bfl = z_cross - tracer.VertexZ(int(lens.surfaces.size()) - 1);
    EXPECT_NEAR(bfl, p.bfl, 1e-6 * p.efl) << name;
    // EFL from the exit angle: h / tan(u').
    EXPECT_NEAR(-h / (r.ray->d.x / r.ray->d.z), p.efl, 1e-6 * p.efl) << name;
  }
}

TEST(LensSystem, FilmToObjectAndBackReturnsTheRay) {
  for (const char* name : {"dgauss.50mm", "tessar.brendel.100mm", "wide.22mm"}) {
    LensPrescription lens = LoadLens(name, GlassCatalog::Default());
    LensSystem tracer(lens);
    tracer.SetBackFocus(ComputeParaxial(lens).bfl);  // pbrt files leave the film at the last vertex
    int got = 0;
    for (int i = 0; i < 50; ++i) {
      double fx = 0.3 * (i % 7) - 1, fy = 0.2 * (i % 5);
      Vec3d film(fx, fy, tracer.FilmZ());
      Vec3d target(0.9 * std::cos(i), 0.9 * std::sin(i), tracer.VertexZ(int(tracer.prescription().surfaces.size()) - 1));
      LensRay out{film, Normalize(target - film)};
      TraceResult a = TraceFromFilm(tracer, out, 550);
      if (!a.ray) continue;
      ++got;
      // Reverse the exiting ray and trace it back toward the film.
      TraceResult b = TraceFromObject(tracer, {a.ray->o + a.ray->d * 30.0, a.ray->d * -1.0}, 550);
      ASSERT_TRUE(b.ray) << name;
      Vec3d back = b.ray->o + b.ray->d * ((tracer.FilmZ() - b.ray->o.z) / b.ray->d.z);
      EXPECT_NEAR(back.x, film.x, 1e-9) << name;
      EXPECT_NEAR(back.y, film.y, 1e-9) << name;
      EXPECT_NEAR(Dot(b.ray->d, out.d * -1.0), 1, 1e-12) << name;
    }
    EXPECT_GT(got, 25) << name;
  }
}

TEST(LensSystem, HyperbolicSingletFocusesPerfectly) {
  // Flat front, exit surface with conic -n^2: a collimated beam in glass leaving a hyperbola
  // of eccentricity n meets at its focus, |R| / (n - 1) behind the vertex.
  const double n = 1.5, R = -50;
  LensSystem t(Parse("stop 0 air 12\nsurface inf 8 n=1.5 12\nsurface -50 100 air 12 k=-2.25\n"));
  EXPECT_NEAR(t.FilmZ() - t.VertexZ(2), -R / (n - 1), 1e-12);
  double worst = 0;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j < 8; ++j) {
      double r = 11.5 * i / 20, phi = j * M_PI / 4;
      TraceResult res = TraceFromObject(t, {{r * std::cos(phi), r * std::sin(phi), -5}, {0, 0, 1}}, 587.6);
      ASSERT_TRUE(res.ray);
      Vec3d p = res.ray->o + res.ray->d * ((t.FilmZ() - res.ray->o.z) / res.ray->d.z);
      worst = std::max(worst, std::hypot(p.x, p.y));
    }
  EXPECT_LT(worst, 1e-3);  // below 1 um (in practice ~1e-12 mm)
  // The same singlet with a spherical exit surface has plain spherical aberration.
  LensSystem sphere(Parse("stop 0 air 12\nsurface inf 8 n=1.5 12\nsurface -50 100 air 12\n"));
  TraceResult edge = TraceFromObject(sphere, {{11.5, 0, -5}, {0, 0, 1}}, 587.6);
  ASSERT_TRUE(edge.ray);
  Vec3d p = edge.ray->o + edge.ray->d * ((sphere.FilmZ() - edge.ray->o.z) / edge.ray->d.z);
  EXPECT_GT(std::abs(p.x), 0.1);
}

TEST(LensSystem, AperturesClipAndTotalInternalReflectionStops) {
  LensSystem t(LoadLens("dgauss.50mm", GlassCatalog::Default()));
  // Far outside the front element: clipped at the first surface.
  TraceResult r = TraceFromObject(t, {{20, 0, -10}, {0, 0, 1}}, 550);
  EXPECT_FALSE(r.ray);
  EXPECT_EQ(r.failure, TraceFailure::kClipped);
  EXPECT_EQ(r.surface, 0);
  // Narrowing the stop clips a marginal ray that passed before.
  TraceResult wide = TraceFromObject(t, {{10, 0, -10}, {0, 0, 1}}, 550);
  ASSERT_TRUE(wide.ray);
  t.SetStopSemiDiameter(2);
  TraceResult narrow = TraceFromObject(t, {{10, 0, -10}, {0, 0, 1}}, 550);
  EXPECT_FALSE(narrow.ray);
  EXPECT_EQ(narrow.surface, t.prescription().StopIndex());
  // Glass to air beyond the critical angle (41.8 degrees for n = 1.5): a ray parallel to the
  // axis at height 5 enters a flat face square on and meets the exit face (radius -6) at
  // asin(5/6) = 56 degrees. (A stop in front with glass after it is an air-glass face: it
  // refracts, so a steep ray cannot be started inside the glass that way.)
  LensSystem exit_face(Parse("stop 1 air 50\nsurface inf 5 n=1.5 50\nsurface -6 5 air 5.9\n"));
  TraceResult tir = TraceFromObject(exit_face, {{0, 5, -1}, {0, 0, 1}}, 550);
  EXPECT_FALSE(tir.ray);
  EXPECT_EQ(tir.failure, TraceFailure::kTotalInternalReflection);
  EXPECT_EQ(tir.surface, 2);
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

TEST(LensSystem, FresnelAndAbsorptionThroughAPlate) {
  LensSystem plate(Parse("stop 1 air 20\nsurface inf 10 N-BK7 20\nsurface inf 5 air 20\n"));
  for (double lambda : {300.0, 550.0}) {
    TraceResult r = TraceFromObject(plate, {{0, 0, -5}, {0, 0, 1}}, lambda);
    ASSERT_TRUE(r.ray);
    double n = plate.prescription().surfaces[1].medium->Index(lambda), R = Sqr(float((n - 1) / (n + 1)));
    EXPECT_NEAR(r.surface_transmittance, (1 - R) * (1 - R), 1e-6);
    EXPECT_NEAR(r.internal_transmittance, plate.prescription().surfaces[1].medium->InternalTransmittance(lambda, 10), 1e-12);
  }
  // The catalog row for N-BK7 at 300 nm over 10 mm.
  TraceResult uv = TraceFromObject(plate, {{0, 0, -5}, {0, 0, 1}}, 300);
  EXPECT_NEAR(uv.internal_transmittance, 0.30171, 1e-5);
  // Obliquely the path in glass is longer: more absorption, and Fresnel grows.
  Vec3d d = Normalize(Vec3d(0, std::sin(0.6), std::cos(0.6)));
  TraceResult oblique = TraceFromObject(plate, {{0, 0, -5}, d}, 300);
  EXPECT_LT(oblique.internal_transmittance, uv.internal_transmittance);
  EXPECT_LT(oblique.surface_transmittance, uv.surface_transmittance);
  EXPECT_NEAR(FresnelReflectance(1, 1.5, 1), 0.04, 1e-12);
  // Per surface: the two faces, each with its own reflectance, multiplying to the total.
  std::vector<SurfaceEvent> events;
  TraceResult again = TraceFromObject(plate, {{0, 0, -5}, d}, 300, nullptr, &events);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].surface, 1);
  EXPECT_EQ(events[1].surface, 2);
  EXPECT_NEAR((1 - events[0].reflectance) * (1 - events[1].reflectance), again.surface_transmittance, 1e-15);
  EXPECT_NEAR(events[0].cos_incidence, d.z, 1e-12);
  EXPECT_EQ(FresnelReflectance(1.5, 1, 0.5), 1.0);  // beyond the critical angle
}

TEST(LensSystem, BladedStops) {
  LensSystem t(LoadLens("dgauss.50mm", GlassCatalog::Default()));
  double r = t.StopSemiDiameter();
  EXPECT_TRUE(t.InsideStop(0.99 * r, 0));
  t.SetStopShape(StopShape::Iris(6, 0, 0));  // corners at 0, 60, 120 ... degrees
  EXPECT_TRUE(t.InsideStop(0.99 * r, 0));  // toward a corner
  double flat = r * std::cos(M_PI / 6);     // the edge's distance, between corners (30 degrees)
  EXPECT_TRUE(t.InsideStop(0.99 * flat * std::cos(M_PI / 6), 0.99 * flat * std::sin(M_PI / 6)));
  EXPECT_FALSE(t.InsideStop(1.01 * flat * std::cos(M_PI / 6), 1.01 * flat * std::sin(M_PI / 6)));
  t.SetStopShape(StopShape::Iris(6, 0, 30 * M_PI / 180));  // rotated: now an edge faces +x
  EXPECT_FALSE(t.InsideStop(0.95 * r, 0));
  t.SetStopShape(StopShape::Iris(6, 1, 0));  // fully curved blades: a circle
  EXPECT_TRUE(t.InsideStop(0.99 * r * std::cos(M_PI / 6), 0.99 * r * std::sin(M_PI / 6)));
  t.SetStopShape(StopShape::Iris(6, 0.5, 0));  // in between: outside the straight edge, inside the circle
  Vec2d mid(r * std::cos(M_PI / 6), r * std::sin(M_PI / 6));
  double m = flat + 0.5 * (r - flat);
  EXPECT_TRUE(t.InsideStop(0.99 * m * mid.x / r, 0.99 * m * mid.y / r));
  EXPECT_FALSE(t.InsideStop(1.01 * m * mid.x / r, 1.01 * m * mid.y / r));
  // The opening's area: a regular hexagon is 3 sqrt(3) / (2 pi) of the circle.
  t.SetStopShape(StopShape::Iris(6, 0, 0));
  int in = 0, n = 400;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) in += t.InsideStop(r * (2.0 * (i + 0.5) / n - 1), r * (2.0 * (j + 0.5) / n - 1));
  EXPECT_NEAR(in * 4.0 / (n * n), 3 * std::sqrt(3.0) / 2, 0.01);
}

}  // namespace
}  // namespace objektiv
