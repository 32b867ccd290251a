// A lens hood: a tube (a round mouth) or a box (a rectangular mouth, its sides along the
// film's x and y) in front of the first element, its mouth `length` mm before the first
// vertex. Light from the scene reaches the lens only through the mouth, which cuts the light
// from outside the field that would otherwise fall on the front element and flare; a hood too
// long or too narrow vignettes the image's corners as well.
//
// The walls run from the front element's rim (or wider) to the mouth, straight or widening,
// and the mouth encloses the front element: then a ray that meets the front element passes the
// hood exactly where it crosses the mouth's plane inside the mouth (its distance to a flat wall
// changes linearly along it, its distance from the axis convexly, so it is inside the walls
// wherever it is inside at both ends). The walls are black: nothing is reflected off them.
#pragma once
#include <string>

#include "base/vec.h"
#include "optics/lens_prescription.h"

namespace objektiv {

struct LensHood {
  double length = 0;                       // mm from the first vertex to the mouth's plane
  double radius = 0;                       // a round mouth (mm); 0: rectangular
  double half_width = 0, half_height = 0;  // a rectangular mouth (mm)

  // Whether the line of a ray (lens space) crosses the mouth's plane inside the mouth;
  // `first_vertex_z` is the first vertex's z.
  bool Passes(const Vec3d& o, const Vec3d& d, double first_vertex_z) const;
  // Why the hood cannot hold the front element `front` (its first vertex at z 0): its mouth
  // narrower than the element's reach from the axis (its semi-diameter, decentre and tilt), or
  // not in front of the element's foremost point (a concave or tilted face's rim lies before the
  // vertex); empty where it can.
  std::string Mismatch(const LensSurface& front) const;
  std::string Describe() const;  // "round, 40 mm long, 72 mm across"
};

}  // namespace objektiv
