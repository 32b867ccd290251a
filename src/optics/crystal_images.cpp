#include "optics/crystal_images.h"

#include <cmath>

#include "optics/lens_tracer.h"

namespace objektiv {

namespace {

struct Spot {
  Vec2d centroid;
  double rms;
};

// The rays that get through with `waves`: their centroid on the film and RMS spread.
std::optional<Spot> FilmSpot(const LensSystem& lens, double lambda_nm, uint32_t waves) {
  const double radius = 0.25 * lens.Paraxial(lambda_nm).entrance_pupil_diameter;
  const double start_z = lens.VertexZ(0) - 1 - (lens.hood() ? lens.hood()->length : 0.0);
  std::vector<Vec2d> points;
  for (int k = 0; k < 17; ++k) {
    const double r = k == 0 ? 0 : radius * (k <= 8 ? 0.5 : 1), a = 2 * M_PI * (k % 8) / 8;
    const TraceResult t = TraceFromObject(lens, {Vec3d(r * std::cos(a), r * std::sin(a), start_z), Vec3d(0, 0, 1), false, waves},
                                          lambda_nm);
    if (!t.ray || !(t.ray->d.z > 0)) continue;
    const Vec3d p = t.ray->o + t.ray->d * ((lens.FilmZ() - t.ray->o.z) / t.ray->d.z);
    points.push_back(Vec2d(p.x, p.y));
  }
  if (points.empty()) return std::nullopt;
  Vec2d sum(0, 0);
  for (const Vec2d& p : points) sum = sum + p;
  const Vec2d c = sum * (1.0 / points.size());
  double s2 = 0;
  for (const Vec2d& p : points) s2 += (p.x - c.x) * (p.x - c.x) + (p.y - c.y) * (p.y - c.y);
  return Spot{c, std::sqrt(s2 / points.size())};
}

}  // namespace

std::optional<CrystalImages> CrystalImagesOf(const LensSystem& lens, double lambda_nm) {
  const int crystals = lens.prescription().CrystalCount();
  if (crystals == 0) return std::nullopt;
  const std::optional<Spot> ordinary = FilmSpot(lens, lambda_nm, 0);
  if (!ordinary) return std::nullopt;
  CrystalImages out;
  out.ordinary_rms = ordinary->rms;
  for (int k = 0; k < crystals; ++k) {
    const std::optional<Spot> e = FilmSpot(lens, lambda_nm, 1u << k);
    out.extraordinary.push_back(e ? std::optional<CrystalImage>(CrystalImage{e->centroid - ordinary->centroid, e->rms})
                                  : std::nullopt);
  }
  return out;
}

}  // namespace objektiv
