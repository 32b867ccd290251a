// The region of the exit pupil's plane through which light from one film point leaves the
// lens: found by probing with rays from the film point aimed at points of the plane (the
// batch tracer says which get through). From a point inside it (the real chief ray's aim,
// else the mean of a grid's passing points), the distance to its edge along a fan of
// directions is bisected; where the edge between two neighbouring directions bulges out of
// their chord (corners of a bladed iris, tips of a cat's eye), the angle between them is
// halved, a few levels deep. The region is convex (an intersection of images of discs and
// of the iris) up to the pupil's aberrations, so the hull of the edge points, grown a little
// to cover the bisection's step and the chords between them, holds all of its light.
#pragma once
#include <vector>

#include "base/convex_polygon.h"
#include "optics/batch_tracer.h"

namespace objektiv {

struct PupilRegion {
  std::vector<Vec2d> hull;  // the hull of the edge points (empty: no light)
  double grow = 0;          // by how much to grow it: 0.2% of the region's size
  double area = 0;          // the grown hull's area
};

struct PupilRegionProbe {
  const BatchLensTracer& fast;  // which rays get through
  const LensSystem& exact;      // the chief ray's aim
  double film_z, plane_z;       // lens space z of the film and of the sampling plane
  double window;                // half-width of the square searched for light (mm)
  double tolerance;             // how far the edge may bulge out of a chord between edge points
  bool recentre;                // move the probe's centre off the edge (openings cut by masks)
};

// Where a table looks for regions on the sampling plane at plane_z: a window wide enough for
// the rear element and the exit pupil (its half-width, mm), and the edge's tolerance, a
// thousandth of the region's size (its first estimate: the exit pupil).
struct PupilSearch {
  double window, tolerance;
};
PupilSearch PupilSearchFor(const LensSystem& lens, double plane_z, double lambda_nm);

// The region for the film point (r, 0), light of every wavelength given, its points turned
// by `turn` (radians) about the axis afterwards.
PupilRegion TracePupilRegion(const PupilRegionProbe& probe, double r, const std::vector<double>& lambdas,
                             double turn = 0);
// The same for any film point (x, y) (a lens without rotational symmetry).
PupilRegion TracePupilRegionAt(const PupilRegionProbe& probe, Vec2d film, const std::vector<double>& lambdas,
                               double turn = 0);

}  // namespace objektiv
