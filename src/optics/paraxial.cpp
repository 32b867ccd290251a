#include "optics/paraxial.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/dormand_prince.h"

namespace objektiv {

namespace {

struct YNu {
  double y, nu;
};

// The ray carried across the gap after surface `gap` (toward the film, or the object where
// `backward`): straight through a homogeneous medium (n: SignedIndices); through a gradient
// by integrating d/dzeta (N0 dy/dzeta) = 2 N2 y along the direction of travel zeta
// (optics/gradient_index.h), as dy/dzeta = nu / N0, dnu/dzeta = 2 N2 y, to 1e-13.
YNu Transfer(const LensPrescription& lens, const std::vector<double>& n, int gap, YNu ray, bool backward,
             double lambda_nm) {
  const LensSurface& s = lens.surfaces[size_t(gap)];
  if (!s.gradient) {
    ray.y += s.thickness * ray.nu / n[size_t(gap) + 1];
    return ray;
  }
  const double n_v = s.IndexAfter(lambda_nm), length = s.thickness;
  const auto f = [&](const OdeState<3>& v) {  // v: y, nu, zeta
    double n0, n2;
    s.gradient->Paraxial(n_v, backward ? length - v[2] : v[2], n0, n2);
    return OdeState<3>{v[1] / n0, 2 * n2 * v[0], 1};
  };
  if (!(length > 0)) return ray;
  OdeState<3> v{ray.y, ray.nu, 0}, next, err, k7, k1 = f(v);
  double h = length / 16;
  for (int steps = 0; length - v[2] > 1e-12 * length; ++steps) {
    if (steps == 200000) return {NAN, NAN};  // a profile no smooth integration follows
    h = std::min(h, length - v[2]);
    DormandPrinceStep<3>(f, v, k1, h, next, err, k7);
    const double e = std::max(std::abs(err[0]), std::abs(err[1]));
    const double tol = 1e-13 * (1 + std::abs(v[0]) + std::abs(v[1]));
    if (e <= tol || h < 1e-9 * length) v = next, k1 = k7;
    h = NextDormandPrinceStep(h, e, tol);
  }
  return {v[0], v[1]};
}

// The index just before surface i on the object side, on the axis at its vertex: a gradient's
// at the far end of its gap.
double IndexArriving(const LensPrescription& lens, const std::vector<double>& n, int i, double lambda_nm) {
  if (i == 0 || !lens.surfaces[size_t(i) - 1].gradient) return n[size_t(i)];
  const LensSurface& g = lens.surfaces[size_t(i) - 1];
  double n0, n2;
  g.gradient->Paraxial(g.IndexAfter(lambda_nm), g.thickness, n0, n2);
  return n0;
}

// y-nu trace through surfaces [first, last] (inclusive), forward (toward the film) or
// backward (toward the object), starting just before `first` with height y and reduced
// angle nu (n u, u the slope along the direction of travel). Returns the values just after
// `last`. `n`: SignedIndices.
YNu TraceRange(const LensPrescription& lens, const std::vector<double>& n, YNu ray, int first, int last, bool backward,
               double lambda_nm, std::vector<double>* heights = nullptr) {
  const auto& s = lens.surfaces;
  int step = backward ? -1 : 1;
  for (int i = first;; i += step) {
    if (heights) (*heights)[size_t(i)] = ray.y;
    double c = s[i].ParaxialCurvatureInY();
    const double n_object = IndexArriving(lens, n, i, lambda_nm), n_film = n[i + 1];
    double n_before = backward ? n_film : n_object, n_after = backward ? n_object : n_film;
    if (backward) c = -c;  // seen from the film side the curvature changes sign
    // Refraction (a mirror: n' = -n): n' u' = n u - y c (n' - n).
    ray.nu -= ray.y * c * (n_after - n_before);
    if (i == last) break;
    // Transfer to the next surface in the direction of travel through the medium between.
    ray = Transfer(lens, n, backward ? i - 1 : i, ray, backward, lambda_nm);
  }
  return ray;
}

}  // namespace

std::pair<double, double> TraceParaxialForward(const LensPrescription& lens, double lambda_nm, double y, double nu,
                                               std::vector<double>* heights) {
  if (heights) heights->assign(lens.surfaces.size(), 0.0);
  const YNu out = TraceRange(lens, SignedIndices(lens, lambda_nm), {y, nu}, 0, int(lens.surfaces.size()) - 1, false,
                             lambda_nm, heights);
  return {out.y, out.nu};
}

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
  YNu f = TraceRange(lens, index, {1, 0}, 0, n - 1, false, lambda_nm);
  const double n_image = index[n];  // 1 for a lens in air
  d.efl = -1 / f.nu;              // EFL = -y1 / (n' u') with y1 = 1
  d.bfl = -f.y * n_image / f.nu;  // where the ray (slope u' = nu / n') crosses the axis
  YNu b = TraceRange(lens, index, {1, 0}, n - 1, 0, true, lambda_nm);
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
    YNu e{0, IndexArriving(lens, index, stop, lambda_nm)};  // u = 1
    e = Transfer(lens, index, stop - 1, e, true, lambda_nm);
    e = TraceRange(lens, index, e, stop - 1, 0, true, lambda_nm);
    d.entrance_pupil_position = n_object * e.y / e.nu;
    YNu m = TraceRange(lens, index, {1, 0}, 0, stop - 1, false, lambda_nm);
    const double y_stop = Transfer(lens, index, stop - 1, m, false, lambda_nm).y;
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
    x = Transfer(lens, index, stop, x, false, lambda_nm);
    x = TraceRange(lens, index, x, stop + 1, n - 1, false, lambda_nm);
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
