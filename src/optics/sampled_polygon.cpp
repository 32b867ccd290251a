#include "optics/sampled_polygon.h"

#include <algorithm>
#include <cmath>

#include "base/sampling.h"

namespace objektiv {

SampledPolygon::SampledPolygon(ConvexPolygon hull) {
  if (!(hull.area > 0)) return;
  poly = std::move(hull);
  double acc = 0;
  cdf.push_back(0);
  for (size_t t = 1; t + 1 < poly.vertices.size(); ++t) {
    acc += 0.5 * Cross(poly.vertices[0], poly.vertices[t], poly.vertices[t + 1]);
    cdf.push_back(acc);
  }
  for (double& c : cdf) c /= acc;
  // The inner disc: the vertices' mean lies inside a convex polygon; its distance to the
  // nearest edge's line (shrunk a little against rounding) bounds a disc inside.
  const size_t n = poly.vertices.size();
  for (const Vec2d& v : poly.vertices) inner_centre = inner_centre + v * (1.0 / n);
  double nearest = INFINITY;
  for (size_t i = 0; i < n; ++i) {
    const Vec2d a = poly.vertices[i], b = poly.vertices[(i + 1) % n];
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    if (length > 0) nearest = std::min(nearest, Cross(a, b, inner_centre) / length);
  }
  inner_radius2 = nearest > 0 && std::isfinite(nearest) ? 0.999 * nearest * nearest : 0;
  // Guide table: for u in [g / G, (g + 1) / G), the triangles before guide[g] are too low.
  guide.resize(64);
  for (size_t g = 0; g < guide.size(); ++g)
    guide[g] = uint16_t(std::max<ptrdiff_t>(1, std::upper_bound(cdf.begin(), cdf.end(), double(g) / guide.size()) - cdf.begin()));
}

Vec2d SampledPolygon::Sample(Vec2d u) const {
  // Pick a fan triangle by area (reusing u.x): the guide table gives the first candidate, a
  // short scan the triangle with cdf[t - 1] <= u.x < cdf[t].
  size_t t = guide[std::min(size_t(u.x * guide.size()), guide.size() - 1)];
  while (t + 1 < cdf.size() && cdf[t] <= u.x) ++t;
  t = std::clamp<size_t>(t, 1, cdf.size() - 1);
  double ux = (u.x - cdf[t - 1]) / std::max(cdf[t] - cdf[t - 1], 1e-300);
  Vec2f bary = SampleUniformTriangle({float(std::min(ux, 0.99999994)), float(u.y)});
  const Vec2d &a = poly.vertices[0], &b = poly.vertices[t], &c = poly.vertices[t + 1];
  double b2 = 1 - bary.x - bary.y;
  return {a.x * bary.x + b.x * bary.y + c.x * b2, a.y * bary.x + b.y * bary.y + c.y * b2};
}

}  // namespace objektiv
