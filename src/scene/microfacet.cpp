#include "scene/microfacet.h"

#include "base/sampling.h"

namespace objektiv {

Vec3f TrowbridgeReitz::SampleVisible(Vec3f w, Vec2f u) const {
  // Stretch to the hemisphere configuration, sample a projected disk, unstretch.
  // The sampled normal always lies in the upper hemisphere.
  if (w.z < 0) w = -w;
  Vec3f wh = Normalize(Vec3f(ax_ * w.x, ay_ * w.y, w.z));
  Vec3f t1 = wh.z < 0.99999f ? Normalize(Cross(Vec3f(0, 0, 1), wh)) : Vec3f(1, 0, 0);
  Vec3f t2 = Cross(wh, t1);
  Vec2f p = SampleUniformDiskConcentric(u);
  // Warp the lower half of the disk toward the visible part of the hemisphere.
  float h = std::sqrt(1 - p.x * p.x);
  p.y = Lerp((1 + wh.z) / 2, h, p.y);
  float pz = SafeSqrt(1 - p.x * p.x - p.y * p.y);
  Vec3f nh = t1 * p.x + t2 * p.y + wh * pz;
  Vec3f wm = Normalize(Vec3f(ax_ * nh.x, ay_ * nh.y, std::max(1e-6f, nh.z)));
  return wm;
}

}  // namespace objektiv
