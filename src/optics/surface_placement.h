// Where a surface sits when the lens is not centred (a decentred or tilted element, Zemax's
// coordinate breaks): a rigid placement of the surface's own frame (its vertex at the origin,
// its axis along z, where its sag is defined) relative to its nominal place on the lens's axis,
// the point (0, 0, vertex z). A point p_s of the surface's frame lies at
//   p = (0, 0, vertex z) + offset + ex p_s.x + ey p_s.y + ez p_s.z
// in lens space; ex, ey, ez are the surface's axes there (orthonormal, right-handed).
//
// DecenterTilt builds the placement Zemax's coordinate break of order 0 gives: decentre by
// (dx, dy), then tilt about x, then about the new y, then about the new z, each a right-handed
// turn (a positive tilt about x turns +y toward +z).
#pragma once
#include <cmath>

#include "base/vec.h"

namespace objektiv {

struct SurfacePlacement {
  Vec3d offset{0, 0, 0};
  Vec3d ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};

  // A direction in lens space in the surface's frame, and back.
  Vec3d ToLocal(const Vec3d& v) const { return {Dot(v, ex), Dot(v, ey), Dot(v, ez)}; }
  Vec3d FromLocal(const Vec3d& v) const { return ex * v.x + ey * v.y + ez * v.z; }
  // A point of the surface's frame relative to its nominal vertex (the inverse of
  // ToLocal(p - offset)).
  Vec3d PointFromLocal(const Vec3d& p) const { return offset + FromLocal(p); }
  // The surface turned by the right-handed angle (radians) about its own axis `axis` (0 x, 1 y, 2 z).
  SurfacePlacement Turned(int axis, double angle) const {
    const double c = std::cos(angle), s = std::sin(angle);
    SurfacePlacement p = *this;
    Vec3d& a = axis == 0 ? p.ey : axis == 1 ? p.ez : p.ex;  // the pair of axes that turns:
    Vec3d& b = axis == 0 ? p.ez : axis == 1 ? p.ex : p.ey;  // a -> c a + s b, b -> c b - s a
    const Vec3d a0 = a, b0 = b;
    a = a0 * c + b0 * s;
    b = b0 * c - a0 * s;
    return p;
  }
  static SurfacePlacement DecenterTilt(double dx, double dy, double tilt_x_deg, double tilt_y_deg, double tilt_z_deg) {
    SurfacePlacement p;
    p.offset = {dx, dy, 0};
    const double k = M_PI / 180;
    return p.Turned(0, tilt_x_deg * k).Turned(1, tilt_y_deg * k).Turned(2, tilt_z_deg * k);
  }
  // This placement (of a surface whose vertex lies at `vertex` on the axis) after the rigid
  // motion `motion` (its turn, then its offset) about the point `pivot` of lens space.
  SurfacePlacement MovedBy(const SurfacePlacement& motion, const Vec3d& pivot, const Vec3d& vertex) const {
    SurfacePlacement moved;
    moved.offset = pivot + motion.offset + motion.FromLocal(vertex + offset - pivot) - vertex;
    moved.ex = motion.FromLocal(ex), moved.ey = motion.FromLocal(ey), moved.ez = motion.FromLocal(ez);
    return moved;
  }
  bool IsIdentity() const {
    return offset.x == 0 && offset.y == 0 && offset.z == 0 && ex.x == 1 && ey.y == 1 && ez.z == 1 && ex.y == 0 &&
           ex.z == 0 && ey.x == 0 && ey.z == 0 && ez.x == 0 && ez.y == 0;
  }
};

}  // namespace objektiv
