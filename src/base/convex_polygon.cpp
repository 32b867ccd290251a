#include "base/convex_polygon.h"

#include <algorithm>
#include <cmath>

namespace objektiv {

std::vector<Vec2d> ConvexHull(std::vector<Vec2d> p) {
  std::sort(p.begin(), p.end(), [](Vec2d a, Vec2d b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Vec2d> h(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && Cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && Cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

double PolygonArea(const std::vector<Vec2d>& v) {
  double a = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    const Vec2d &p = v[i], &q = v[(i + 1) % v.size()];
    a += p.x * q.y - q.x * p.y;
  }
  return 0.5 * a;
}

ConvexPolygon ConvexPolygon::HullOf(std::vector<Vec2d> points) {
  ConvexPolygon poly;
  std::vector<Vec2d> hull = ConvexHull(std::move(points));
  double area = hull.size() >= 3 ? PolygonArea(hull) : 0;
  if (area > 0) poly.vertices = std::move(hull), poly.area = area;
  return poly;
}

bool ConvexPolygon::Contains(Vec2d p) const {
  const size_t n = vertices.size();
  if (n < 3) return false;
  // The fan of triangles from the first corner: p must lie between its first and last edges
  // (the polygon's two edges there), then, in the triangle whose wedge holds it (found by
  // bisection: a pupil bound's hull has hundreds of corners), on the inner side of the
  // polygon's edge that closes it.
  const Vec2d o = vertices[0];
  if (Cross(o, vertices[1], p) < 0 || Cross(o, vertices[n - 1], p) > 0) return false;
  size_t lo = 1, hi = n - 1;  // p lies left of o -> v[lo] and right of o -> v[hi]
  while (hi - lo > 1) {
    const size_t mid = (lo + hi) / 2;
    (Cross(o, vertices[mid], p) >= 0 ? lo : hi) = mid;
  }
  return Cross(vertices[lo], vertices[hi], p) >= 0;
}

ConvexPolygon HullOfGrown(const std::vector<const std::vector<Vec2d>*>& point_sets, double grow) {
  // The hull of the points first: only its corners, grown, can be corners of the sum.
  std::vector<Vec2d> all;
  for (const std::vector<Vec2d>* points : point_sets) all.insert(all.end(), points->begin(), points->end());
  std::vector<Vec2d> corners;
  for (const Vec2d& q : ConvexHull(std::move(all)))
    for (double dx : {-grow, grow})
      for (double dy : {-grow, grow}) corners.push_back({q.x + dx, q.y + dy});
  return ConvexPolygon::HullOf(std::move(corners));
}

double DistanceOutside(const ConvexPolygon& poly, Vec2d q) {
  if (poly.Contains(q)) return 0;
  double best = INFINITY;
  const std::vector<Vec2d>& v = poly.vertices;
  for (size_t i = 0; i < v.size(); ++i) {
    const Vec2d a = v[i], ab = v[(i + 1) % v.size()] - a, aq = q - a;
    const double t = std::clamp((aq.x * ab.x + aq.y * ab.y) / std::max(ab.x * ab.x + ab.y * ab.y, 1e-300), 0.0, 1.0);
    best = std::min(best, std::hypot(aq.x - t * ab.x, aq.y - t * ab.y));
  }
  return best;
}

}  // namespace objektiv
