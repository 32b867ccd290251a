#include "render/flare_sources.h"

#include <cmath>

namespace objektiv {

namespace {

// Points spread evenly over a disc of radius r (a Fibonacci spiral), lens space at z.
std::vector<Vec3d> DiscPoints(int n, double r, double z) {
  std::vector<Vec3d> points;
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double rho = r * std::sqrt((i + 0.5) / n), phi = i * golden;
    points.push_back({rho * std::cos(phi), rho * std::sin(phi), z});
  }
  return points;
}

// The share of the front element's points from which the light is unoccluded: toward a
// point (stopping just short of it) or toward where a directional light comes from.
double Visibility(const Scene& scene, const RealisticCamera& camera, const std::vector<Vec3d>& front,
                  const Vec3f* position, const Vec3f* travel) {
  int seen = 0;
  for (const Vec3d& lp : front) {
    Ray ray;
    ray.o = camera.WorldPoint(lp);
    if (position) {
      const Vec3f to = *position - ray.o;
      const float distance = Length(to);
      if (!(distance > 0)) continue;
      ray.d = to / distance;
      ray.tmax = distance * (1 - 1e-4f);
    } else {
      ray.d = -*travel;
    }
    seen += !scene.Occluded(ray);
  }
  return front.empty() ? 0 : double(seen) / front.size();
}

}  // namespace

std::vector<FlareSource> FindFlareSources(const Scene& scene, const RealisticCamera& camera, int visibility_samples) {
  const LensSystem& lens = camera.lens();
  const std::vector<Vec3d> front = DiscPoints(visibility_samples, lens.surface(0).semi_diameter, lens.VertexZ(0));
  const double mm_to_units = 1e-3 / camera.settings().metres_per_unit;
  const Vec3f lens_centre = camera.WorldPoint(Vec3d(0, 0, lens.VertexZ(0)));
  std::vector<FlareSource> out;
  for (const std::unique_ptr<Light>& light : scene.lights()) {
    FlareSource f;
    const Vec3f* position = nullptr;
    const Vec3f* travel = nullptr;
    if (const auto* point = dynamic_cast<const PointLight*>(light.get())) {
      position = &point->position();
      f.emission = &point->intensity();
    } else if (const auto* spot = dynamic_cast<const SpotLight*>(light.get())) {
      position = &spot->position();
      f.emission = &spot->intensity();
      const Vec3f to_lens = lens_centre - spot->position();
      if (!(Length(to_lens) > 0)) continue;
      f.factor = spot->Falloff(Normalize(to_lens));
    } else if (const auto* sun = dynamic_cast<const DirectionalLight*>(light.get())) {
      travel = &sun->direction();
      f.emission = &sun->irradiance();
    } else {
      continue;  // area and environment lights: not points
    }
    if (position) {
      f.source = PointSource::At(camera.LensSpacePoint(*position));
      f.irradiance_scale = 1 / (mm_to_units * mm_to_units);
      if (!(f.source.position.z < lens.VertexZ(0))) continue;  // not in front of the lens
    } else {
      f.source = PointSource::Distant(camera.LensSpaceDirection(*travel));
      if (!(f.source.direction.z > 0)) continue;  // travelling away from the lens
    }
    if (f.factor <= 0) continue;
    f.visibility = Visibility(scene, camera, front, position, travel);
    if (f.visibility > 0) out.push_back(f);
  }
  return out;
}

}  // namespace objektiv
