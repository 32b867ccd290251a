// Light entering a lens through its first surface, for estimators that start on the light's
// side (camera importance, ghosts and glare by light tracing). A point of the first surface's
// clear aperture is chosen uniformly over its projection on the plane across the axis (a disc
// of the semi-diameter r: density 1 / (pi r^2) per mm^2). The flux that light of radiance L
// arriving there in direction d brings through the surface element is
//   L cos(d, n) dA = L (cos(d, n) / n_z) dx dy,
// n the surface's unit normal (facing the object) and dA = dx dy / n_z the curved surface's
// area over the projected element: the flux through the whole surface, estimated from one
// point, is L ProjectedCosine(d) pi r^2 / (the rest of the sample's density).
#pragma once
#include "base/vec.h"
#include "optics/lens_system.h"

namespace objektiv {

struct FrontPoint {
  Vec3d p;       // lens space, on the first surface
  Vec3d normal;  // unit, toward the film along the surface's axis (light enters against it)
  Vec3d axis{0, 0, 1};  // the surface's own axis (tilted with it: optics/surface_placement.h)
  // cos(d, n) / (n . axis) for light travelling in unit direction d (the disc is sampled across
  // the surface's own axis); 0 where d does not enter the surface from the object side.
  double ProjectedCosine(const Vec3d& d) const {
    const double c = Dot(d, normal);
    return c > 0 ? c / Dot(normal, axis) : 0;
  }
};

// u in [0, 1)^2.
FrontPoint SampleFrontElement(const LensSystem& lens, Vec2d u);
// pi r^2 (mm^2), r the first surface's semi-diameter.
double FrontElementArea(const LensSystem& lens);

}  // namespace objektiv
