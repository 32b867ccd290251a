#include "optics/real_fnumber.h"

#include <cmath>

#include "optics/paraxial.h"

namespace objektiv {

namespace {
LensSystem AtInfinityFocus(const LensSystem& lens, double lambda_nm) {
  LensSystem t = lens;
  t.SetBackFocus(t.Paraxial(lambda_nm).bfl);
  return t;
}

LensRay ConeRay(const LensSystem& t, double sin_u) {
  return {{0, 0, t.FilmZ()}, {0, sin_u, -std::sqrt(1 - sin_u * sin_u)}};
}

constexpr int kScan = 1024;  // steps of sin u over (0, 1] where the axis is blocked

// The boundary between sin u = a and b (one passes, the other not), by bisection.
double Edge(const LensSystem& t, double a, double b, double lambda_nm) {
  const bool a_passes = TraceFromFilm(t, ConeRay(t, a), lambda_nm).ray.has_value();
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (a + b);
    (TraceFromFilm(t, ConeRay(t, mid), lambda_nm).ray.has_value() == a_passes ? a : b) = mid;
  }
  return a_passes ? a : b;
}

// The first step of the scan at which a ray gets through (0 where none does).
int FirstPassing(const LensSystem& t, double lambda_nm) {
  for (int k = 1; k <= kScan; ++k)
    if (TraceFromFilm(t, ConeRay(t, double(k) / kScan), lambda_nm).ray) return k;
  return 0;
}
}  // namespace

double RealFNumber(const LensSystem& lens, double lambda_nm) {
  LensSystem t = AtInfinityFocus(lens, lambda_nm);
  // The cone's edge: the steepest ray from the axial film point that gets through.
  if (!TraceFromFilm(t, ConeRay(t, 0), lambda_nm).ray) {
    // A central obstruction: the cone is a hollow one; its outer edge beyond the first
    // passing ray of a scan.
    int k = FirstPassing(t, lambda_nm);
    if (k == 0) return INFINITY;
    while (k < kScan && TraceFromFilm(t, ConeRay(t, double(k + 1) / kScan), lambda_nm).ray) ++k;
    return 1 / (2 * Edge(t, double(k) / kScan, std::min(1.0, double(k + 1) / kScan), lambda_nm));
  }
  double lo = 0, hi = 1;
  for (int it = 0; it < 60; ++it) {
    double mid = 0.5 * (lo + hi);
    (TraceFromFilm(t, ConeRay(t, mid), lambda_nm).ray ? lo : hi) = mid;
  }
  return lo > 0 ? 1 / (2 * lo) : INFINITY;
}

double ObstructionRatio(const LensSystem& lens, double lambda_nm) {
  const std::optional<double> hidden = ObstructionFNumber(lens, lambda_nm);
  return hidden ? RealFNumber(lens, lambda_nm) / *hidden : 0.0;
}

std::optional<double> ObstructionFNumber(const LensSystem& lens, double lambda_nm) {
  LensSystem t = AtInfinityFocus(lens, lambda_nm);
  if (TraceFromFilm(t, ConeRay(t, 0), lambda_nm).ray) return std::nullopt;
  const int k = FirstPassing(t, lambda_nm);
  if (k == 0) return std::nullopt;
  return 1 / (2 * Edge(t, double(k) / kScan, double(k - 1) / kScan, lambda_nm));
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
