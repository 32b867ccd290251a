// What a ray hit: position with its error bound, normals, shading frame, texture coordinates.
#pragma once
#include <cmath>

#include "base/frame.h"
#include "base/ray.h"

namespace objektiv {

class Light;
struct ShapeRecord;

struct SurfaceInteraction {
  Vec3f p, p_error;
  Vec3f n;        // geometric normal (unit; oriented as the shape defines its outside)
  Frame shading;  // shading frame (z = shading normal, on the same side as n)
  Vec2f uv;
  // The surface's partial derivatives along its (u, v) parameterisation, in world units per
  // unit of uv (docs/scene-format.md lists each shape's). Zero where the parameterisation is
  // singular (a sphere's poles, a disk's centre): there only dpdu or dpdv may be used.
  // Bump and normal maps read them; the shading frame's tangent s follows dpdu.
  Vec3f dpdu, dpdv;
  Vec3f wo;       // direction back toward the ray origin
  float t = 0;
  const ShapeRecord* shape = nullptr;

  Ray SpawnRay(const Vec3f& d) const { return Ray{OffsetRayOrigin(p, p_error, n, d), d}; }
  // The rest of `ray`, which met this surface and passes it (a medium's null boundary, a mask's
  // hole): from just beyond it, in the same direction, to the same end point (tmax in units of
  // ray.d; infinite stays infinite). A tmax <= 0 means nothing of the ray is left.
  Ray ContinueBeyond(const Ray& ray) const {
    Ray next = SpawnRay(ray.d);
    if (std::isfinite(ray.tmax)) next.tmax = ray.tmax - Dot(next.o - ray.o, ray.d) / Dot(ray.d, ray.d);
    return next;
  }
  // Shadow ray toward a point (with its own error bound, e.g. on a light); stops just short of it.
  Ray SpawnRayTo(const Vec3f& target, const Vec3f& target_error, const Vec3f& target_n) const {
    Vec3f d0 = target - p;
    Vec3f from = OffsetRayOrigin(p, p_error, n, d0);
    Vec3f to = OffsetRayOrigin(target, target_error, target_n, from - target);
    Vec3f d = to - from;
    return Ray{from, d, 1 - 1e-4f};
  }
};

}  // namespace objektiv
