// The batch (single-precision) lens tracer against the exact one on random rays from the film:
// rays from full-frame film points aimed at points of the rear vertex's plane, traced by both
// at 550 nm, carried to a plane in front of the lens and compared there.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "base/rng.h"
#include "optics/batch_tracer.h"
#include "optics/lens_tracer.h"

namespace objektiv::test {

struct BatchAgreement {
  int rays = 0, agree = 0, through = 0;  // traced; passed or blocked by both; passed by both
  double worst_mm = 0;                   // the largest distance between them on the plane
  double worst_transmittance = 0;        // the largest difference of their transmittances
};

// `aim_half`: the aim points' square, +-aim_half mm; `plane_z`: lens-space z of the plane;
// `random_waves`: each ray takes random waves in birefringent crystals (LensRay::wave_choices).
inline BatchAgreement CompareTracers(const LensSystem& lens, int count, double aim_half, double plane_z, uint64_t seed,
                                     uint64_t stream, bool random_waves = false) {
  BatchLensTracer fast(lens);
  RayBatch batch;
  std::vector<LensRay> rays;
  PCG32 rng(seed, stream);
  const double rear_z = lens.VertexZ(lens.SurfaceCount() - 1);
  for (int k = 0; k < count; ++k) {
    const Vec3d o(rng.UniformFloat() * 36 - 18, rng.UniformFloat() * 24 - 12, lens.FilmZ());
    const Vec3d aim(rng.UniformFloat() * 2 * aim_half - aim_half, rng.UniformFloat() * 2 * aim_half - aim_half, rear_z);
    const Vec3d d = Normalize(aim - o);
    const uint32_t waves = random_waves ? rng.Uniform32() : 0;
    rays.push_back({o, d, false, waves});
    batch.Push({float(o.x), float(o.y), float(o.z), float(d.x), float(d.y), float(d.z), 550.f, 1.f, waves});
  }
  fast.TraceFromFilm(batch);
  BatchAgreement a;
  a.rays = count;
  for (size_t k = 0; k < rays.size(); ++k) {
    const TraceResult exact = TraceFromFilm(lens, rays[k], 550);
    a.agree += bool(exact.ray) == bool(batch.alive[k]);
    if (!exact.ray || !batch.alive[k]) continue;
    ++a.through;
    const double t_exact = (plane_z - exact.ray->o.z) / exact.ray->d.z, t_fast = (plane_z - batch.oz[k]) / batch.dz[k];
    a.worst_mm = std::max(a.worst_mm, std::hypot(exact.ray->o.x + t_exact * exact.ray->d.x - (batch.ox[k] + t_fast * batch.dx[k]),
                                                 exact.ray->o.y + t_exact * exact.ray->d.y - (batch.oy[k] + t_fast * batch.dy[k])));
    a.worst_transmittance = std::max(
        a.worst_transmittance, std::abs(batch.transmittance[k] - exact.Transmittance()));
  }
  return a;
}

// What each surface kind's test expects of the comparison: transmittances within 1e-4, more
// than `min_through` rays through both, at most `rim_slack` going either way (rays that graze a
// rim or an edge in single precision) and positions within `worst_mm` on the plane.
inline void ExpectAgreement(const BatchAgreement& a, int min_through, int rim_slack, double worst_mm) {
  EXPECT_LE(a.worst_transmittance, 1e-4);
  EXPECT_GT(a.through, min_through);
  EXPECT_GE(a.agree, a.rays - rim_slack);
  EXPECT_LT(a.worst_mm, worst_mm);
}

}  // namespace objektiv::test
