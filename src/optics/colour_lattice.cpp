#include "optics/colour_lattice.h"

#include <algorithm>
#include <limits>

#include "base/catmull_rom.h"

namespace objektiv {

ColourLattice::ColourLattice(Vec2d lo, Vec2d hi, int nodes,
                             const std::function<std::optional<Vec3d>(Vec2d)>& colour_at) {
  const int n = std::max(nodes, 2);
  const Vec2d size = hi - lo;
  std::vector<std::optional<Vec3d>> found(size_t(n) * n);
  bool any = false;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec2d p(lo.x + size.x * i / (n - 1), lo.y + size.y * j / (n - 1));
      found[size_t(j) * n + i] = colour_at(p);
      any |= found[size_t(j) * n + i].has_value();
    }
  if (!any) return;
  lo_ = lo;
  scale_ = Vec2d(size.x > 0 ? (n - 1) / size.x : 0, size.y > 0 ? (n - 1) / size.y : 0);
  nodes_ = n;
  colours_.resize(found.size());
  // Each node without a colour takes its nearest node's (the first of equally near ones).
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (found[size_t(j) * n + i]) {
        colours_[size_t(j) * n + i] = *found[size_t(j) * n + i];
        continue;
      }
      int best = std::numeric_limits<int>::max();
      for (int l = 0; l < n; ++l)
        for (int k = 0; k < n; ++k) {
          const int d = (k - i) * (k - i) + (l - j) * (l - j);
          if (found[size_t(l) * n + k] && d < best) best = d, colours_[size_t(j) * n + i] = *found[size_t(l) * n + k];
        }
    }
}

ColourLattice ColourLattice::Uniform(const Vec3d& colour) {
  ColourLattice l;
  l.nodes_ = 2;
  l.colours_.assign(4, colour);
  return l;
}

Vec3d ColourLattice::At(Vec2d p) const {
  const int last = nodes_ - 1;
  auto coordinate = [last](double x) { return x > 0 ? std::min(x, double(last)) : 0.0; };  // (NaN: 0)
  const double u = coordinate((p.x - lo_.x) * scale_.x), v = coordinate((p.y - lo_.y) * scale_.y);
  const int i = std::min(int(u), last - 1), j = std::min(int(v), last - 1);
  const double fu = u - i, fv = v - j;
  if (nodes_ == 2) {  // bilinear
    const Vec3d* row = colours_.data();
    const Vec3d low = row[0] * (1 - fu) + row[1] * fu, high = row[2] * (1 - fu) + row[3] * fu;
    return low * (1 - fv) + high * fv;
  }
  double wu[4], wv[4];
  CatmullRomWeights(fu, wu), CatmullRomWeights(fv, wv);
  Vec3d sum(0.0);
  for (int y = 0; y < 4; ++y) {
    // Row j - 1 + y (extended past the lattice's edges), at column u.
    auto node = [&](int x) {
      return CatmullRomSample<Vec3d>(j - 1 + y, nodes_, [&](int row) { return colours_[size_t(row) * nodes_ + x]; });
    };
    Vec3d row(0.0);
    for (int x = 0; x < 4; ++x) row += CatmullRomSample<Vec3d>(i - 1 + x, nodes_, node) * wu[x];
    sum += row * wv[y];
  }
  // (Cubic interpolation can dip below zero between nodes where a colour falls to none.)
  return Vec3d(std::max(sum.x, 0.0), std::max(sum.y, 0.0), std::max(sum.z, 0.0));
}

}  // namespace objektiv
