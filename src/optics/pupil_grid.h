// The pupil bounds of a lens without rotational symmetry (toroids: an anamorphic lens),
// tabulated over the film's x and y. For each film point the bound is a convex polygon on the
// sampling plane that holds every point through which a ray from it leaves the lens (as in
// optics/pupil_bounds.h, which turns one radial table about the axis where the lens allows).
//
// The film square [-R, R]^2 (R the film radius asked for: every film point lies within R of
// the axis) is cut into cells, those wholly outside that circle left empty; a cell's bound is
// the hull of the regions traced at its four corners and its centre, grown by the region's
// tolerance plus twice the most the centre's region sticks out of the corners' hull (a region
// that moves smoothly across the cell departs from the corners' hull most near the middle).
// A cell whose bound wastes more than 4% of the rays of its smallest corner region is split
// in four, twice at most. Where the lens and the stop are symmetric under x -> -x or y -> -y
// (LensPrescription::MirrorSymmetric and a round stop: centred toroids both, a lens tilted about
// x or a crystal whose axis leans in the x-z plane one), only the half x >= 0 or y >= 0 (or the
// quadrant) is tabulated and the rest are its mirror images.
#pragma once
#include <cstdint>
#include <vector>

#include "base/vec.h"
#include "optics/lens_system.h"
#include "optics/pupil_bounds_options.h"
#include "optics/sampled_polygon.h"

namespace objektiv {

class PupilGrid {
 public:
  // `plane_z`: the sampling plane (lens space z).
  PupilGrid(const LensSystem& lens, double film_radius, double plane_z, const PupilBoundsOptions& options);

  struct Found {
    const SampledPolygon* region;  // null: no light reaches the film point
    Vec2d mirror;                  // (+-1, +-1): the region's points times these are the film point's
  };
  Found RegionAt(Vec2d film) const;
  size_t RegionCount() const { return regions_.size(); }

 private:
  class Builder;
  static constexpr int kCellsPerRadius = 8;  // a cell's side: the film radius / 8
  bool mirror_x_ = false, mirror_y_ = false;  // only x >= 0 (y >= 0) tabulated, mirrored
  int cells_x_ = 0, cells_y_ = 0;             // cells along x and y
  double x0_ = 0, y0_ = 0, step_ = 0;         // the table's lower corner and a cell's side
  // Cell c has 2^levels_[c] x 2^levels_[c] equal sub-cells, sub-cell (i, j)'s region at
  // regions_[leaves_[first_[c] + j 2^levels + i]].
  std::vector<SampledPolygon> regions_;
  std::vector<uint32_t> leaves_, first_;
  std::vector<uint8_t> levels_;
};

}  // namespace objektiv
