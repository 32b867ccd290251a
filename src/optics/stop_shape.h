// The opening of the aperture stop, in units of the stop's radius (the round stop is the unit
// disc): the disc itself, or an iris of n >= 3 blades inscribed in it, straight (a regular
// polygon) or curved (each edge a circular arc through two neighbouring corners that bulges
// toward the circle: curvature 0 straight, 1 the circle), its first corner at angle
// `rotation`; optionally cut by a convex polygon as well (the region where an aperture mask
// lets light through).
//
// Its symmetry is what sampling exploits. The lens is rotationally symmetric, so the region
// of the exit pupil that passes light toward a film point at azimuth phi is the one for the
// film point on +x turned by phi, with the opening turned by -phi. The round stop looks the
// same for every phi: one region per film radius. An n-bladed iris looks the same after a
// turn by 2 pi / n, and mirrored about the line through a corner: with psi the film point's
// azimuth from a corner, the regions for psi in [0, pi / n] give every other one (psi and
// 2 pi / n - psi are mirror images). A cut opening has no symmetry.
#pragma once
#include "base/convex_polygon.h"

namespace objektiv {

class StopShape {
 public:
  StopShape() = default;  // the round stop
  // `blades` >= 3 (fewer: the round stop), curvature clamped to [0, 1], rotation in radians.
  static StopShape Iris(int blades, double curvature, double rotation);

  // Also cut by `polygon` (stop radii).
  void Cut(ConvexPolygon polygon);
  // The same opening turned by `angle` (radians) about the axis.
  StopShape Rotated(double angle) const;

  // Whether (x, y), in stop radii, lies in the opening.
  bool Contains(double x, double y) const;
  bool IsRound() const { return blades_ == 0 && !cut_; }
  bool HasCut() const { return cut_; }
  int blades() const { return blades_; }

  // The turns and mirrors that leave the opening unchanged: `order` 0 for every turn (the
  // round stop), else turns by 2 pi / order; with `mirror`, mirroring about the line at angle
  // `axis` through the centre.
  struct Symmetry {
    int order = 0;
    bool mirror = false;
    double axis = 0;
  };
  Symmetry symmetry() const;

  // The iris without the cut (the ideal-lens cameras sample it and weight by the mask
  // themselves): its area, and a point uniform over it (stop radii; density 1 / area).
  double IrisArea() const;
  Vec2d SampleIris(Vec2d u) const;

 private:
  // A curved blade in the frame of its edge's bisector (+x from the centre toward the edge's
  // middle): the arc's centre (xc, 0) and radius; the chord lies at x = apothem.
  struct Arc {
    double apothem = 0, xc = 0, radius = 0, half_chord = 0;
    double segment_area = 0;  // between the chord and the arc
  };
  bool InsideIris(double x, double y) const;
  Vec2d SampleSegment(double u, double v) const;  // in the bisector frame

  int blades_ = 0;
  double curvature_ = 0, rotation_ = 0;
  bool curved_ = false;  // 0 < curvature < 1
  Arc arc_;
  bool cut_ = false;
  ConvexPolygon cut_polygon_;
};

}  // namespace objektiv
