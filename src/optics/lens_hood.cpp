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

std::string LensHood::Mismatch(double front_semi) const {
  if (!(length > 0)) return fmt::format("hood_length {} mm: a hood reaches forward from the lens (above 0)", length);
  const double narrowest = radius > 0 ? radius : std::min(half_width, half_height);
  if (narrowest < front_semi)
    return fmt::format("the hood's mouth ({}) is narrower than the front element ({:.4g} mm across): a hood encloses it",
                       radius > 0 ? fmt::format("{:g} mm across", 2 * radius)
                                  : fmt::format("{:g} x {:g} mm", 2 * half_width, 2 * half_height),
                       2 * front_semi);
  return "";
}

std::string LensHood::Describe() const {
  return radius > 0 ? fmt::format("round, {:g} mm long, {:g} mm across", length, 2 * radius)
                    : fmt::format("rectangular, {:g} mm long, {:g} x {:g} mm", length, 2 * half_width, 2 * half_height);
}

}  // namespace objektiv
