#include "optics/pupil_grid.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <tbb/parallel_for.h>

#include "optics/batch_tracer.h"
#include "optics/pupil_region.h"

namespace objektiv {

class PupilGrid::Builder {
 public:
  static constexpr int kMaxDepth = 2;  // a cell is split into 4^kMaxDepth at most
  Builder(PupilGrid& grid, const LensSystem& lens, double film_radius, double plane_z, const PupilBoundsOptions& options)
      : g_(grid), lens_(lens), fast_(lens), lambdas_(options.wavelengths), plane_z_(plane_z), radius_(film_radius) {
    if (!options.rims) fast_.IgnoreRims();
    const PupilSearch search = PupilSearchFor(lens, plane_z, lambdas_.front());  // as the radial table's
    window_ = search.window, tolerance_ = search.tolerance;
    round_ = lens.stop_shape().symmetry().order == 0;
    // Centred toroids are symmetric under x -> -x and y -> -y; so is a round stop. A decentred or
    // tilted surface need not be, nor a form error, nor a crystal whose optic axis leans.
    g_.mirror_x_ = round_ && lens.prescription().MirrorSymmetric(0);
    g_.mirror_y_ = round_ && lens.prescription().MirrorSymmetric(1);
    g_.step_ = film_radius / kCellsPerRadius;
    g_.cells_x_ = (g_.mirror_x_ ? 1 : 2) * kCellsPerRadius, g_.cells_y_ = (g_.mirror_y_ ? 1 : 2) * kCellsPerRadius;
    g_.x0_ = g_.mirror_x_ ? 0 : -film_radius, g_.y0_ = g_.mirror_y_ ? 0 : -film_radius;
  }

  void Build() {
    const int nx = g_.cells_x_, ny = g_.cells_y_, corner_count = (nx + 1) * (ny + 1);
    // Only cells that reach into the film's circle are ever asked for (the square's corners lie
    // outside it, and there the search for light is slowest: none gets through).
    auto used = [&](int i, int j) {
      if (i < 0 || j < 0 || i >= nx || j >= ny) return false;
      const Vec2d lo = Film(i, j), hi = Film(i + 1, j + 1);
      const double x = std::max({lo.x, -hi.x, 0.0}), y = std::max({lo.y, -hi.y, 0.0});
      return std::hypot(x, y) <= radius_ * (1 + 1e-9);
    };
    // The corners and the centres of the top cells, in parallel.
    std::vector<PupilRegion> corners(corner_count), centres(nx * ny);
    tbb::parallel_for(0, corner_count + nx * ny, [&](int k) {
      if (k < corner_count) {
        const int i = k % (nx + 1), j = k / (nx + 1);
        if (used(i - 1, j - 1) || used(i, j - 1) || used(i - 1, j) || used(i, j)) corners[k] = Trace(Film(i, j));
      } else {
        const int i = (k - corner_count) % nx, j = (k - corner_count) / nx;
        if (used(i, j)) centres[k - corner_count] = Trace(Film(i + 0.5, j + 0.5));
      }
    });
    struct CellOut {
      std::vector<SampledPolygon> regions;
      std::vector<uint32_t> leaves;
      int levels = 0;
    };
    std::vector<CellOut> out(nx * ny);
    tbb::parallel_for(0, nx * ny, [&](int c) {
      const int i = c % nx, j = c / nx;
      const PupilRegion* corner[4] = {&corners[j * (nx + 1) + i], &corners[j * (nx + 1) + i + 1],
                                      &corners[(j + 1) * (nx + 1) + i], &corners[(j + 1) * (nx + 1) + i + 1]};
      CellOut& o = out[c];
      if (!used(i, j)) {
        o.regions.emplace_back();
        o.leaves = {0};
        return;
      }
      // Sub-cells fill a block of side x side leaves (kMaxDepth levels); flattened below.
      constexpr int side = 1 << kMaxDepth;
      std::vector<int32_t> block(side * side, -1);
      std::function<void(double, double, double, const PupilRegion* const*, const PupilRegion&, int)> build =
          [&](double u, double v, double w, const PupilRegion* const* k, const PupilRegion& mid, int depth) {
            // (u, v): the sub-cell's lower corner in cell units, w its width.
            ConvexPolygon bound = Bound(k, mid);
            double smallest = INFINITY;
            for (int q = 0; q < 4; ++q) smallest = std::min(smallest, k[q]->area);
            if (depth < kMaxDepth && bound.area > 1.04 * smallest && (bound.area > 0 || mid.area > 0)) {
              const double h = 0.5 * w;
              // The new corners: the edges' middles and the centre (which was `mid`).
              PupilRegion bottom = Trace(Film(i + u + h, j + v)), top = Trace(Film(i + u + h, j + v + w)),
                          left = Trace(Film(i + u, j + v + h)), right = Trace(Film(i + u + w, j + v + h));
              const PupilRegion* sub[4][4] = {{k[0], &bottom, &left, &mid},
                                              {&bottom, k[1], &mid, &right},
                                              {&left, &mid, k[2], &top},
                                              {&mid, &right, &top, k[3]}};
              for (int q = 0; q < 4; ++q) {
                const double su = u + h * (q % 2), sv = v + h * (q / 2);
                PupilRegion centre = Trace(Film(i + su + 0.5 * h, j + sv + 0.5 * h));
                build(su, sv, h, sub[q], centre, depth + 1);
              }
              return;
            }
            const int index = int(o.regions.size());
            o.regions.emplace_back(std::move(bound));
            const int span = int(std::lround(w * side)), bi = int(std::lround(u * side)), bj = int(std::lround(v * side));
            for (int y = bj; y < bj + span; ++y)
              for (int x = bi; x < bi + span; ++x) block[y * side + x] = index;
          };
      build(0, 0, 1, corner, centres[c], 0);
      if (o.regions.size() == 1) {
        o.leaves = {0};
      } else {
        o.levels = kMaxDepth;
        o.leaves.assign(block.begin(), block.end());
      }
    });
    for (CellOut& o : out) {
      const uint32_t base = uint32_t(g_.regions_.size());
      g_.first_.push_back(uint32_t(g_.leaves_.size()));
      g_.levels_.push_back(uint8_t(o.levels));
      for (uint32_t leaf : o.leaves) g_.leaves_.push_back(base + leaf);
      for (SampledPolygon& r : o.regions) g_.regions_.push_back(std::move(r));
    }
  }

 private:
  // The film point at (i, j) in cell units.
  Vec2d Film(double i, double j) const { return {g_.x0_ + i * g_.step_, g_.y0_ + j * g_.step_}; }
  PupilRegion Trace(Vec2d film) const {
    PupilRegionProbe probe{fast_, lens_, lens_.FilmZ(), plane_z_, window_, tolerance_, !round_};
    return TracePupilRegionAt(probe, film, lambdas_);
  }
  // The hull of the corners' and the centre's regions, grown by their tolerance plus twice the
  // most the centre's sticks out of the corners' hull.
  static ConvexPolygon Bound(const PupilRegion* const* k, const PupilRegion& mid) {
    double grow = mid.grow;
    for (int q = 0; q < 4; ++q) grow = std::max(grow, k[q]->grow);
    const ConvexPolygon corners = HullOfGrown({&k[0]->hull, &k[1]->hull, &k[2]->hull, &k[3]->hull}, grow);
    double margin = 0;
    if (!corners.Empty())
      for (const Vec2d& q : mid.hull) margin = std::max(margin, 2 * DistanceOutside(corners, q));
    return HullOfGrown({&k[0]->hull, &k[1]->hull, &k[2]->hull, &k[3]->hull, &mid.hull}, grow + margin);
  }

  PupilGrid& g_;
  const LensSystem& lens_;
  BatchLensTracer fast_;
  const std::vector<double>& lambdas_;
  double plane_z_, radius_, window_ = 0, tolerance_ = 0;
  bool round_ = true;
};

PupilGrid::PupilGrid(const LensSystem& lens, double film_radius, double plane_z, const PupilBoundsOptions& options) {
  Builder(*this, lens, film_radius, plane_z, options).Build();
}

PupilGrid::Found PupilGrid::RegionAt(Vec2d film) const {
  Found f{nullptr, Vec2d(1, 1)};
  if (mirror_x_ && film.x < 0) film.x = -film.x, f.mirror.x = -1;
  if (mirror_y_ && film.y < 0) film.y = -film.y, f.mirror.y = -1;
  const double u = (film.x - x0_) / step_, v = (film.y - y0_) / step_;
  // The table's far edge belongs to its last cell.
  if (!(u >= 0 && v >= 0 && u <= cells_x_ * (1 + 1e-12) && v <= cells_y_ * (1 + 1e-12))) return f;
  const int i = std::min(int(u), cells_x_ - 1), j = std::min(int(v), cells_y_ - 1);
  const int cell = j * cells_x_ + i, levels = levels_[cell], side = 1 << levels;
  const int si = std::min(int((u - i) * side), side - 1), sj = std::min(int((v - j) * side), side - 1);
  const SampledPolygon& r = regions_[leaves_[first_[cell] + sj * side + si]];
  if (!r.Empty()) f.region = &r;
  return f;
}

}  // namespace objektiv
