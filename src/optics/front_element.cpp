#include "optics/front_element.h"

#include <cmath>

namespace objektiv {

FrontPoint SampleFrontElement(const LensSystem& lens, Vec2d u) {
  const LensSurface& s = lens.surface(0);
  // Uniform over the disc: radius sqrt(u) r (a uniform density needs no concentric map here).
  const double rho = s.semi_diameter * std::sqrt(u.x), phi = 2 * M_PI * u.y;
  const double x = rho * std::cos(phi), y = rho * std::sin(phi);
  FrontPoint f;
  f.p = {x, y, lens.VertexZ(0) + s.Sag(rho)};
  // z = sag(r): the normal (-dz/dx, -dz/dy, 1) normalised.
  const double slope = rho > 0 ? s.SagSlope(rho) : 0;
  const Vec3d n = rho > 0 ? Vec3d(-slope * x / rho, -slope * y / rho, 1) : Vec3d(0, 0, 1);
  f.normal = n / Length(n);
  return f;
}

double FrontElementArea(const LensSystem& lens) {
  const double r = lens.surface(0).semi_diameter;
  return M_PI * r * r;
}

}  // namespace objektiv
