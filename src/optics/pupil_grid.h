// The pupil bounds of a lens without rotational symmetry (toroids: an anamorphic lens),
// tabulated over the film's x and y. For each film point the bound is a convex polygon on the
// sampling plane that holds every point through which a ray from it leaves the lens (as in
// optics/pupil_bounds.h, which turns one radial table about the axis where the lens allows).
//
// The film square [-R, R]^2 (R the film radius asked for) is cut into cells; a cell's bound is
// the hull of the regions traced at its four corners and its centre, grown by the region's
// tolerance plus twice the most the centre's region sticks out of the corners' hull (a region
// that moves smoothly across the cell departs from the corners' hull most near the middle).
// A cell whose bound wastes more than 4% of the rays of its smallest corner region is split
// in four, twice at most. Where the lens and the stop are symmetric under x -> -x and
// y -> -y (centred toroids and a round stop), only the quadrant x, y >= 0 is tabulated and the
// others are its mirror images.
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
  int CellsPerSide() const { return cells_; }

 private:
  class Builder;
  bool quadrant_ = false;  // only x, y >= 0, mirrored
  int cells_ = 0;          // per side of the table
  double x0_ = 0, size_ = 0;  // the table covers [x0_, x0_ + size_]^2
  // Cell c has 2^levels_[c] x 2^levels_[c] equal sub-cells, sub-cell (i, j)'s region at
  // regions_[leaves_[first_[c] + j 2^levels + i]].
  std::vector<SampledPolygon> regions_;
  std::vector<uint32_t> leaves_, first_;
  std::vector<uint8_t> levels_;
};

}  // namespace objektiv
