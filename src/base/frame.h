// Orthonormal frames: local shading coordinates with the normal as z axis.
#pragma once
#include "base/vec.h"

namespace objektiv {

struct Frame {
  Vec3f s, t, n;

  Frame() : s(1, 0, 0), t(0, 1, 0), n(0, 0, 1) {}
  Frame(const Vec3f& s_, const Vec3f& t_, const Vec3f& n_) : s(s_), t(t_), n(n_) {}

  // Branchless basis from a unit normal (Duff et al., "Building an Orthonormal Basis, Revisited", 2017).
  static Frame FromZ(const Vec3f& n) {
    float sign = std::copysign(1.f, n.z);
    float a = -1.f / (sign + n.z);
    float b = n.x * n.y * a;
    return Frame(Vec3f(1 + sign * n.x * n.x * a, sign * b, -sign * n.x), Vec3f(b, sign + n.y * n.y * a, -n.y), n);
  }
  // Frame with z = n and x as close to the tangent dpdu as possible (Gram-Schmidt).
  static Frame FromNormalTangent(const Vec3f& n, const Vec3f& dpdu) {
    Vec3f s = dpdu - n * Dot(n, dpdu);
    float len2 = LengthSquared(s);
    if (!(len2 > 1e-12f)) return FromZ(n);
    s = s / std::sqrt(len2);
    return Frame(s, Cross(n, s), n);
  }

  Vec3f ToLocal(const Vec3f& v) const { return {Dot(v, s), Dot(v, t), Dot(v, n)}; }
  Vec3f FromLocal(const Vec3f& v) const { return s * v.x + t * v.y + n * v.z; }
};

}  // namespace objektiv
