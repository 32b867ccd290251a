// Where light can get through a lens, seen from the film: for each radial distance on the film
// (the lens is rotationally symmetric), a convex polygon on the exit pupil's plane that contains
// every point through which a ray from that film annulus leaves the front of the lens.
// Sampling points uniformly inside it (with its exact pdf) wastes few rays and, because the
// polygon contains the whole passing region, leaves the estimator unbiased.
#pragma once
#include <vector>

#include "base/vec.h"
#include "optics/lens_tracer.h"

namespace objektiv {

struct ConvexPolygon {
  std::vector<Vec2d> vertices;  // counter-clockwise
  double area = 0;
  bool Contains(Vec2d p) const;
};

class PupilBounds {
 public:
  // `film_radius`: largest radial film distance needed (e.g. the half-diagonal, mm); `bins`
  // radial bins; `grid` x `grid` probe rays over the rear element per film radius probed.
  PupilBounds(const LensTracer& tracer, double film_radius, double lambda_nm = 587.5618, int bins = 128, int grid = 64);

  struct Sample {
    Vec3d point;  // on the sampling (exit pupil) plane, lens space (mm)
    double pdf;   // per unit area on that plane; 0 when no light reaches this film point
  };
  // A point to aim at from the film point (x, y), uniform in the bound of its annulus.
  Sample SampleRear(Vec2d film, Vec2d u) const;
  // The bound (unrotated: film point on +x) for the annulus containing radius r; null if none.
  const ConvexPolygon* BoundAt(double r) const;
  double rear_z() const { return rear_z_; }  // the sampling plane's z (the exit pupil)
  double film_radius() const { return film_radius_; }

 private:
  std::vector<ConvexPolygon> bounds_;  // per bin; empty polygon: no light
  std::vector<std::vector<double>> triangle_cdf_;  // per bin, for sampling the fan
  double film_radius_, rear_z_;
};

}  // namespace objektiv
