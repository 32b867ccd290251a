#include "optics/crystal_images.h"

#include <cmath>

#include "optics/lens_tracer.h"

namespace objektiv {

namespace {

// The centroid on the film of the rays that get through with `waves`; nothing if none does.
std::optional<Vec2d> FilmCentroid(const LensSystem& lens, double lambda_nm, uint32_t waves) {
  const double radius = 0.25 * lens.Paraxial(lambda_nm).entrance_pupil_diameter;
  const double start_z = lens.VertexZ(0) - 1 - (lens.hood() ? lens.hood()->length : 0.0);
  Vec2d sum(0, 0);
  int count = 0;
  for (int k = 0; k < 17; ++k) {
    const double r = k == 0 ? 0 : radius * (k <= 8 ? 0.5 : 1), a = 2 * M_PI * (k % 8) / 8;
    const TraceResult t = TraceFromObject(lens, {Vec3d(r * std::cos(a), r * std::sin(a), start_z), Vec3d(0, 0, 1), false, waves},
                                          lambda_nm);
    if (!t.ray || !(t.ray->d.z > 0)) continue;
    const Vec3d p = t.ray->o + t.ray->d * ((lens.FilmZ() - t.ray->o.z) / t.ray->d.z);
    sum = sum + Vec2d(p.x, p.y);
    ++count;
  }
  if (count == 0) return std::nullopt;
  return sum * (1.0 / count);
}

}  // namespace

std::vector<std::optional<Vec2d>> ExtraordinaryImageOffsets(const LensSystem& lens, double lambda_nm) {
  const int crystals = lens.prescription().CrystalCount();
  std::vector<std::optional<Vec2d>> out(static_cast<size_t>(crystals));
  const std::optional<Vec2d> ordinary = FilmCentroid(lens, lambda_nm, 0);
  if (!ordinary) return out;
  for (int k = 0; k < crystals; ++k)
    if (const std::optional<Vec2d> e = FilmCentroid(lens, lambda_nm, 1u << k)) out[size_t(k)] = *e - *ordinary;
  return out;
}

}  // namespace objektiv
