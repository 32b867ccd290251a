// A ray bundle's colour over its start square (optics/ghosts.h, BundleSpectrum: a preview's
// ghosts, traced along one geometry). The losses along a ghost's path at many wavelengths
// change slowly from ray to ray, with the angles at which the rays meet the surfaces (a
// coating's reflectance moves with the angle: a coated ghost's colour shifts from its middle
// to its rim), so they are found only at the nodes of a coarse lattice over the square,
// weighted into a colour there (a vector: CIE XYZ), and interpolated between the nodes by
// Catmull-Rom's cubic in each direction (base/catmull_rom.h): a bundle of 16 x 16 cells takes 25
// rays at 32 wavelengths instead of 289 (and more at its edge). Bilinear interpolation is not
// enough: a multi-coated ghost's transmittance is convex over the bundle (its coatings reflect
// least near normal incidence), and bilinear over a node every 4 cells gave 4.5% more light
// than every cell; the cubic comes within 0.2%.
//
// A node whose ray finds no colour (it misses a surface, or is reflected totally: the square
// reaches past the light) takes the colour of its nearest node that has one; where no node has
// one, the lattice is empty.
#pragma once
#include <functional>
#include <optional>
#include <vector>

#include "base/vec.h"

namespace objektiv {

class ColourLattice {
 public:
  ColourLattice() = default;
  // `nodes` x `nodes` nodes (at least 2) over the rectangle [lo, hi], the colour at each from
  // `colour_at` (a point of the square), or none.
  ColourLattice(Vec2d lo, Vec2d hi, int nodes, const std::function<std::optional<Vec3d>(Vec2d)>& colour_at);
  // The same colour everywhere.
  static ColourLattice Uniform(const Vec3d& colour);

  bool empty() const { return colours_.empty(); }
  // The colour at p, interpolated between the nodes around it (p clamped to the rectangle;
  // bilinear where there are 2 nodes a side), never below zero. Not for an empty lattice.
  Vec3d At(Vec2d p) const;

 private:
  Vec2d lo_{0, 0}, scale_{0, 0};  // a point's lattice coordinates: (p - lo) * scale
  int nodes_ = 0;
  std::vector<Vec3d> colours_;  // row by row
};

}  // namespace objektiv
