#include "optics/real_fnumber.h"

#include <cmath>

#include "optics/paraxial.h"

namespace objektiv {

namespace {
LensSystem AtInfinityFocus(const LensSystem& lens, double lambda_nm) {
  LensSystem t = lens;
  t.SetBackFocus(ComputeParaxial(t.prescription(), lambda_nm, t.StopSemiDiameter()).bfl);
  return t;
}

LensRay ConeRay(const LensSystem& t, double sin_u) {
  return {{0, 0, t.FilmZ()}, {0, sin_u, -std::sqrt(1 - sin_u * sin_u)}};
}
}  // namespace

double RealFNumber(const LensSystem& lens, double lambda_nm) {
  LensSystem t = AtInfinityFocus(lens, lambda_nm);
  // The cone's edge: the steepest ray from the axial film point that gets through.
  double lo = 0, hi = 1;
  for (int it = 0; it < 60; ++it) {
    double mid = 0.5 * (lo + hi);
    (TraceFromFilm(t, ConeRay(t, mid), lambda_nm).ray ? lo : hi) = mid;
  }
  return lo > 0 ? 1 / (2 * lo) : INFINITY;
}

std::optional<double> StopSemiDiameterForFNumber(const LensSystem& lens, double fnumber, double lambda_nm) {
  if (!(fnumber > 0.5)) return std::nullopt;
  LensSystem t = AtInfinityFocus(lens, lambda_nm);
  // Where the cone's edge ray crosses the stop: the stop's radius for that cone.
  std::optional<Vec3d> hit = StopCrossingFromFilm(t, ConeRay(t, 1 / (2 * fnumber)), lambda_nm);
  if (!hit) return std::nullopt;
  double semi = std::hypot(hit->x, hit->y);
  if (semi > t.StopSemiDiameter() * (1 + 1e-9)) return std::nullopt;
  return semi;
}

}  // namespace objektiv
