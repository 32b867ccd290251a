#include "optics/front_element.h"

#include <cmath>

#include "optics/lens_tracer.h"

namespace objektiv {

FrontPoint SampleFrontElement(const LensSystem& lens, Vec2d u) {
  const LensSurface& s = lens.surface(0);
  // Uniform over the disc: radius sqrt(u) r (a uniform density needs no concentric map here).
  const double rho = s.semi_diameter * std::sqrt(u.x), phi = 2 * M_PI * u.y;
  const double x = rho * std::cos(phi), y = rho * std::sin(phi);
  FrontPoint f;
  double sag = 0;
  s.SagAt(x, y, sag);  // inside the clear disc the surface is whole (CheckReachable)
  const Vec3d local(x, y, sag);
  f.normal = SurfaceNormal(s, local);
  f.p = Vec3d(0, 0, lens.VertexZ(0)) + local;
  if (s.placement) {  // decentred or tilted: the point and the normal carried into lens space
    f.p = lens.FromSurfaceFrame(0, local);
    f.normal = s.placement->FromLocal(f.normal);
    f.axis = s.placement->ez;
  }
  return f;
}

double FrontElementArea(const LensSystem& lens) {
  const double r = lens.surface(0).semi_diameter;
  return M_PI * r * r;
}

}  // namespace objektiv
