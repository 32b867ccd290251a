#include "optics/gradient_propagation.h"

#include <algorithm>
#include <cmath>

#include "base/dormand_prince.h"

namespace objektiv {

namespace {

// State: x, y, z, Tx, Ty, Tz (the medium's frame), s.
using State = OdeState<7>;


}  // namespace

double IndexInGap(const LensSystem& lens, int gap, const Vec3d& p, double lambda_nm) {
  const LensSurface& s = lens.surface(gap);
  const double n_v = s.IndexAfter(lambda_nm);
  return s.gradient ? s.gradient->Index(n_v, lens.InSurfaceFrame(gap, p)) : n_v;
}

GradientArrival PropagateThroughGradient(const LensSystem& lens, int gap, bool toward_film, const LensRay& ray,
                                         double lambda_nm, double tolerance, std::vector<Vec3d>* points) {
  GradientArrival out;
  const LensSurface& medium_surface = lens.surface(gap);
  const GradientIndex& grin = *medium_surface.gradient;
  const double n_v = medium_surface.IndexAfter(lambda_nm);
  const int target = toward_film ? gap + 1 : gap;
  const LensSurface& ts = lens.surface(target);
  const SurfacePlacement* placed = medium_surface.placement ? &*medium_surface.placement : nullptr;
  const double direction = toward_film ? 1 : -1;
  // The element's edge, a cylinder as wide as the wider of its faces: a ray that reaches it
  // between them leaves the glass there (into the mount).
  const double r_max = std::max(medium_surface.semi_diameter, lens.surface(gap + 1).semi_diameter);

  bool real_index = true;
  const auto f = [&](const State& y) {
    Vec3d half_grad;
    const double n2 = grin.IndexSquared(n_v, Vec3d(y[0], y[1], y[2]), &half_grad);
    real_index &= n2 > 0;
    return State{y[3], y[4], y[5], half_grad.x, half_grad.y, half_grad.z, std::sqrt(std::max(n2, 0.0))};
  };
  // The target's side function at a point of the medium's frame: negative before the crossing;
  // false outside the surface's domain (where it cannot be met).
  const auto side = [&](const State& y, double& value) {
    const Vec3d local = lens.InSurfaceFrame(target, lens.FromSurfaceFrame(gap, Vec3d(y[0], y[1], y[2])));
    double z;
    if (!ts.SagAt(local.x, local.y, z)) return false;
    value = direction * (local.z - z);
    return true;
  };

  const Vec3d p0 = lens.InSurfaceFrame(gap, ray.o), d0 = placed ? placed->ToLocal(ray.d) : ray.d;
  const double n0 = grin.Index(n_v, p0);
  State y{p0.x, p0.y, p0.z, n0 * d0.x, n0 * d0.y, n0 * d0.z, 0};
  State k1 = f(y), y1, err, k7;
  double f_start = -1;  // the side function at y (the last accepted step's end)
  side(y, f_start);
  if (!real_index || !(n0 > 0)) {
    out.failure = TraceFailure::kClipped;
    out.p = ray.o;
    return out;
  }
  // Steps in tau (an arc length of about n h): at most half the gap's length at once.
  const double gap_length = std::max(std::abs(medium_surface.thickness), 0.05);
  const double h_max = 0.5 * gap_length / n0;
  double h = 0.25 * h_max;
  for (int attempts = 0; attempts < 60000 && out.steps < 20000; ++attempts) {
    DormandPrinceStep<7>(f, y, k1, h, y1, err, k7);
    double err_max = 0;
    for (int i = 0; i < 6; ++i) err_max = std::max(err_max, std::abs(err[i]));
    if (!(err_max <= tolerance) && h > 1e-12) {
      h = NextDormandPrinceStep(h, std::isfinite(err_max) ? err_max : 1e300, tolerance);
      real_index = true;
      continue;
    }
    ++out.steps;
    double f1 = -1;
    const bool on_surface = side(y1, f1);
    if (on_surface && f1 >= 0) {
      // The crossing lies within this step: regula falsi (Illinois) on the step's length.
      double lo = 0, hi = h, flo = std::min(f_start, 0.0), fhi = f1;
      State y_hit = y1;
      int last = 0;
      for (int it = 0; it < 100; ++it) {
        double m = (flo * hi - fhi * lo) / (flo - fhi);
        if (!(m > lo && m < hi)) m = 0.5 * (lo + hi);
        DormandPrinceStep<7>(f, y, k1, m, y_hit, err, k7);
        double fm;
        if (!side(y_hit, fm)) fm = -1;  // off the surface's domain: not yet across
        if (std::abs(fm) < 0.01 * tolerance || hi - lo < 1e-15 * h) break;
        if (fm < 0) {
          lo = m, flo = fm;
          if (last == -1) fhi *= 0.5;
          last = -1;
        } else {
          hi = m, fhi = fm;
          if (last == 1) flo *= 0.5;
          last = 1;
        }
      }
      const Vec3d t(y_hit[3], y_hit[4], y_hit[5]);
      out.p = lens.FromSurfaceFrame(gap, Vec3d(y_hit[0], y_hit[1], y_hit[2]));
      out.d = placed ? placed->FromLocal(t / Length(t)) : t / Length(t);
      out.length = y_hit[6];
      if (points) points->push_back(out.p);
      if (!real_index) out.failure = TraceFailure::kClipped;
      return out;
    }
    y = y1;
    k1 = k7;
    f_start = on_surface ? f1 : -1;
    if (points) points->push_back(lens.FromSurfaceFrame(gap, Vec3d(y[0], y[1], y[2])));
    if (!real_index || std::hypot(y[0], y[1]) > r_max) {
      out.failure = TraceFailure::kClipped;
      out.p = lens.FromSurfaceFrame(gap, Vec3d(y[0], y[1], y[2]));
      return out;
    }
    if (!(direction * y[5] > 0)) break;  // turned back toward where it came from
    h = std::min(NextDormandPrinceStep(h, err_max, tolerance), h_max);
  }
  out.failure = TraceFailure::kMissedSurface;
  return out;
}

}  // namespace objektiv
