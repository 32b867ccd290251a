// The single-precision batch tracer against the double-precision one.
#include <gtest/gtest.h>

#include "optics/lens_tracer.h"
#include "base/rng.h"
#include "optics/batch_tracer.h"
#include "optics/lens_file.h"
#include "optics/paraxial.h"

namespace objektiv {
namespace {

LensSystem Prepared(const LensPrescription& lens) {
  LensSystem t(lens);
  if (lens.surfaces.back().thickness == 0) t.SetBackFocus(ComputeParaxial(lens).bfl);
  return t;
}

std::vector<LensPrescription> Lenses() {
  std::vector<LensPrescription> l;
  for (const char* n : {"dgauss.50mm", "wide.22mm", "fisheye.10mm", "telephoto.250mm", "tessar.brendel.100mm"})
    l.push_back(LoadLens(n, GlassCatalog::Default()));
  l.push_back(ParseNativeLens("stop 2 air 6\nsurface 30 6 N-LAK9 10 k=-0.8 a4=-2e-6 a6=3e-9\n"
                              "surface -80 0.5 air 10\nsurface 40 3 N-SF5 9 a4=1e-6\nsurface 25 35 air 9\n",
                              "asphere.lens", GlassCatalog::Default()));
  return l;
}

TEST(BatchTracer, FollowsTheDoubleTracerFromTheFilm) {
  for (const LensPrescription& lens : Lenses()) {
    LensSystem exact = Prepared(lens);
    BatchLensTracer fast(exact);
    const LensSurface& rear = lens.surfaces.back();
    PCG32 rng(1, 7);
    const int n = 4000;
    RayBatch b;
    b.Resize(n);
    std::vector<LensRay> in(n);
    for (int i = 0; i < n; ++i) {
      Vec3d film((rng.UniformFloat() - 0.5) * 24, (rng.UniformFloat() - 0.5) * 16, exact.FilmZ());
      double a = 2 * M_PI * rng.UniformFloat(), r = rear.semi_diameter * std::sqrt(rng.UniformFloat());
      Vec3d target(r * std::cos(a), r * std::sin(a), exact.VertexZ(int(lens.surfaces.size()) - 1));
      in[i] = {film, Normalize(target - film)};
      b.ox[i] = float(film.x), b.oy[i] = float(film.y), b.oz[i] = float(film.z);
      b.dx[i] = float(in[i].d.x), b.dy[i] = float(in[i].d.y), b.dz[i] = float(in[i].d.z);
      b.lambda[i] = 420 + 250 * rng.UniformFloat();
    }
    fast.TraceFromFilm(b);
    int both = 0, disagree = 0;
    double worst_pos = 0, worst_dir = 0, worst_t = 0;
    for (int i = 0; i < n; ++i) {
      TraceResult e = TraceFromFilm(exact, in[i], b.lambda[i]);
      if (bool(e.ray) != bool(b.alive[i])) {
        ++disagree;  // only rays grazing a rim may fall differently
        continue;
      }
      if (!e.ray) continue;
      ++both;
      worst_pos = std::max({worst_pos, std::abs(e.ray->o.x - b.ox[i]), std::abs(e.ray->o.y - b.oy[i]), std::abs(e.ray->o.z - b.oz[i])});
      worst_dir = std::max({worst_dir, std::abs(e.ray->d.x - b.dx[i]), std::abs(e.ray->d.y - b.dy[i])});
      worst_t = std::max(worst_t, std::abs(e.surface_transmittance * e.internal_transmittance - b.transmittance[i]));
    }
    // Rays aimed from anywhere on a 24 x 16 mm film at the rear element: for the wide angles
    // most are cut by the apertures, but enough get through to compare.
    EXPECT_GT(both, n / 40) << lens.name;
    EXPECT_LE(disagree, n / 500) << lens.name;
    EXPECT_LT(worst_pos, 1e-4) << lens.name;
    EXPECT_LT(worst_dir, 1e-5) << lens.name;
    EXPECT_LT(worst_t, 1e-4) << lens.name;
  }
}

TEST(BatchTracer, EmptyBatchIsTracedAsNothing) {
  // A pixel outside a fisheye's image circle starts no ray. The tracer took element 0 of its
  // empty scratch tables (undefined behaviour, reported by UBSan; an abort under
  // _GLIBCXX_ASSERTIONS, the hardening default of major distributions).
  for (const LensPrescription& lens : Lenses()) {
    BatchLensTracer fast(Prepared(lens));
    for (bool transmission : {false, true}) {
      RayBatch b;
      b.record_stop = true;
      fast.TraceFromFilm(b, transmission);
      fast.TraceFromObject(b, transmission);
      EXPECT_EQ(b.Size(), 0u);
      EXPECT_TRUE(b.stop_x.empty());
    }
  }
}

TEST(BatchTracer, FollowsTheDoubleTracerToTheFilm) {
  for (const LensPrescription& lens : Lenses()) {
    LensSystem exact = Prepared(lens);
    BatchLensTracer fast(exact);
    PCG32 rng(3, 9);
    const int n = 3000;
    RayBatch b;
    b.Resize(n);
    std::vector<LensRay> in(n);
    double front = lens.surfaces.front().semi_diameter;
    for (int i = 0; i < n; ++i) {
      double th = 0.3 * rng.UniformFloat(), ph = 2 * M_PI * rng.UniformFloat();
      Vec3d d(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
      Vec3d o((rng.UniformFloat() - 0.5) * front, (rng.UniformFloat() - 0.5) * front, -20);
      in[i] = {o - d * 0.0, d};
      b.ox[i] = float(o.x), b.oy[i] = float(o.y), b.oz[i] = float(o.z);
      b.dx[i] = float(d.x), b.dy[i] = float(d.y), b.dz[i] = float(d.z);
      b.lambda[i] = 420 + 250 * rng.UniformFloat();
    }
    fast.TraceFromObject(b, false);
    double worst = 0;
    int both = 0;
    for (int i = 0; i < n; ++i) {
      TraceResult e = TraceFromObject(exact, in[i], b.lambda[i]);
      if (!e.ray || !b.alive[i]) continue;
      ++both;
      // Positions on the film.
      double se = (exact.FilmZ() - e.ray->o.z) / e.ray->d.z, sf = (fast.FilmZ() - b.oz[i]) / b.dz[i];
      worst = std::max({worst, std::abs(e.ray->o.x + e.ray->d.x * se - (b.ox[i] + b.dx[i] * sf)),
                        std::abs(e.ray->o.y + e.ray->d.y * se - (b.oy[i] + b.dy[i] * sf))});
    }
    EXPECT_GT(both, n / 100) << lens.name;
    EXPECT_LT(worst, 1e-4) << lens.name;
  }
}

}  // namespace
}  // namespace objektiv
