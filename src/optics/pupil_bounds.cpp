#include "optics/pupil_bounds.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include <tbb/parallel_for.h>

#include "base/sampling.h"
#include "optics/paraxial.h"
#include "optics/pupil_region.h"

namespace objektiv {

// Named (not anonymous): PupilBounds::Builder holds these, which warns in a unity build.
namespace pupil_bounds_detail {

using PointSets = std::vector<const std::vector<Vec2d>*>;

// The lens as a film point at one azimuth of the table sees it (the stop's opening turned),
// for both tracers.
struct TurnedLens {
  TurnedLens(LensSystem turned, bool rims) : exact(std::move(turned)), fast(exact) {
    if (!rims) fast.IgnoreRims();
  }
  LensSystem exact;
  BatchLensTracer fast;
};

// What a cell of the table is made of: the regions at its two azimuths (and half-way between
// them, at the finest columns that did not settle) at one of its radii, grown by the column's
// margin.
struct CellEnd {
  const PupilRegion *a, *b, *mid;
  double grow, area;
  void AddHulls(PointSets& to) const {
    to.insert(to.end(), {&a->hull, &b->hull});
    if (mid) to.push_back(&mid->hull);
  }
};

}  // namespace pupil_bounds_detail
using pupil_bounds_detail::CellEnd;
using pupil_bounds_detail::PointSets;
using pupil_bounds_detail::TurnedLens;

// Builds the table: regions traced at nodes (radial node k at film_radius k / bins, azimuth
// node m at psi = span m / max_columns), each bin's columns refined, then each cell's bound.
class PupilBounds::Builder {
 public:
  Builder(PupilBounds& table, const LensSystem& lens_system, const PupilBoundsOptions& options)
      : t_(table), lens_(lens_system), lambdas_(options.wavelengths), rims_(options.rims) {
    // Sample on the exit pupil's plane: light from every film point passes the same image of
    // the stop there, trimmed slowly by vignetting, so the region changes little across an
    // annulus (on the rear vertex plane it slides with the film position).
    t_.rear_z_ = PupilPlaneZ(lens_system, lambdas_.front());
    const PupilSearch search = PupilSearchFor(lens_system, t_.rear_z_, lambdas_.front());
    window_ = search.window, tolerance_ = search.tolerance;
    // Columns start at 90 degrees or less. The finest: 2.8 degrees for an iris (95% or more
    // of the rays then pass for every shipped lens); 5.6 degrees for an opening without
    // symmetry, whose columns cover the whole turn (88-97% pass, in a few seconds' set-up
    // rather than ten).
    first_columns_ = t_.round_ ? 1 : std::max(1, int(std::ceil(t_.span_ / (M_PI / 2) - 1e-9)));
    max_columns_ = first_columns_;
    const double finest = t_.symmetry_.order == 1 ? M_PI / 32 : M_PI / 64;
    while (!t_.round_ && t_.span_ / max_columns_ > finest) max_columns_ *= 2;
    turned_.resize(max_columns_ + 1);
    nodes_.assign(t_.bins_ + 1, std::vector<PupilRegion>(max_columns_ + 1));
    traced_.assign(t_.bins_ + 1, std::vector<uint8_t>(max_columns_ + 1, 0));
  }

  void Build() {
    RefineColumns();
    BuildCells();
  }

 private:
  double Radius(int k) const { return t_.film_radius_ * k / t_.bins_; }
  double Psi(int m) const { return t_.span_ * m / max_columns_; }

  // The region at radius r and azimuth node m, in the table's frame: probed with the film
  // point on +x (the opening turned by -(axis + psi)), then turned by psi.
  PupilRegion Trace(double r, int m) const {
    const TurnedLens& at = *turned_[m];
    PupilRegionProbe probe{at.fast, at.exact, lens_.FilmZ(), t_.rear_z_, window_, tolerance_, !t_.round_};
    return TracePupilRegion(probe, r, lambdas_, Psi(m));
  }

  // Traces the nodes that bins of `columns[b]` columns need and have not been traced.
  void TraceNodes(const std::vector<int>& columns) {
    std::vector<std::pair<int, int>> todo;
    for (int b = 0; b < t_.bins_; ++b) {
      const int step = max_columns_ / columns[b];
      for (int k = b; k <= b + 1; ++k)
        for (int m = 0; m <= (t_.round_ ? 0 : max_columns_); m += step)
          if (!traced_[k][m]) traced_[k][m] = 1, todo.push_back({k, m});
    }
    for (auto [k, m] : todo)
      if (!turned_[m]) {
        LensSystem turned = lens_;
        turned.SetStopShape(lens_.stop_shape().Rotated(-(t_.symmetry_.axis + Psi(m))));
        turned_[m] = std::make_unique<TurnedLens>(std::move(turned), rims_);
      }
    tbb::parallel_for(size_t(0), todo.size(), [&](size_t i) {
      auto [k, m] = todo[i];
      nodes_[k][m] = Trace(Radius(k), m);
    });
  }

  // Between two azimuth nodes the region moves (the vignetting and the pupil's aberrations
  // turn with the film point): the region half-way between them may stick out of their common
  // hull; the column's hull is grown by twice the most it sticks out at either radius (a
  // smooth motion departs from the chord most near the middle). A column is fine where that
  // hull wastes at most 4% of the rays of the smaller region at its edges.
  struct ColumnFit {
    bool fine;
    double margin;
  };
  ColumnFit FitColumn(int b, int m0, int m1) const {
    ColumnFit fit{true, 0};
    for (int k = b; k <= b + 1; ++k) {
      const PupilRegion &e0 = nodes_[k][m0], &e1 = nodes_[k][m1], &mid = nodes_[k][(m0 + m1) / 2];
      ConvexPolygon both = HullOfGrown({&e0.hull, &e1.hull}, std::max(e0.grow, e1.grow));
      if (mid.area > 0 && both.Empty()) fit.fine = false;  // light only in between
      for (const Vec2d& q : mid.hull) fit.margin = std::max(fit.margin, 2 * DistanceOutside(both, q));
    }
    for (int k = b; k <= b + 1; ++k) {
      const PupilRegion &e0 = nodes_[k][m0], &e1 = nodes_[k][m1];
      const double smaller = std::min(e0.area, e1.area);
      if (smaller > 0 && HullOfGrown({&e0.hull, &e1.hull}, std::max(e0.grow, e1.grow) + fit.margin).area > 1.04 * smaller)
        fit.fine = false;
    }
    return fit;
  }

  // Each bin's columns are halved until all are fine or the finest are reached; those keep
  // the half-way regions in their hulls.
  void RefineColumns() {
    t_.columns_.assign(t_.bins_, first_columns_);
    margins_.assign(t_.bins_, std::vector<double>(1, 0.0));
    with_mid_.assign(t_.bins_, 0);
    std::vector<uint8_t> settled(t_.bins_, t_.round_);
    for (;;) {
      // Each unsettled bin also needs the azimuths half-way between its columns' edges.
      std::vector<int> needed(t_.bins_);
      for (int b = 0; b < t_.bins_; ++b) needed[b] = settled[b] ? t_.columns_[b] : 2 * t_.columns_[b];
      TraceNodes(needed);
      bool refined = false;
      for (int b = 0; b < t_.bins_; ++b) {
        if (settled[b]) continue;
        const int step = max_columns_ / t_.columns_[b];
        bool fine = true;
        margins_[b].assign(t_.columns_[b], 0);
        for (int j = 0; j < t_.columns_[b]; ++j) {
          ColumnFit fit = FitColumn(b, j * step, (j + 1) * step);
          fine &= fit.fine;
          margins_[b][j] = fit.margin;
        }
        if (fine || 4 * t_.columns_[b] > max_columns_) settled[b] = 1, with_mid_[b] = !fine;
        else t_.columns_[b] *= 2, refined = true;
      }
      if (!refined) break;
    }
  }

  CellEnd MakeEnd(const PupilRegion& a, const PupilRegion& b, const PupilRegion* mid, double margin) const {
    CellEnd e{&a, &b, mid, std::max(a.grow, b.grow) + margin, 0};
    e.area = HullOfGrown({&a.hull, &b.hull}, e.grow).area;
    return e;
  }

  // Each cell is one annulus of one column, or where the region changes fast across it (at
  // the rim of a fisheye's image circle, say), halves, quarters, ... of it: a sub-annulus is
  // split while the hull of both its ends is more than 4% larger than the smaller end (a film
  // point at that end would waste more than 4% of its rays).
  void BuildCells() {
    const int max_depth = 5;
    struct CellRegions {
      std::vector<Region> regions;
      std::vector<uint32_t> leaves;  // per finest sub-annulus, its region
    };
    std::vector<std::pair<int, int>> cells;  // (bin, column)
    for (int b = 0; b < t_.bins_; ++b) {
      t_.bin_first_cell_.push_back(uint32_t(cells.size()));
      for (int j = 0; j < t_.columns_[b]; ++j) cells.push_back({b, j});
    }
    std::vector<CellRegions> per_cell(cells.size());
    tbb::parallel_for(size_t(0), cells.size(), [&](size_t cell) {
      const auto [bin, j] = cells[cell];
      const int step = max_columns_ / t_.columns_[bin];
      const int m0 = j * step, m1 = t_.round_ ? m0 : (j + 1) * step;
      const int mm = with_mid_[bin] ? (m0 + m1) / 2 : -1;  // the half-way azimuth, where kept
      const double margin = t_.round_ ? 0 : margins_[bin][j];
      CellRegions& out = per_cell[cell];
      std::function<void(double, double, const CellEnd&, const CellEnd&, int)> build =
          [&](double r0, double r1, const CellEnd& e0, const CellEnd& e1, int depth) {
            PointSets hulls;
            e0.AddHulls(hulls), e1.AddHulls(hulls);
            ConvexPolygon both = HullOfGrown(hulls, std::max(e0.grow, e1.grow));
            if (depth < max_depth && both.area > 1.04 * std::min(e0.area, e1.area)) {
              double rm = 0.5 * (r0 + r1);
              PupilRegion ra = Trace(rm, m0), rb = m1 == m0 ? PupilRegion() : Trace(rm, m1);
              PupilRegion rmid = mm < 0 ? PupilRegion() : Trace(rm, mm);
              CellEnd em = MakeEnd(ra, m1 == m0 ? ra : rb, mm < 0 ? nullptr : &rmid, margin);
              build(r0, rm, e0, em, depth + 1);
              build(rm, r1, em, e1, depth + 1);
              return;
            }
            out.leaves.insert(out.leaves.end(), size_t(1) << (max_depth - depth), uint32_t(out.regions.size()));
            out.regions.push_back(Region(std::move(both)));
          };
      auto end_at = [&](int k) {
        return MakeEnd(nodes_[k][m0], nodes_[k][m1], mm < 0 ? nullptr : &nodes_[k][mm], margin);
      };
      build(Radius(bin), Radius(bin + 1), end_at(bin), end_at(bin + 1), 0);
    });
    // Flatten; a cell with one region needs no sub-annuli.
    for (CellRegions& c : per_cell) {
      const uint32_t base = uint32_t(t_.regions_.size());
      t_.cell_first_.push_back(uint32_t(t_.leaves_.size()));
      t_.cell_levels_.push_back(c.regions.size() == 1 ? 0 : uint8_t(max_depth));
      if (c.regions.size() == 1) t_.leaves_.push_back(base);
      else
        for (uint32_t leaf : c.leaves) t_.leaves_.push_back(base + leaf);
      for (Region& r : c.regions) t_.regions_.push_back(std::move(r));
    }
  }

  PupilBounds& t_;
  const LensSystem& lens_;
  const std::vector<double>& lambdas_;
  bool rims_;
  double window_, tolerance_;
  int first_columns_, max_columns_;
  std::vector<std::unique_ptr<TurnedLens>> turned_;  // per azimuth node, made on demand
  std::vector<std::vector<PupilRegion>> nodes_;            // [k][m]
  std::vector<std::vector<uint8_t>> traced_;
  std::vector<std::vector<double>> margins_;  // per bin and column
  std::vector<uint8_t> with_mid_;             // per bin
};

PupilBounds::PupilBounds(const LensSystem& lens, double film_radius, const PupilBoundsOptions& options)
    : symmetry_(lens.stop_shape().symmetry()), film_radius_(film_radius) {
  // A round stop: one column, regions in the film point's frame. Any other opening: regions
  // in the opening's frame (lens space turned by -axis, where the opening stays put and only
  // the vignetting and the pupil's aberrations turn with the film point), over azimuths psi
  // in [0, span_] from the axis, and half as many radial bins (the radial splitting still
  // follows fast changes) to keep the set-up time in bounds.
  round_ = symmetry_.order == 0;
  bins_ = round_ ? options.bins : std::max(8, options.bins / 2);
  period_ = round_ ? 2 * M_PI : 2 * M_PI / symmetry_.order;
  span_ = round_ ? 0 : (symmetry_.mirror ? period_ / 2 : period_);
  for (int k = 0; k < (round_ ? 0 : symmetry_.order); ++k)
    turns_.push_back({std::cos(symmetry_.axis + k * period_), std::sin(symmetry_.axis + k * period_)});
  // A central obstruction only takes light away: the bound is built for the lens without it
  // (the convex hull of an annulus is its disc anyway, and the region search walks out from the
  // chief ray, which the obstruction blocks).
  const LensSystem unobstructed = lens.WithoutObstructions();
  // (A rectangular hood's mouth is no figure of revolution either.)
  if (!lens.prescription().RotationallySymmetric() || (lens.hood() && lens.hood()->radius == 0)) {
    rear_z_ = PupilPlaneZ(unobstructed, options.wavelengths.front());
    grid_ = std::make_unique<PupilGrid>(unobstructed, film_radius, rear_z_, options);
    return;
  }
  Builder(*this, unobstructed, options).Build();
}

PupilBounds::~PupilBounds() = default;
PupilBounds::PupilBounds(PupilBounds&&) noexcept = default;

size_t PupilBounds::RegionCount() const { return grid_ ? grid_->RegionCount() : regions_.size(); }
int PupilBounds::MaxAzimuthColumns() const {
  return grid_ ? 0 : *std::max_element(columns_.begin(), columns_.end());
}

PupilBounds::Frame PupilBounds::FrameOf(Vec2d film) const {
  const double r = std::sqrt(film.x * film.x + film.y * film.y);
  Frame f{r, 0, false, Vec2d(r > 0 ? film.x / r : 1, r > 0 ? film.y / r : 0)};
  if (round_) return f;  // the film point's own frame
  // The azimuth from the axis: turns by whole periods (k), then the mirror (psi and period - psi
  // mirror each other about the axis of the next period).
  double psi = std::atan2(f.cos_sin.y, f.cos_sin.x) - symmetry_.axis;
  const double periods = std::floor(psi / period_);
  psi -= period_ * periods;
  int k = int(periods);
  if (symmetry_.mirror && psi > span_) psi = period_ - psi, f.mirrored = true, ++k;
  k %= symmetry_.order;
  if (k < 0) k += symmetry_.order;
  f.cos_sin = turns_[k];
  f.psi = psi;
  return f;
}

const PupilBounds::Region* PupilBounds::RegionAt(const Frame& f) const {
  double x = f.r / film_radius_ * bins_;
  int bin = int(x);
  if (bin < 0 || bin >= bins_) return nullptr;
  const int columns = columns_[bin];
  const int column = round_ ? 0 : std::clamp(int(f.psi / span_ * columns), 0, columns - 1);
  const int cell = bin_first_cell_[bin] + column;
  int levels = cell_levels_[cell];
  int sub = std::min(int((x - bin) * (1 << levels)), (1 << levels) - 1);
  const Region& region = regions_[leaves_[cell_first_[cell] + sub]];
  return region.poly.area > 0 ? &region : nullptr;
}

const ConvexPolygon* PupilBounds::BoundAt(Vec2d film) const {
  if (grid_) {
    const PupilGrid::Found f = grid_->RegionAt(film);
    return f.region ? &f.region->poly : nullptr;
  }
  const Region* region = RegionAt(FrameOf(film));
  return region ? &region->poly : nullptr;
}

PupilBounds::Sample PupilBounds::SampleRear(Vec2d film, Vec2d u) const {
  if (grid_) {
    const PupilGrid::Found f = grid_->RegionAt(film);
    if (!f.region) return {{0, 0, rear_z_}, 0};
    const Vec2d p = f.region->Sample(u);
    return {{p.x * f.mirror.x, p.y * f.mirror.y, rear_z_}, 1 / f.region->poly.area};
  }
  const Frame frame = FrameOf(film);
  const Region* region = RegionAt(frame);
  if (!region) return {{0, 0, rear_z_}, 0};
  Vec2d p = region->Sample(u);
  if (frame.mirrored) p.y = -p.y;
  // From the table's frame to lens space.
  const double cs = frame.cos_sin.x, sn = frame.cos_sin.y;
  return {{p.x * cs - p.y * sn, p.x * sn + p.y * cs, rear_z_}, 1 / region->poly.area};
}

double PupilBounds::PdfRear(Vec2d film, Vec2d point) const {
  if (grid_) {
    const PupilGrid::Found f = grid_->RegionAt(film);
    if (!f.region) return 0;
    return f.region->Contains(Vec2d(point.x * f.mirror.x, point.y * f.mirror.y)) ? 1 / f.region->poly.area : 0;
  }
  const Frame frame = FrameOf(film);
  const Region* region = RegionAt(frame);
  if (!region) return 0;
  // From lens space to the table's frame: the turn undone, then the mirror.
  const double cs = frame.cos_sin.x, sn = frame.cos_sin.y;
  Vec2d p(point.x * cs + point.y * sn, -point.x * sn + point.y * cs);
  if (frame.mirrored) p.y = -p.y;
  return region->Contains(p) ? 1 / region->poly.area : 0;
}

double PupilPlaneZ(const LensSystem& lens, double lambda_nm) {
  return lens.VertexZ(lens.SurfaceCount() - 1) + lens.Paraxial(lambda_nm).exit_pupil_position;
}

}  // namespace objektiv
