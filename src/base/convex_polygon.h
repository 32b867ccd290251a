// Convex polygons in the plane, in double precision: the convex hull of a set of points
// (Andrew's monotone chain), the signed area (shoelace formula) and a containment test (a
// point is inside when it lies left of, or on, every counter-clockwise edge).
#pragma once
#include <vector>

#include "base/vec.h"

namespace objektiv {

// (a - o) x (b - o): positive when o, a, b turn counter-clockwise.
inline double Cross(Vec2d o, Vec2d a, Vec2d b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

struct ConvexPolygon {
  std::vector<Vec2d> vertices;  // counter-clockwise
  double area = 0;
  // The hull of the points; fewer than three distinct points not on one line give an empty
  // polygon (no vertices, area 0).
  static ConvexPolygon HullOf(std::vector<Vec2d> points);
  bool Empty() const { return vertices.empty(); }
  bool Contains(Vec2d p) const;
};

// The hull of several point sets with every point grown to a square of half-side `grow` (the
// Minkowski sum of their hull with that square).
ConvexPolygon HullOfGrown(const std::vector<const std::vector<Vec2d>*>& point_sets, double grow);
// How far q lies outside the polygon (0 inside).
double DistanceOutside(const ConvexPolygon& poly, Vec2d q);

// Andrew's monotone chain: the hull's corners, counter-clockwise, without collinear points.
std::vector<Vec2d> ConvexHull(std::vector<Vec2d> points);
// Signed area of a simple polygon (positive when counter-clockwise).
double PolygonArea(const std::vector<Vec2d>& vertices);

}  // namespace objektiv
