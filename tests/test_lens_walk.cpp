// The random walk through the lens (optics/lens_walk.h): without reflections it is the exact
// tracer; with them, each class of paths carries on average the light the exact tracer gives
// its fixed sequences (the direct path, the sum of the two-reflection ghosts), whatever the
// reflection probability chosen.
#include <gtest/gtest.h>

#include <cmath>

#include "optics/coating_library.h"
#include "optics/ghosts.h"
#include "optics/lens_file.h"
#include "optics/lens_setup.h"
#include "optics/lens_walk.h"

namespace objektiv {
namespace {

LensSystem Set(LensPrescription lens, double fnumber) {
  return SetUpLens(std::move(lens), {fnumber, 0, {}}, {INFINITY, FocusRequest::From::kFilm, false}).lens;
}

std::optional<Vec3d> OnFilm(const LensSystem& lens, const TraceResult& r) {
  if (!r.ray || !(r.ray->d.z > 0)) return std::nullopt;
  const double t = (lens.FilmZ() - r.ray->o.z) / r.ray->d.z;
  return r.ray->o + r.ray->d * t;
}

TEST(LensWalk, WithoutReflectionsItIsTheExactTracer) {
  const LensSystem lens = Set(LoadLens("dgauss.50mm", GlassCatalog::Default()), 2.8);
  PCG32 rng(1, 2);
  LensWalkOptions lossless;
  lossless.lossless = true;
  int reached = 0;
  for (int k = 0; k < 200; ++k) {
    const LensRay ray{{(rng.UniformFloat() - 0.5) * 40, (rng.UniformFloat() - 0.5) * 40, -10},
                      Normalize(Vec3d(rng.UniformFloat() - 0.5, rng.UniformFloat() - 0.5, 2))};
    const TraceResult exact = TraceFromObject(lens, ray, 587.6);
    const std::optional<Vec3d> film = OnFilm(lens, exact);
    const LensWalk w = WalkFromObject(lens, ray, 587.6, rng, lossless);
    ASSERT_EQ(film.has_value(), w.film.has_value()) << k;
    if (!film) continue;
    ++reached;
    EXPECT_EQ(w.reflections, 0);
    EXPECT_NEAR(w.film->o.x, film->x, 1e-12);
    EXPECT_NEAR(w.film->o.y, film->y, 1e-12);
    EXPECT_EQ(w.weight, 1.0);
  }
  EXPECT_GT(reached, 20);
}

// Mean weight per reflection count over n walks of one ray, with its standard error.
struct ClassMeans {
  double mean[3] = {0, 0, 0}, se[3] = {0, 0, 0};  // 0, 2 and 4 or more reflections
};
ClassMeans Walks(const LensSystem& lens, const LensRay& ray, double lambda, double q, int n) {
  PCG32 rng(3, uint64_t(q * 1000));
  LensWalkOptions o;
  o.min_reflect_probability = q;
  double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
  for (int k = 0; k < n; ++k) {
    const LensWalk w = WalkFromObject(lens, ray, lambda, rng, o);
    if (!w.film) continue;
    EXPECT_EQ(w.reflections % 2, 0);
    const int c = std::min(w.reflections / 2, 2);
    sum[c] += w.weight;
    sum2[c] += w.weight * w.weight;
  }
  ClassMeans m;
  for (int c = 0; c < 3; ++c) {
    m.mean[c] = sum[c] / n;
    m.se[c] = std::sqrt(std::max(sum2[c] / n - m.mean[c] * m.mean[c], 0.0) / n);
  }
  return m;
}

TEST(LensWalk, PathClassesCarryTheirShareOfTheLight) {
  for (const char* coating : {"", "MgF2"}) {
    LensPrescription p = LoadLens("dgauss.50mm", GlassCatalog::Default());
    if (*coating) Recoat(p, *FindBuiltInCoating(coating));
    const LensSystem lens = Set(p, 2.8);
    const LensRay ray{{3, -2, -5}, Normalize(Vec3d(0.1, 0.05, 1))};
    const double lambda = 520;
    // The exact tracer's fixed sequences: the direct path, and every ghost's.
    const TraceResult direct = TraceFromObject(lens, ray, lambda);
    const double direct_t = OnFilm(lens, direct) ? direct.surface_transmittance * direct.internal_transmittance : 0;
    double ghosts_t = 0;
    for (const Ghost& g : TwoReflectionGhosts(lens)) {
      const TraceResult r = TraceSequence(lens, ray, lambda, GhostPath(lens, g));
      if (OnFilm(lens, r)) ghosts_t += r.surface_transmittance * r.internal_transmittance;
    }
    ASSERT_GT(direct_t, 0.3);
    ASSERT_GT(ghosts_t, 1e-6);
    // The light's own odds, and walks sent into reflections more often.
    for (double q : {0.0, 0.1, 0.3}) {
      const ClassMeans m = Walks(lens, ray, lambda, q, 200000);
      EXPECT_NEAR(m.mean[0], direct_t, 4 * m.se[0] + 1e-12) << coating << " q " << q;
      EXPECT_NEAR(m.mean[1], ghosts_t, 4 * m.se[1]) << coating << " q " << q;
      // A test that can tell: walks sent into reflections about once per pass through the lens
      // (q = 1 / 10 interfaces) find the ghosts often enough for a standard error well below
      // their light (at the light's own odds, coated, they are rare; at q = 0.3 most walks
      // reflect too often and leave by the front).
      if (q == 0.1) {
        EXPECT_LT(4 * m.se[1], 0.1 * ghosts_t) << coating << " q " << q;
      }
    }
  }
}

}  // namespace
}  // namespace objektiv
