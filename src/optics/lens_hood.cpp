#include "optics/lens_hood.h"

#include <cmath>

#include <fmt/format.h>

namespace objektiv {

bool LensHood::Passes(const Vec3d& o, const Vec3d& d, double first_vertex_z) const {
  if (d.z == 0) return false;
  const double t = (first_vertex_z - length - o.z) / d.z;
  const double x = o.x + t * d.x, y = o.y + t * d.y;
  return radius > 0 ? x * x + y * y <= radius * radius : std::abs(x) <= half_width && std::abs(y) <= half_height;
}

std::string LensHood::Mismatch(const LensSurface& front) const {
  if (!(length > 0)) return fmt::format("hood_length {} mm: a hood reaches forward from the lens (above 0)", length);
  // The element's reach from the axis and its foremost point: the rim (and the vertex) as placed.
  double reach = 0, foremost = 0;
  for (int k = 0; k < 64; ++k) {
    const double a = 2 * M_PI * k / 64, x = front.semi_diameter * std::cos(a), y = front.semi_diameter * std::sin(a);
    double z = 0;
    front.SagAt(x, y, z);
    for (const Vec3d& local : {Vec3d(x, y, z), Vec3d(0, 0, 0)}) {
      const Vec3d p = front.placement ? front.placement->PointFromLocal(local) : local;
      reach = std::max(reach, std::hypot(p.x, p.y));
      foremost = std::min(foremost, p.z);
    }
  }
  const double narrowest = radius > 0 ? radius : std::min(half_width, half_height);
  if (narrowest < reach)
    return fmt::format("the hood's mouth ({}) is narrower than the front element ({:.4g} mm across as placed): a hood "
                       "encloses it",
                       radius > 0 ? fmt::format("{:g} mm across", 2 * radius)
                                  : fmt::format("{:g} x {:g} mm", 2 * half_width, 2 * half_height),
                       2 * reach);
  if (-length > foremost - 1e-9)
    return fmt::format("hood_length {:g} mm: the front element's rim reaches {:.4g} mm before its vertex; the mouth must "
                       "lie in front of it", length, -foremost);
  return "";
}

std::string LensHood::Describe() const {
  return radius > 0 ? fmt::format("round, {:g} mm long, {:g} mm across", length, 2 * radius)
                    : fmt::format("rectangular, {:g} mm long, {:g} x {:g} mm", length, 2 * half_width, 2 * half_height);
}

}  // namespace objektiv
