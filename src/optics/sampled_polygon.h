// A convex polygon (a pupil bound) with the tables that sample it uniformly: fan triangles
// from vertex 0 picked in proportion to their area (a cdf, with a guide table to find the
// triangle in a step or two), then a uniform point in the triangle.
#pragma once
#include <cstdint>
#include <vector>

#include "base/convex_polygon.h"
#include "base/vec.h"

namespace objektiv {

struct SampledPolygon {
  ConvexPolygon poly;           // empty: no light
  std::vector<double> cdf;      // over the fan triangles from vertex 0
  std::vector<uint16_t> guide;  // where to start looking in the cdf for u in [g/G, (g+1)/G)

  // A disc inside the polygon (about its vertices' mean, as wide as the nearest edge allows):
  // most points tested lie in it, which saves the polygon's own test.
  Vec2d inner_centre{0, 0};
  double inner_radius2 = 0;

  explicit SampledPolygon(ConvexPolygon hull = {});
  bool Empty() const { return !(poly.area > 0); }
  bool Contains(Vec2d p) const {
    const double dx = p.x - inner_centre.x, dy = p.y - inner_centre.y;
    return dx * dx + dy * dy < inner_radius2 || poly.Contains(p);
  }
  // A point uniform in the polygon (pdf 1 / area) for u in [0, 1)^2.
  Vec2d Sample(Vec2d u) const;
};

}  // namespace objektiv
