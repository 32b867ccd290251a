// Where light can get through a lens, seen from the film: for each film point, a convex
// polygon on the exit pupil's plane that contains every point through which a ray from that
// film point leaves the front of the lens. Sampling points uniformly inside it (with its
// exact pdf) wastes few rays and, because the polygon contains the whole passing region,
// leaves the estimator unbiased.
//
// Where the lens is rotationally symmetric, the region for a film point at radius r and azimuth
// phi is the region for the film point (r, 0) with the stop's opening turned by -phi, turned
// by phi. A round stop makes it independent of phi: one region per film annulus. For an iris
// of n blades it repeats every 2 pi / n and mirrors about each corner (see StopShape), so the
// regions are tabulated over film radius and the azimuth psi from a corner, psi in
// [0, pi / n]; for a stop with no symmetry (cut by a mask), over psi in [0, 2 pi).
//
// Each table cell (a range of radii and of psi) holds the convex hull of the regions traced
// at its corners, grown a little; cells are split in radius where the region changes fast
// (e.g. at a fisheye's image circle), and the psi columns are made narrow enough that
// neighbouring columns' regions differ by a few per cent. A lens without that symmetry (with
// toroids) has its regions tabulated over the film's x and y instead (optics/pupil_grid.h).
#pragma once
#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "optics/dispersion.h"
#include "base/convex_polygon.h"
#include "base/vec.h"
#include "optics/lens_system.h"
#include "optics/pupil_bounds_options.h"
#include "optics/pupil_grid.h"
#include "optics/sampled_polygon.h"

namespace objektiv {

class PupilBounds {
 public:
  // `film_radius`: largest radial film distance needed (e.g. the half-diagonal, mm).
  PupilBounds(const LensSystem& lens, double film_radius, const PupilBoundsOptions& options = {});
  ~PupilBounds();
  PupilBounds(PupilBounds&&) noexcept;

  struct Sample {
    Vec3d point;  // on the sampling (exit pupil) plane, lens space (mm)
    double pdf;   // per unit area on that plane; 0 when no light reaches this film point
  };
  // A point to aim at from the film point (x, y), uniform in its bound.
  Sample SampleRear(Vec2d film, Vec2d u) const;
  // The density SampleRear samples `point` (on the sampling plane, lens x, y) with from the film
  // point: 1 / area inside its bound, else 0.
  double PdfRear(Vec2d film, Vec2d point) const;
  // The bound for the film point (x, y) in the table's frame (see FrameOf); null if no light.
  const ConvexPolygon* BoundAt(Vec2d film) const;
  size_t RegionCount() const;
  // The most azimuth columns of any radial bin (1 for a round stop; 0 for the x-y grid).
  int MaxAzimuthColumns() const;
  double rear_z() const { return rear_z_; }  // the sampling plane's z (the exit pupil)
  double film_radius() const { return film_radius_; }

 private:
  class Builder;
  using Region = SampledPolygon;
  // Where a film point's bound lives: its radius and azimuth psi in the table, whether the
  // table holds its mirror image (y -> -y), and the turn (cos, sin) from the table's frame to
  // lens space (the film point's azimuth for a round stop, else the axis plus whole periods).
  struct Frame {
    double r, psi;
    bool mirrored;
    Vec2d cos_sin;
  };
  Frame FrameOf(Vec2d film) const;
  const Region* RegionAt(const Frame& frame) const;

  // Radial bin b has columns_[b] cells, from bin_first_cell_[b]; cell c has 2^cell_levels_[c]
  // equal sub-annuli; sub-annulus k's region is regions_[leaves_[cell_first_[c] + k]].
  std::vector<Region> regions_;
  std::vector<uint32_t> leaves_, cell_first_, bin_first_cell_;
  std::vector<uint8_t> cell_levels_;
  std::vector<int> columns_;
  int bins_ = 0;
  StopShape::Symmetry symmetry_;
  bool round_ = true;
  double period_ = 0, span_ = 0;  // azimuths repeat every period_; the table covers [0, span_]
  std::vector<Vec2d> turns_;      // (cos, sin) of axis + k period_
  double film_radius_, rear_z_;
  std::unique_ptr<PupilGrid> grid_;  // the x-y table of a lens without rotational symmetry
};

// The plane the bounds sample on: the paraxial exit pupil's (light from every film point
// passes the same image of the stop there, trimmed slowly by vignetting).
double PupilPlaneZ(const LensSystem& lens, double lambda_nm);

}  // namespace objektiv
