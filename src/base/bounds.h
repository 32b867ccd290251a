// Axis-aligned bounding boxes.
#pragma once
#include <limits>

#include "base/vec.h"

namespace objektiv {

struct Bounds3f {
  Vec3f lo{std::numeric_limits<float>::infinity()}, hi{-std::numeric_limits<float>::infinity()};

  bool Empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  void Extend(const Vec3f& p) {
    lo = Min(lo, p);
    hi = Max(hi, p);
  }
  void Extend(const Bounds3f& b) {
    lo = Min(lo, b.lo);
    hi = Max(hi, b.hi);
  }
  Vec3f Center() const { return (lo + hi) * 0.5f; }
  // Radius of the bounding sphere around the centre.
  float Radius() const { return Empty() ? 0.f : Length(hi - lo) * 0.5f; }
};

}  // namespace objektiv
