// Where light can get through a lens, seen from the film: for each radial distance on the film
// (the lens is rotationally symmetric), a convex polygon on the exit pupil's plane that contains
// every point through which a ray from that film annulus leaves the front of the lens.
// Sampling points uniformly inside it (with its exact pdf) wastes few rays and, because the
// polygon contains the whole passing region, leaves the estimator unbiased.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <vector>

#include "base/vec.h"
#include "optics/lens_tracer.h"

namespace objektiv {

struct ConvexPolygon {
  std::vector<Vec2d> vertices;  // counter-clockwise
  double area = 0;
  bool Contains(Vec2d p) const;
};

struct PupilBoundsOptions {
  int bins = 128;  // radial film bins
  // A probe passes if it passes at any of these wavelengths: a dispersive lens's pupil
  // changes a little with wavelength, and the bound must hold the light of every one.
  std::vector<double> wavelengths = {587.5618};
  bool rims = true;  // false: only the stop clips (a lens without optical vignetting)
};

class PupilBounds {
 public:
  // `film_radius`: largest radial film distance needed (e.g. the half-diagonal, mm).
  PupilBounds(const LensTracer& tracer, double film_radius, const PupilBoundsOptions& options = {});

  struct Sample {
    Vec3d point;  // on the sampling (exit pupil) plane, lens space (mm)
    double pdf;   // per unit area on that plane; 0 when no light reaches this film point
  };
  // A point to aim at from the film point (x, y), uniform in the bound of its annulus.
  Sample SampleRear(Vec2d film, Vec2d u) const;
  // The bound (unrotated: film point on +x) for the annulus containing radius r; null if none.
  const ConvexPolygon* BoundAt(double r) const;
  size_t RegionCount() const { return regions_.size(); }
  double rear_z() const { return rear_z_; }  // the sampling plane's z (the exit pupil)
  double film_radius() const { return film_radius_; }

 private:
  struct Region {
    ConvexPolygon poly;          // empty: no light
    std::vector<double> cdf;     // over the fan triangles from vertex 0
    std::vector<uint16_t> guide;  // where to start looking in the cdf for u in [g/G, (g+1)/G)
  };
  static Region MakeRegion(std::vector<Vec2d> hull);  // the polygon and its sampling tables
  const Region* RegionAt(double r) const;

  // Bin b (an annulus of film radii) has 2^bin_levels_[b] equal sub-annuli; sub-annulus k's
  // region is regions_[leaves_[bin_first_[b] + k]].
  std::vector<Region> regions_;
  std::vector<uint32_t> leaves_, bin_first_;
  std::vector<uint8_t> bin_levels_;
  double film_radius_, rear_z_;
};

}  // namespace objektiv
