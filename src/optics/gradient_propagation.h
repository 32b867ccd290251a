// A ray through a gradient-index gap (optics/gradient_index.h) from where it entered to the
// surface that ends the gap: the ray equation integrated by an adaptive Runge-Kutta pair
// (Dormand-Prince 5(4), base/dormand_prince.h) whose every step holds its local error under a
// fixed tolerance (not by slicing the medium into layers). The state is the point r, the
// optical direction T = n dr/ds and the path length s, against tau (ds = n dtau):
//   dr/dtau = T,  dT/dtau = grad(n^2) / 2,  ds/dtau = n.
// The crossing is where the surface's side function (its frame's z less its sag, signed with
// the direction of travel) changes sign within a step: found by regula falsi on the step's
// length (each trial a step of that length from the step's start) to a hundredth of the
// tolerance (1e-12 mm in the exact tracer).
#pragma once
#include <vector>

#include "optics/lens_tracer.h"

namespace objektiv {

struct GradientArrival {
  // kMissedSurface: the ray turned back, or ran past 20000 steps (60000 tries); kClipped: it left the
  // element through its edge (a cylinder about the medium's axis as wide as the wider of the
  // gap's clear apertures) or where the index is no longer real (p is where).
  TraceFailure failure = TraceFailure::kNone;
  Vec3d p, d;         // lens space: the point on the surface, and the unit direction of arrival
  double length = 0;  // the geometric path length, mm
  int steps = 0;      // accepted steps (for the benchmarks)
};

// The ray, in the gradient medium after surface `gap` (lens space; its direction unit), to
// surface gap + 1 (toward the film) or gap (toward the object). `points`, if given, receives
// the point after every accepted step (for plots).
GradientArrival PropagateThroughGradient(const LensSystem& lens, int gap, bool toward_film, const LensRay& ray,
                                         double lambda_nm, double tolerance = kGradientTolerance,  // optics/lens_tracer.h
                                         std::vector<Vec3d>* points = nullptr);

// The index at lens-space point p in the medium after surface `gap` (a gradient's or the
// glass's own).
double IndexInGap(const LensSystem& lens, int gap, const Vec3d& p, double lambda_nm);

}  // namespace objektiv
