// Rays and robust ray spawning (offsets from floating-point error bounds, as pbrt does,
// so that no fixed epsilon is needed at any scene scale).
#pragma once
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "base/vec.h"

namespace objektiv {

struct Ray {
  Vec3f o, d;
  float tmax = std::numeric_limits<float>::infinity();
};

// gamma(n) = n u / (1 - n u), u = 2^-24: bound on the relative error of n float operations.
constexpr float Gamma(int n) {
  constexpr float u = 0x1p-24f;
  return (n * u) / (1 - n * u);
}

// The adjacent float above / below v, by stepping its bit pattern (as pbrt does; cheaper
// than std::nextafter, which is a library call). -0 is treated as +0; infinities stay.
inline float NextFloatUp(float v) {
  if (std::isinf(v) && v > 0) return v;
  if (v == -0.f) v = 0.f;
  uint32_t ui = std::bit_cast<uint32_t>(v);
  ui = v >= 0 ? ui + 1 : ui - 1;
  return std::bit_cast<float>(ui);
}
inline float NextFloatDown(float v) {
  if (std::isinf(v) && v < 0) return v;
  if (v == 0.f) v = -0.f;
  uint32_t ui = std::bit_cast<uint32_t>(v);
  ui = v > 0 ? ui - 1 : ui + 1;
  return std::bit_cast<float>(ui);
}

// One ulp further in the direction of `dir` (v itself where dir is 0).
inline float NextFloatToward(float v, float dir) {
  if (dir > 0) return NextFloatUp(v);
  if (dir < 0) return NextFloatDown(v);
  return v;
}

// Move p (with absolute error bound p_error) off its surface (normal n) to the side of w,
// far enough that a ray leaving in direction w cannot re-hit the surface it left.
inline Vec3f OffsetRayOrigin(const Vec3f& p, const Vec3f& p_error, const Vec3f& n, const Vec3f& w) {
  float d = Dot(Abs(n), p_error);
  Vec3f offset = n * d;
  if (Dot(w, n) < 0) offset = -offset;
  Vec3f po = p + offset;
  // Built from three scalars: writing the components one by one through memory made the
  // caller's wide load of the result wait (store forwarding fails), 1.5% of a render.
  return {NextFloatToward(po.x, offset.x), NextFloatToward(po.y, offset.y), NextFloatToward(po.z, offset.z)};
}

}  // namespace objektiv
