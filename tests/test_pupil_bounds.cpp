// Pupil bounds: few wasted camera rays, and no light left outside the bound.
#include <gtest/gtest.h>

#include "optics/lens_tracer.h"
#include "base/rng.h"
#include "optics/lens_file.h"
#include "optics/paraxial.h"
#include "optics/pupil_bounds.h"
#include "optics/real_ray_analysis.h"
#include "base/sampling.h"
#include "sanitizer_build.h"

namespace objektiv {
namespace {

LensSystem AtFNumber(const LensPrescription& lens, double fnumber) {
  LensSystem t(lens);
  ParaxialData p = ComputeParaxial(lens);
  if (lens.surfaces.back().thickness == 0) t.SetBackFocus(p.bfl);
  // Stop semi-diameter for this f-number: the entrance pupil scales with the stop.
  double full = t.StopSemiDiameter();
  t.SetStopSemiDiameter(full * (p.efl / fnumber) / p.entrance_pupil_diameter);
  return t;
}

// Film radius to cover: the full-frame half-diagonal, or the image circle if smaller.
double FilmRadius(const LensSystem& t) {
  FieldOfView fov = SensorFieldOfView(t, 36, 24, 587.5618);
  double r = std::hypot(18.0, 12.0);
  if (fov.diagonal < 2 * 89) {
    std::optional<double> h = RealImageHeight(t, fov.diagonal / 2, 587.5618);
    if (h) r = std::min(r, std::abs(*h));
  }
  return r;
}

TEST(PupilBounds, NinetyFivePercentOfCameraRaysGetThrough) {
  SKIP_UNDER_SANITIZERS("PupilBounds.TheBoundContainsAllTheLight");
  for (const char* name : {"dgauss.50mm", "wide.22mm", "fisheye.10mm", "telephoto.250mm", "tessar.brendel.100mm"}) {
    LensPrescription lens = LoadLens(name, GlassCatalog::Default());
    double wide_open = ComputeParaxial(lens).fnumber;
    for (double n : {0.0, 2.8, 4.0, 5.6, 8.0, 16.0}) {
      double fnumber = n == 0 ? wide_open : n;
      if (fnumber < wide_open) continue;
      LensSystem t = AtFNumber(lens, fnumber);
      double radius = FilmRadius(t);
      PupilBounds bounds(t, radius);
      PCG32 rng(11, 3);
      int launched = 0, passed = 0;
      for (int i = 0; i < 4000; ++i) {
        double r = radius * std::sqrt(rng.UniformFloat()), phi = 2 * M_PI * rng.UniformFloat();
        Vec2d film(r * std::cos(phi), r * std::sin(phi));
        PupilBounds::Sample s = bounds.SampleRear(film, {rng.UniformFloat(), rng.UniformFloat()});
        if (s.pdf == 0) continue;
        ++launched;
        Vec3d o(film.x, film.y, t.FilmZ());
        passed += bool(TraceFromFilm(t, {o, Normalize(s.point - o)}, 587.5618).ray);
      }
      ASSERT_GT(launched, 100) << name << " f/" << fnumber;
      EXPECT_GE(double(passed) / launched, 0.95) << name << " f/" << fnumber << ": " << passed << "/" << launched;
    }
  }
}

TEST(PupilBounds, TheBoundContainsAllTheLight) {
  // The passing area on the rear plane estimated two ways: uniformly over the whole rear
  // element, and through the bound (area x pass rate). A bound missing part of the passing
  // region would make the second smaller.
  for (const char* name : {"dgauss.50mm", "wide.22mm", "tessar.brendel.100mm"}) {
    LensPrescription lens = LoadLens(name, GlassCatalog::Default());
    LensSystem t = AtFNumber(lens, ComputeParaxial(lens).fnumber);
    double radius = FilmRadius(t);
    PupilBounds bounds(t, radius);
    ParaxialData pd = ComputeParaxial(lens, 587.5618, t.StopSemiDiameter());
    double rear = std::max(lens.surfaces.back().semi_diameter, 1.5 * pd.exit_pupil_diameter);  // brute-force disk
    PCG32 rng(5, 1);
    for (double fr : {0.0, 0.5, 0.9}) {
      Vec2d film(fr * radius, 0);
      Vec3d o(film.x, film.y, t.FilmZ());
      const int n = 40000;
      int brute = 0, via_bound = 0;
      for (int i = 0; i < n; ++i) {
        Vec2f d = SampleUniformDiskConcentric({rng.UniformFloat(), rng.UniformFloat()});
        Vec3d target(d.x * rear, d.y * rear, bounds.rear_z());
        brute += bool(TraceFromFilm(t, {o, Normalize(target - o)}, 587.5618).ray);
        PupilBounds::Sample s = bounds.SampleRear(film, {rng.UniformFloat(), rng.UniformFloat()});
        if (s.pdf > 0) via_bound += bool(TraceFromFilm(t, {o, Normalize(s.point - o)}, 587.5618).ray);
      }
      const ConvexPolygon* poly = bounds.BoundAt(film);
      double a_brute = M_PI * rear * rear * brute / n;
      double a_bound = poly ? poly->area * via_bound / n : 0;
      // Binomial standard errors of both estimates.
      double se = std::sqrt(M_PI * rear * rear * a_brute / n + (poly ? poly->area * a_bound / n : 0));
      EXPECT_NEAR(a_bound, a_brute, 4 * se + 1e-9) << name << " at " << fr;
    }
  }
}

}  // namespace
}  // namespace objektiv
