#include "optics/paraxial.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace objektiv {

namespace {

struct YNu {
  double y, nu;
};

// y-nu trace through surfaces [first, last] (inclusive), forward (toward the film) or
// backward (toward the object), starting just before `first` with height y and reduced
// angle nu (n u, u the slope along the direction of travel). Returns the values just after
// `last`. `n`: SignedIndices.
YNu TraceRange(const LensPrescription& lens, const std::vector<double>& n, YNu ray, int first, int last, bool backward) {
  const auto& s = lens.surfaces;
  int step = backward ? -1 : 1;
  for (int i = first;; i += step) {
    double c = s[i].ParaxialCurvatureInY();
    const double n_object = n[i], n_film = n[i + 1];
    double n_before = backward ? n_film : n_object, n_after = backward ? n_object : n_film;
    if (backward) c = -c;  // seen from the film side the curvature changes sign
    // Refraction (a mirror: n' = -n): n' u' = n u - y c (n' - n).
    ray.nu -= ray.y * c * (n_after - n_before);
    if (i == last) break;
    // Transfer to the next surface in the direction of travel through the medium between.
    int next = i + step;
    double t = backward ? s[next].thickness : s[i].thickness;
    double index = backward ? n[next + 1] : n_after;
    ray.y += t * ray.nu / index;
  }
  return ray;
}

}  // namespace

std::vector<double> SignedIndices(const LensPrescription& lens, double lambda_nm) {
  std::vector<double> n{lens.IndexBefore(0, lambda_nm)};
  double sign = 1;
  for (const LensSurface& s : lens.surfaces) {
    if (s.mirror) sign = -sign;
    n.push_back(sign * s.IndexAfter(lambda_nm));
  }
  return n;
}

ParaxialData ComputeParaxial(const LensPrescription& lens, double lambda_nm, double stop_semi) {
  ParaxialData d;
  const int n = int(lens.surfaces.size());
  const std::vector<double> index = SignedIndices(lens, lambda_nm);
  YNu f = TraceRange(lens, index, {1, 0}, 0, n - 1, false);
  const double n_image = index[n];  // 1 for a lens in air
  d.efl = -1 / f.nu;              // EFL = -y1 / (n' u') with y1 = 1
  d.bfl = -f.y * n_image / f.nu;  // where the ray (slope u' = nu / n') crosses the axis
  YNu b = TraceRange(lens, index, {1, 0}, n - 1, 0, true);
  // Object space may be another medium (index n0): a reduced angle nu there is n0 u, and the
  // front focal length is n0 EFL.
  const double n_object = index[0];
  d.object_index = n_object;
  d.ffl = n_object * b.y / b.nu;   // the front focus, in front of the first vertex (negative)
  d.back_principal_plane = d.bfl - n_image * d.efl;  // the rear focal length in the image medium is n' EFL
  d.front_principal_plane = d.ffl + n_object * d.efl;

  int stop = lens.StopIndex();
  if (stop < 0) return d;
  double semi = stop_semi >= 0 ? stop_semi : lens.surfaces[stop].semi_diameter;
  // Entrance pupil: from the stop centre backward through the front group. Its size scales
  // the stop by the ratio of heights of a ray parallel to the axis (first surface / stop).
  if (stop == 0) {
    d.entrance_pupil_position = 0;
    d.entrance_pupil_diameter = 2 * semi;
  } else {
    // Start at the stop centre and transfer back to the surface in front of it.
    double n_front = index[stop];
    YNu e{0, n_front};  // u = 1
    e.y += lens.surfaces[stop - 1].thickness * e.nu / n_front;
    e = TraceRange(lens, index, e, stop - 1, 0, true);
    d.entrance_pupil_position = n_object * e.y / e.nu;
    YNu m = TraceRange(lens, index, {1, 0}, 0, stop - 1, false);
    double y_stop = m.y + lens.surfaces[stop - 1].thickness * m.nu / index[stop];
    d.entrance_pupil_diameter = std::abs(2 * semi / y_stop);
  }
  // Exit pupil: from the stop centre forward through the rear group; the Lagrange invariant
  // gives its magnification as the ratio of reduced angles (n u at the stop / n' u' after).
  if (stop == n - 1) {
    d.exit_pupil_position = 0;
    d.exit_pupil_diameter = 2 * semi;
  } else {
    double n_stop = index[stop + 1];
    YNu x{0, n_stop};  // u = 1 at the stop
    x.y += lens.surfaces[stop].thickness * x.nu / n_stop;
    x = TraceRange(lens, index, x, stop + 1, n - 1, false);
    d.exit_pupil_position = -x.y / x.nu;
    d.exit_pupil_diameter = std::abs(2 * semi * n_stop / x.nu);
  }
  d.fnumber = d.efl / d.entrance_pupil_diameter;
  return d;
}

LensPrescription ScaledToFocalLength(const LensPrescription& lens, double focal_length) {
  return lens.Scaled(focal_length / ComputeParaxial(lens).efl);
}

}  // namespace objektiv
