#include "optics/paraxial.h"

#include <algorithm>

namespace objektiv {

namespace {
// Trace a ray parallel to the axis at height 1 through the surfaces in the given order;
// returns the final height and reduced angle (n u) after the last surface (n = 1, air).
struct YNu {
  double y, nu;
};
YNu TraceParallel(const LensPrescription& lens, double lambda_nm, bool reversed) {
  const auto& s = lens.surfaces;
  const int n = int(s.size());
  double y = 1, nu = 0;
  for (int k = 0; k < n; ++k) {
    int i = reversed ? n - 1 - k : k;
    // Media on either side of surface i in the direction of travel.
    double n_before, n_after, c = s[i].Curvature();
    if (!reversed) {
      n_before = i > 0 ? s[i - 1].IndexAfter(lambda_nm) : 1.0;
      n_after = s[i].IndexAfter(lambda_nm);
    } else {
      n_before = s[i].IndexAfter(lambda_nm);
      n_after = i > 0 ? s[i - 1].IndexAfter(lambda_nm) : 1.0;
      c = -c;  // seen from the film side the surface's curvature changes sign
    }
    // Refraction: n' u' = n u - y c (n' - n).
    nu = nu - y * c * (n_after - n_before);
    // Transfer to the next surface in the direction of travel.
    if (k + 1 < n) {
      int next = reversed ? i - 1 : i + 1;
      double t = reversed ? s[next].thickness : s[i].thickness;
      double index = reversed ? s[next].IndexAfter(lambda_nm) : n_after;
      y += t * nu / index;
    }
  }
  return {y, nu};
}
}  // namespace

ParaxialData ComputeParaxial(const LensPrescription& lens, double lambda_nm) {
  ParaxialData d;
  YNu f = TraceParallel(lens, lambda_nm, false);
  d.efl = -1 / f.nu;          // EFL = -y1 / (n' u') with y1 = 1
  d.bfl = -f.y / f.nu;        // distance at which the ray crosses the axis
  YNu b = TraceParallel(lens, lambda_nm, true);
  d.ffl = b.y / b.nu;         // the front focus lies in front of the first vertex (negative)
  return d;
}

}  // namespace objektiv
