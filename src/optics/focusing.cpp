#include "optics/focusing.h"

#include <cmath>

#include "optics/paraxial.h"

namespace objektiv {

namespace {
// y-nu trace of a ray leaving the axial object point with slope 1; returns the height and
// reduced angle after the last surface, and the height at the stop.
struct ObjectRay {
  double y_end, nu_end, y_stop;
};
ObjectRay TraceFromObjectPoint(const LensPrescription& lens, double s, double lambda_nm) {
  // Slope 1 over the object distance s, in the object medium; through mirrors and gradients too.
  std::vector<double> heights;
  const auto [y, nu] = TraceParaxialForward(lens, lambda_nm, s, lens.IndexBefore(0, lambda_nm), &heights);
  const int stop = lens.StopIndex();
  return {y, nu, stop >= 0 ? heights[size_t(stop)] : 0.0};
}
}  // namespace

FocusSolution ImageObject(const LensPrescription& lens, double s, double lambda_nm) {
  ObjectRay r = TraceFromObjectPoint(lens, s, lambda_nm);
  FocusSolution f;
  f.object_to_first_vertex = s;
  f.back_focus = -r.y_end / r.nu_end;
  f.magnification = lens.IndexBefore(0, lambda_nm) / r.nu_end;  // Lagrange: n u / n' u', n u = n0 at the object
  int stop = lens.StopIndex();
  double semi = stop >= 0 ? lens.surfaces[stop].semi_diameter : 0;
  // Scale the ray to pass the stop's edge: its slope at the film gives the cone of light.
  double u_image = r.y_stop != 0 ? r.nu_end * semi / std::abs(r.y_stop) : 0;
  f.working_fnumber = u_image != 0 ? 1 / (2 * std::abs(u_image)) : 0;
  return f;
}

std::optional<FocusSolution> FocusAtDistance(const LensPrescription& lens, double distance_from_film, double lambda_nm) {
  const double track = lens.TotalTrack();
  ParaxialData p = ComputeParaxial(lens, lambda_nm);
  // g(t) = (image distance of the object at D - track - t) - t; zero when in focus. At
  // t = BFL the object is at a finite distance, its image lies beyond BFL: g > 0. Search
  // upward for a sign change while the object stays outside the front focus.
  auto g = [&](double t) {
    double s = distance_from_film - track - t;
    return ImageObject(lens, s, lambda_nm).back_focus - t;
  };
  double lo = p.bfl, hi = p.bfl;
  double front_focus_distance = -p.ffl;  // object must stay farther than this from the first vertex
  double step = std::max(1e-3 * p.efl, 1e-6);
  bool bracketed = false;
  while (distance_from_film - track - hi > front_focus_distance) {
    if (g(hi) < 0) {
      bracketed = true;
      break;
    }
    lo = hi;
    hi += step;
    step *= 2;
    if (distance_from_film - track - hi <= front_focus_distance) hi = distance_from_film - track - front_focus_distance - 1e-9 * p.efl;
    if (hi <= lo) break;
  }
  if (!bracketed || g(lo) < 0) return std::nullopt;
  for (int it = 0; it < 200 && hi - lo > 1e-12 * (1 + hi); ++it) {
    double mid = 0.5 * (lo + hi);
    (g(mid) > 0 ? lo : hi) = mid;
  }
  double t = 0.5 * (lo + hi);
  FocusSolution f = ImageObject(lens, distance_from_film - track - t, lambda_nm);
  f.back_focus = t;
  return f;
}

}  // namespace objektiv
