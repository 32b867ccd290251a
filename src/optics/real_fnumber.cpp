#include "optics/real_fnumber.h"

#include <cmath>

#include "optics/paraxial.h"

namespace objektiv {

namespace {
LensTracer AtInfinityFocus(const LensTracer& tracer, double lambda_nm) {
  LensTracer t = tracer;
  t.SetBackFocus(ComputeParaxial(t.lens(), lambda_nm, t.StopSemiDiameter()).bfl);
  return t;
}

LensRay ConeRay(const LensTracer& t, double sin_u) {
  return {{0, 0, t.FilmZ()}, {0, sin_u, -std::sqrt(1 - sin_u * sin_u)}};
}
}  // namespace

double RealFNumber(const LensTracer& tracer, double lambda_nm) {
  LensTracer t = AtInfinityFocus(tracer, lambda_nm);
  // The cone's edge: the steepest ray from the axial film point that gets through.
  double lo = 0, hi = 1;
  for (int it = 0; it < 60; ++it) {
    double mid = 0.5 * (lo + hi);
    (t.TraceFromFilm(ConeRay(t, mid), lambda_nm).ray ? lo : hi) = mid;
  }
  return lo > 0 ? 1 / (2 * lo) : INFINITY;
}

std::optional<double> StopSemiDiameterForFNumber(const LensTracer& tracer, double fnumber, double lambda_nm) {
  if (!(fnumber > 0.5)) return std::nullopt;
  LensTracer t = AtInfinityFocus(tracer, lambda_nm);
  // Where the cone's edge ray crosses the stop: the stop's radius for that cone.
  std::optional<Vec3d> hit = t.StopCrossingFromFilm(ConeRay(t, 1 / (2 * fnumber)), lambda_nm);
  if (!hit) return std::nullopt;
  double semi = std::hypot(hit->x, hit->y);
  if (semi > t.StopSemiDiameter() * (1 + 1e-9)) return std::nullopt;
  return semi;
}

}  // namespace objektiv
