#include "optics/lens_walk.h"

#include <algorithm>

namespace objektiv {

LensWalk WalkFromObject(const LensSystem& lens, const LensRay& in, double lambda_nm, PCG32& rng,
                        const LensWalkOptions& options) {
  LensWalk walk;
  const int n = lens.SurfaceCount(), stop = lens.StopIndex();
  const double stop_radius = lens.StopSemiDiameter();
  LensRay ray = in;
  // Unpolarised light: each crystal's wave chosen with probability 1/2 (optics/uniaxial_crystal.h).
  if (lens.prescription().CrystalCount() > 0) ray.wave_choices = rng.Uniform32();
  if (!lens.PassesHood(ray.o, ray.d)) return walk;  // the scene's light enters through the hood
  double weight = 1;
  int i = 0, previous = -1;
  bool toward_film = true;
  // Each step crosses one surface; a walk that bounces without end (possible only between
  // totally reflecting surfaces) is cut off.
  for (int step = 0; step < 64 * n; ++step) {
    if (i < 0) return walk;  // out of the front: lost to the scene
    if (i == n) {
      // Past the last surface toward the film: the film plane.
      if (!(ray.d.z > 0)) return walk;
      const double t = (lens.FilmZ() - ray.o.z) / ray.d.z;
      if (!(t >= 0)) return walk;
      walk.film = LensRay{ray.o + ray.d * t, ray.d, ray.extraordinary, ray.wave_choices};
      walk.weight = weight;
      return walk;
    }
    const SurfaceCrossing c = CrossSurface(lens, i, ray, lambda_nm, toward_film);
    if (c.failure != TraceFailure::kNone) return walk;
    if (previous >= 0 && !options.lossless) weight *= SegmentTransmittance(lens, previous, i, lambda_nm, c.t);
    previous = i;
    weight *= c.clean;  // dust and scratches (lossless or not: they block)
    if (!(weight > 0)) return walk;
    if (i == stop && options.stop_transmittance) {
      weight *= options.stop_transmittance(c.p.x / stop_radius, c.p.y / stop_radius);
      if (!(weight > 0)) return walk;
    }
    if (c.mirror) {  // reflects all it does not absorb; the walk goes on in the same order
      if (!options.lossless) weight *= c.reflectance;
      ray = Reflected(c, c.d);
      i += toward_film ? 1 : -1;
      continue;
    }
    bool reflect = false;
    std::optional<LensRay> refracted;
    if (c.interface) {
      refracted = Refracted(c, c.d);
      if (!refracted) {
        reflect = true;  // beyond the critical angle: all of it
      } else if (!options.lossless) {
        const double r = c.reflectance, q = std::max(r, options.min_reflect_probability);
        reflect = rng.UniformFloat() < q;
        weight *= reflect ? r / q : (1 - r) / (1 - q);
      }
    }
    if (reflect) {
      if (++walk.reflections > options.max_reflections) return walk;
      ray = Reflected(c, c.d);
      toward_film = !toward_film;
    } else {
      ray = refracted ? *refracted : Onward(c);
    }
    i += toward_film ? 1 : -1;
  }
  return walk;
}

}  // namespace objektiv
