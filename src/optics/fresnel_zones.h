// A Fresnel surface: a surface's profile z_p(r) (its radius, conic, aspheric or Q-type terms)
// cut into concentric zones of one radial width, the pitch p. In zone k (r_k = k p <= r <
// r_(k+1)) the facet is the profile lowered to start on the vertex plane:
//
//   z(r) = z_p(r) - z_p(r_k),
//
// so every facet has the profile's slope where it lies (the same refraction, hence the same
// paraxial power and vertex curvature) while the whole surface stays within a thin slab about
// the vertex plane. Between zone k - 1 and zone k stands a riser: the cylinder r = r_k parallel
// to the axis, from the outer edge of facet k - 1 (height h_(k-1) = z_p(r_k) - z_p(r_(k-1))) back
// to the vertex plane. Risers (the draft faces of a moulded Fresnel lens) have no optical use:
// light that meets one is lost (they cast the thin rings a Fresnel lens draws into its bokeh).
//
// The crossing of a ray with the zoned surface: its path through the slab is cut where it
// crosses the zones' radii (a quadratic in the ray's parameter t for each radius); in each
// piece, within one zone, z(t) - facet(t) changes sign where the ray meets the facet (found by
// bisection, refined by Newton); at each zone radius in between, the ray meets the riser if its
// height there lies on the riser.
#pragma once
#include <optional>
#include <vector>

#include "base/vec.h"

namespace objektiv {

struct LensSurface;

class FresnelZones {
 public:
  // The zones of `profile`'s sag (LensSurface::Sag) with pitch `pitch` > 0 mm, over its clear
  // semi-diameter.
  FresnelZones(const LensSurface& profile, double pitch);

  double pitch() const { return pitch_; }
  // The slab [lo, hi] along z (from the vertex plane) that holds every facet and riser.
  double slab_lo() const { return lo_; }
  double slab_hi() const { return hi_; }
  // The zone holding radius r (0 at the centre), and the profile's height at a zone's inner
  // radius (tabulated over the clear aperture; `profile` is the surface's own).
  int Zone(double r) const;
  double BaseHeight(const LensSurface& profile, int zone) const;

  struct Hit {
    double t = 0;
    bool riser = false;  // the ray met a riser (and stops there when they block)
  };
  // The first crossing of the ray o + t d (o relative to the vertex, in the surface's frame)
  // with the zoned `surface` (this object's own), t >= 0; nothing if it meets neither a facet
  // nor a riser within the slab.
  std::optional<Hit> Intersect(const LensSurface& surface, const Vec3d& o, const Vec3d& d) const;

 private:
  double pitch_;
  double lo_ = 0, hi_ = 0;
  std::vector<double> base_;  // the profile's height at k pitch, k = 0 .. the last zone
};

}  // namespace objektiv
