#include "optics/pupil_bounds.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include <tbb/parallel_for.h>

#include "base/sampling.h"
#include "optics/batch_tracer.h"
#include "optics/paraxial.h"

namespace objektiv {

namespace {

// Probing the region of the sampling plane through which light from one film point (r, 0)
// at one wavelength leaves the lens.
class RegionProbe {
 public:
  RegionProbe(const BatchLensTracer& fast, const LensTracer& exact, double r, double film_z, double plane_z,
              double lambda_nm)
      : fast_(fast), exact_(exact), r_(r), film_z_(film_z), plane_z_(plane_z), lambda_(lambda_nm) {}

  // Whether the rays aimed at each point get through.
  std::vector<uint8_t> Passes(const std::vector<Vec2d>& points) const {
    batch_.Resize(points.size());
    for (size_t n = 0; n < points.size(); ++n) {
      Vec3d d = Normalize(Vec3d(points[n].x - r_, points[n].y, plane_z_ - film_z_));
      batch_.ox[n] = float(r_), batch_.oy[n] = 0, batch_.oz[n] = float(film_z_);
      batch_.dx[n] = float(d.x), batch_.dy[n] = float(d.y), batch_.dz[n] = float(d.z);
      batch_.lambda[n] = float(lambda_);
    }
    fast_.TraceFromFilm(batch_, false);
    return batch_.alive;
  }

  // The aim point whose ray crosses the stop's centre (the real chief ray), by the secant
  // method from the axis; nothing if the ray does not reach the stop.
  std::optional<Vec2d> ChiefAim() const {
    auto stop_x = [&](double a) -> std::optional<double> {
      Vec3d o(r_, 0, film_z_);
      std::optional<Vec3d> hit = exact_.StopCrossingFromFilm({o, Normalize(Vec3d(a, 0, plane_z_) - o)}, lambda_);
      return hit ? std::optional<double>(hit->x) : std::nullopt;
    };
    double a0 = 0, a1 = 1e-3 * (1 + std::abs(r_));
    std::optional<double> f0 = stop_x(a0), f1 = stop_x(a1);
    for (int it = 0; it < 30 && f0 && f1; ++it) {
      if (std::abs(*f1) < 1e-9 || *f1 == *f0) return Vec2d(a1, 0);
      double a2 = a1 - *f1 * (a1 - a0) / (*f1 - *f0);
      a0 = a1, f0 = f1, a1 = a2, f1 = stop_x(a1);
    }
    if (f1 && std::abs(*f1) < 1e-6) return Vec2d(a1, 0);
    return std::nullopt;
  }

  // A point inside the region: the chief ray's aim if it passes, else the centroid of the
  // passing probes of a grid over the window |x|, |y| <= half; nothing if none passes.
  std::optional<Vec2d> Inside(double half) const {
    if (std::optional<Vec2d> c = ChiefAim(); c && Passes({*c})[0]) return c;
    const int g = 32;
    std::vector<Vec2d> grid;
    for (int i = 0; i < g; ++i)
      for (int j = 0; j < g; ++j) grid.push_back({half * (2 * (i + 0.5) / g - 1), half * (2 * (j + 0.5) / g - 1)});
    std::vector<uint8_t> ok = Passes(grid);
    Vec2d sum(0, 0);
    int count = 0;
    for (size_t n = 0; n < grid.size(); ++n)
      if (ok[n]) sum = sum + grid[n], ++count;
    if (count == 0) return std::nullopt;
    Vec2d c = sum * (1.0 / count);
    if (Passes({c})[0]) return c;
    for (size_t n = 0; n < grid.size(); ++n)
      if (ok[n]) return grid[n];
    return std::nullopt;
  }

  // A centre well inside the region, seen from c inside it: c itself unless it lies near the
  // edge (closer than a quarter of the region's reach from it, e.g. the chief ray's aim when a
  // mask's edge runs through the stop's centre, where rays along the edge find its corners
  // only by chance), else the mean of 16 edge points around c (inside: the region is convex).
  Vec2d Centred(Vec2d c, double limit) const {
    std::vector<Vec2d> dirs;
    for (int k = 0; k < 16; ++k) dirs.push_back({std::cos(2 * M_PI * k / 16), std::sin(2 * M_PI * k / 16)});
    std::vector<double> t = EdgeDistances(c, dirs, limit);
    if (*std::min_element(t.begin(), t.end()) >= 0.25 * *std::max_element(t.begin(), t.end())) return c;
    Vec2d mean(0, 0);
    for (size_t k = 0; k < dirs.size(); ++k) mean = mean + (c + dirs[k] * t[k]) * (1.0 / dirs.size());
    return Passes({mean})[0] ? mean : c;
  }

  // Distance from c to the region's edge along each direction, at most `limit`, to a relative
  // precision of 1e-4 (bisection, all directions in one batch per step; tiny regions, such as
  // a pinhole's, take a few more steps).
  std::vector<double> EdgeDistances(Vec2d c, const std::vector<Vec2d>& dirs, double limit) const {
    std::vector<double> lo(dirs.size(), 0), hi(dirs.size(), limit);
    std::vector<Vec2d> pts(dirs.size());
    for (int step = 0; step < 60; ++step) {
      bool done = true;
      for (size_t k = 0; k < dirs.size(); ++k) {
        pts[k] = c + dirs[k] * (0.5 * (lo[k] + hi[k]));
        done &= hi[k] - lo[k] <= 1e-4 * hi[k];
      }
      if (done) break;
      std::vector<uint8_t> ok = Passes(pts);
      for (size_t k = 0; k < dirs.size(); ++k) (ok[k] ? lo[k] : hi[k]) = 0.5 * (lo[k] + hi[k]);
    }
    return hi;  // the blocked side: just outside
  }

 private:
  const BatchLensTracer& fast_;
  const LensTracer& exact_;
  double r_, film_z_, plane_z_, lambda_;
  mutable RayBatch batch_;
};

// The region's edge around a point inside it: directions at even angles first, then, where
// the edge between two neighbouring points bulges out of their chord by more than `tol`
// (corners of the blades, tips of a cat's eye), the angle between them is halved, a few
// levels deep. The edge points are returned.
std::vector<Vec2d> TraceEdge(const RegionProbe& probe, Vec2d c, double limit, double tol) {
  struct EdgePoint {
    double angle;
    Vec2d p;
  };
  auto probe_angles = [&](const std::vector<double>& angles) {
    std::vector<Vec2d> dirs;
    for (double a : angles) dirs.push_back({std::cos(a), std::sin(a)});
    std::vector<double> t = probe.EdgeDistances(c, dirs, limit);
    std::vector<EdgePoint> out;
    for (size_t k = 0; k < angles.size(); ++k) out.push_back({angles[k], c + dirs[k] * t[k]});
    return out;
  };
  const int initial = 32;
  std::vector<double> angles;
  for (int k = 0; k < initial; ++k) angles.push_back(2 * M_PI * k / initial);
  std::vector<EdgePoint> edge = probe_angles(angles);
  std::vector<uint8_t> pending(edge.size(), 1);  // gap k: between edge[k] and edge[k + 1]
  for (int level = 0; level < 6; ++level) {
    std::vector<double> mids;
    for (size_t k = 0; k < edge.size(); ++k)
      if (pending[k]) {
        double a = edge[k].angle, b = k + 1 < edge.size() ? edge[k + 1].angle : edge[0].angle + 2 * M_PI;
        mids.push_back(0.5 * (a + b));
      }
    if (mids.empty()) break;
    std::vector<EdgePoint> found = probe_angles(mids);
    std::vector<EdgePoint> merged;
    std::vector<uint8_t> next;
    size_t m = 0;
    for (size_t k = 0; k < edge.size(); ++k) {
      merged.push_back(edge[k]);
      if (!pending[k]) {
        next.push_back(0);
        continue;
      }
      const EdgePoint &a = edge[k], &b = edge[(k + 1) % edge.size()], &mid = found[m++];
      Vec2d ab = b.p - a.p;
      double len = std::hypot(ab.x, ab.y);
      double out = len > 0 ? std::abs((mid.p.x - a.p.x) * ab.y - (mid.p.y - a.p.y) * ab.x) / len
                           : std::hypot(mid.p.x - a.p.x, mid.p.y - a.p.y);
      merged.push_back(mid);
      uint8_t again = out > tol;
      next.push_back(again);
      next.push_back(again);
    }
    edge = std::move(merged);
    pending = std::move(next);
  }
  std::vector<Vec2d> pts;
  for (const EdgePoint& e : edge) pts.push_back(e.p);
  return pts;
}

// The convex hull of edge points grown by `grow` (each point becomes a small square), so that
// the edge tolerance and the bisection's step leave no light outside.
ConvexPolygon GrownHull(const std::vector<const std::vector<Vec2d>*>& edges, double grow) {
  std::vector<Vec2d> corners;
  for (const std::vector<Vec2d>* edge : edges)
    for (const Vec2d& q : *edge)
      for (double dx : {-grow, grow})
        for (double dy : {-grow, grow}) corners.push_back({q.x + dx, q.y + dy});
  return ConvexPolygon::HullOf(std::move(corners));
}

// How far q lies outside the convex polygon (0 inside).
double Protrusion(const ConvexPolygon& poly, Vec2d q) {
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

// The edge of the passing region for one film point (all wavelengths together): the hull of
// the edge points, how much to grow it, and the area of the grown hull.
struct Edge {
  std::vector<Vec2d> hull;
  double grow = 0;   // 0.2% of the region's size (its largest distance from the probe's centre)
  double area = 0;
};

// The tracers that probe one azimuth of the table: the stop's opening turned as a film point
// at that azimuth sees it.
struct AzimuthTracers {
  BatchLensTracer fast;
  LensTracer exact;
};

}  // namespace

PupilBounds::Region PupilBounds::MakeRegion(ConvexPolygon hull) {
  Region region;
  if (!(hull.area > 0)) return region;
  ConvexPolygon& poly = region.poly;
  poly = std::move(hull);
  // Fan triangles from vertex 0, chosen in proportion to their area.
  std::vector<double>& cdf = region.cdf;
  double acc = 0;
  cdf.push_back(0);
  for (size_t t = 1; t + 1 < poly.vertices.size(); ++t) {
    acc += 0.5 * Cross(poly.vertices[0], poly.vertices[t], poly.vertices[t + 1]);
    cdf.push_back(acc);
  }
  for (double& c : cdf) c /= acc;
  // Guide table: for u in [g / G, (g + 1) / G), the triangles before guide[g] are too low.
  region.guide.resize(64);
  for (size_t g = 0; g < region.guide.size(); ++g)
    region.guide[g] = uint16_t(
        std::max<ptrdiff_t>(1, std::upper_bound(cdf.begin(), cdf.end(), double(g) / region.guide.size()) - cdf.begin()));
  return region;
}

PupilBounds::PupilBounds(const LensTracer& tracer, double film_radius, const PupilBoundsOptions& options)
    : symmetry_(tracer.stop_shape().symmetry()), film_radius_(film_radius) {
  // An opening that is not round needs regions over azimuth too: half as many radial bins
  // (the radial splitting below still follows fast changes) keep its set-up time in bounds.
  bins_ = symmetry_.order == 0 ? options.bins : std::max(8, options.bins / 2);
  const int bins = bins_;
  const std::vector<double>& lambdas = options.wavelengths;
  const LensPrescription& lens = tracer.lens();
  const int last = int(lens.surfaces.size()) - 1;
  // Sample on the exit pupil's plane: light from every film point passes the same image of the
  // stop there, trimmed slowly by vignetting, so the region changes little across an annulus
  // (on the rear vertex plane it slides with the film position).
  ParaxialData p = ComputeParaxial(lens, lambdas.front(), tracer.StopSemiDiameter());
  rear_z_ = tracer.VertexZ(last) + p.exit_pupil_position;
  // The window searched: wide enough for the rear element and the exit pupil.
  const double half = std::max(lens.surfaces[last].semi_diameter, 1.5 * p.exit_pupil_diameter) +
                      std::abs(rear_z_ - tracer.VertexZ(last));
  const double film_z = tracer.FilmZ();
  BatchLensTracer fast(tracer);
  if (!options.rims) fast.IgnoreRims();

  // The azimuth table. A round stop: one column, regions in the film point's frame. Any other
  // opening: regions in the opening's frame (lens space turned by -axis, where the opening
  // stays put and only the vignetting and the pupil's aberrations turn with the film point),
  // over azimuths psi in [0, span_] from the axis, in columns of 90 degrees or less, each
  // bin's halved where the region changes with psi (below).
  round_ = symmetry_.order == 0;
  period_ = round_ ? 2 * M_PI : 2 * M_PI / symmetry_.order;
  span_ = round_ ? 0 : (symmetry_.mirror ? period_ / 2 : period_);
  const int first_columns = round_ ? 1 : std::max(1, int(std::ceil(span_ / (M_PI / 2) - 1e-9)));
  int max_columns = first_columns;
  // The finest columns: 2.8 degrees for an iris (95% or more of the rays then pass for every
  // shipped lens); 5.6 degrees for an opening without symmetry, whose columns cover the whole
  // turn (88-97% pass, in a few seconds' set-up rather than ten).
  const double finest = symmetry_.order == 1 ? M_PI / 32 : M_PI / 64;
  while (!round_ && span_ / max_columns > finest) max_columns *= 2;
  for (int k = 0; k < (round_ ? 0 : symmetry_.order); ++k)
    turns_.push_back({std::cos(symmetry_.axis + k * period_), std::sin(symmetry_.axis + k * period_)});

  // Azimuth node m of the finest grid (psi = span_ m / max_columns): its tracers (made before
  // each parallel stage) and the edge there at each radial node k (film_radius k / bins).
  std::vector<std::unique_ptr<AzimuthTracers>> tracers(max_columns + 1);
  auto psi_of = [&](int m) { return span_ * m / max_columns; };
  auto edge_at = [&](double r, int m) {
    const AzimuthTracers& t = *tracers[m];
    // Probed with the film point on +x (the opening turned by -(axis + psi)), then turned by
    // psi into the opening's frame.
    const double c = std::cos(psi_of(m)), sn = std::sin(psi_of(m));
    Edge edge;
    std::vector<Vec2d> points;
    double size = 0;
    for (double lambda : lambdas) {
      RegionProbe probe(t.fast, t.exact, r, film_z, rear_z_, lambda);
      std::optional<Vec2d> centre = probe.Inside(half);
      if (!centre) continue;
      if (!round_) centre = probe.Centred(*centre, 2 * half);
      // Tolerance: a thousandth of the region's size (its first estimate: the exit pupil).
      double tol = 1e-3 * std::max(p.exit_pupil_diameter, 1e-9);
      for (const Vec2d& q : TraceEdge(probe, *centre, 2 * half, tol)) {
        size = std::max(size, std::hypot(q.x - centre->x, q.y - centre->y));
        points.push_back(m == 0 ? q : Vec2d(c * q.x - sn * q.y, sn * q.x + c * q.y));
      }
    }
    edge.hull = ConvexHull(std::move(points));
    edge.grow = 2e-3 * size;
    edge.area = GrownHull({&edge.hull}, edge.grow).area;
    return edge;
  };
  std::vector<std::vector<Edge>> nodes(bins + 1, std::vector<Edge>(max_columns + 1));
  std::vector<std::vector<uint8_t>> traced(bins + 1, std::vector<uint8_t>(max_columns + 1, 0));
  // Traces the nodes that bins of `columns[b]` columns need and have not been traced.
  auto trace_nodes = [&](const std::vector<int>& columns) {
    std::vector<std::pair<int, int>> todo;
    for (int b = 0; b < bins; ++b) {
      const int step = max_columns / columns[b];
      for (int k = b; k <= b + 1; ++k)
        for (int m = 0; m <= (round_ ? 0 : max_columns); m += step)
          if (!traced[k][m]) traced[k][m] = 1, todo.push_back({k, m});
    }
    for (auto [k, m] : todo)
      if (!tracers[m]) {
        const StopShape turned = tracer.stop_shape().Rotated(-(symmetry_.axis + psi_of(m)));
        LensTracer exact = tracer;
        exact.SetStopShape(turned);
        tracers[m] = std::make_unique<AzimuthTracers>(AzimuthTracers{fast.WithStopShape(turned), std::move(exact)});
      }
    tbb::parallel_for(size_t(0), todo.size(), [&](size_t i) {
      nodes[todo[i].first][todo[i].second] = edge_at(film_radius * todo[i].first / bins, todo[i].second);
    });
  };
  // Between two azimuth nodes the region moves (the vignetting turns with the film point): the
  // region half-way between them may stick out of their common hull, by `Protrusion`; the
  // cell's hull is grown by twice the most it sticks out at either radius (the largest
  // departure from the chord of a smooth motion is near the middle). A bin's columns are halved
  // while that hull wastes more than 4% of the rays of the smaller region at a column's edge.
  struct ColumnFit {
    bool fine;
    double margin;
  };
  auto fit_column = [&](int b, int m0, int m1) {
    ColumnFit fit{true, 0};
    for (int k = b; k <= b + 1; ++k) {
      const Edge &e0 = nodes[k][m0], &e1 = nodes[k][m1], &mid = nodes[k][(m0 + m1) / 2];
      ConvexPolygon both = GrownHull({&e0.hull, &e1.hull}, std::max(e0.grow, e1.grow));
      if (mid.area > 0 && both.Empty()) fit.fine = false;  // light only in between
      for (const Vec2d& q : mid.hull) fit.margin = std::max(fit.margin, 2 * Protrusion(both, q));
    }
    for (int k = b; k <= b + 1; ++k) {
      const Edge &e0 = nodes[k][m0], &e1 = nodes[k][m1];
      const double smaller = std::min(e0.area, e1.area);
      if (smaller > 0 && GrownHull({&e0.hull, &e1.hull}, std::max(e0.grow, e1.grow) + fit.margin).area > 1.04 * smaller)
        fit.fine = false;
    }
    return fit;
  };
  columns_.assign(bins, first_columns);
  std::vector<std::vector<double>> margins(bins, std::vector<double>(1, 0.0));
  std::vector<uint8_t> settled(bins, round_), with_mid(bins, 0);
  for (;;) {
    // Each unsettled bin also needs the azimuths half-way between its columns' edges.
    std::vector<int> needed(bins);
    for (int b = 0; b < bins; ++b) needed[b] = settled[b] ? columns_[b] : 2 * columns_[b];
    trace_nodes(needed);
    bool refined = false;
    for (int b = 0; b < bins; ++b) {
      if (settled[b]) continue;
      const int step = max_columns / columns_[b];
      bool fine = true;
      margins[b].assign(columns_[b], 0);
      for (int j = 0; j < columns_[b]; ++j) {
        ColumnFit fit = fit_column(b, j * step, (j + 1) * step);
        fine &= fit.fine;
        margins[b][j] = fit.margin;
      }
      // The finest level keeps its columns; their hulls take in the half-way regions too.
      if (fine || 4 * columns_[b] > max_columns) settled[b] = 1, with_mid[b] = !fine;
      else columns_[b] *= 2, refined = true;
    }
    if (!refined) break;
  }

  // A cell end: the edges at both of its column's azimuths (and half-way between them, at the
  // finest columns that did not settle), and the column's margin.
  struct End {
    const Edge *a, *b, *mid;
    double grow, area;
    void AddHulls(std::vector<const std::vector<Vec2d>*>& to) const {
      to.insert(to.end(), {&a->hull, &b->hull});
      if (mid) to.push_back(&mid->hull);
    }
  };
  auto make_end = [&](const Edge& a, const Edge& b, const Edge* mid, double margin) {
    End e{&a, &b, mid, std::max(a.grow, b.grow) + margin, 0};
    e.area = GrownHull({&a.hull, &b.hull}, e.grow).area;
    return e;
  };
  // Each cell is one annulus of one column, or where the region changes fast across it (at
  // the rim of a fisheye's image circle, say), halves, quarters, ... of it: a sub-annulus is
  // split while the hull of both its ends is more than 4% larger than the smaller end (a film
  // point at that end would waste more than 4% of its rays).
  const int max_depth = 5;
  struct CellRegions {
    std::vector<Region> regions;
    std::vector<uint32_t> leaves;  // per finest sub-annulus, its region
  };
  std::vector<std::pair<int, int>> cell_list;  // (bin, column)
  for (int b = 0; b < bins; ++b) {
    bin_first_cell_.push_back(uint32_t(cell_list.size()));
    for (int j = 0; j < columns_[b]; ++j) cell_list.push_back({b, j});
  }
  std::vector<CellRegions> per_cell(cell_list.size());
  tbb::parallel_for(size_t(0), cell_list.size(), [&](size_t cell) {
    const auto [bin, j] = cell_list[cell];
    const int step = max_columns / columns_[bin];
    const int m0 = j * step, m1 = round_ ? m0 : (j + 1) * step;
    const int mm = with_mid[bin] ? (m0 + m1) / 2 : -1;  // the half-way azimuth, where kept
    const double margin = round_ ? 0 : margins[bin][j];
    CellRegions& out = per_cell[cell];
    std::function<void(double, double, const End&, const End&, int)> build =
        [&](double r0, double r1, const End& e0, const End& e1, int depth) {
          std::vector<const std::vector<Vec2d>*> hulls;
          e0.AddHulls(hulls), e1.AddHulls(hulls);
          ConvexPolygon both = GrownHull(hulls, std::max(e0.grow, e1.grow));
          if (depth < max_depth && both.area > 1.04 * std::min(e0.area, e1.area)) {
            double rm = 0.5 * (r0 + r1);
            Edge ma = edge_at(rm, m0), mb = m1 == m0 ? Edge() : edge_at(rm, m1);
            Edge mid = mm < 0 ? Edge() : edge_at(rm, mm);
            End em = make_end(ma, m1 == m0 ? ma : mb, mm < 0 ? nullptr : &mid, margin);
            build(r0, rm, e0, em, depth + 1);
            build(rm, r1, em, e1, depth + 1);
            return;
          }
          out.leaves.insert(out.leaves.end(), size_t(1) << (max_depth - depth), uint32_t(out.regions.size()));
          out.regions.push_back(MakeRegion(std::move(both)));
        };
    build(film_radius * bin / bins, film_radius * (bin + 1) / bins,
          make_end(nodes[bin][m0], nodes[bin][m1], mm < 0 ? nullptr : &nodes[bin][mm], margin),
          make_end(nodes[bin + 1][m0], nodes[bin + 1][m1], mm < 0 ? nullptr : &nodes[bin + 1][mm], margin), 0);
  });
  // Flatten; a cell with one region needs no sub-annuli.
  for (CellRegions& c : per_cell) {
    const uint32_t base = uint32_t(regions_.size());
    cell_first_.push_back(uint32_t(leaves_.size()));
    cell_levels_.push_back(c.regions.size() == 1 ? 0 : uint8_t(max_depth));
    if (c.regions.size() == 1) leaves_.push_back(base);
    else
      for (uint32_t leaf : c.leaves) leaves_.push_back(base + leaf);
    for (Region& r : c.regions) regions_.push_back(std::move(r));
  }
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
  const Region* region = RegionAt(FrameOf(film));
  return region ? &region->poly : nullptr;
}

PupilBounds::Sample PupilBounds::SampleRear(Vec2d film, Vec2d u) const {
  const Frame frame = FrameOf(film);
  const Region* region = RegionAt(frame);
  if (!region) return {{0, 0, rear_z_}, 0};
  const ConvexPolygon& poly = region->poly;
  const std::vector<double>& cdf = region->cdf;
  // Pick a fan triangle by area (reusing u.x): the guide table gives the first candidate,
  // a short scan the triangle with cdf[t - 1] <= u.x < cdf[t].
  const std::vector<uint16_t>& guide = region->guide;
  size_t t = guide[std::min(size_t(u.x * guide.size()), guide.size() - 1)];
  while (t + 1 < cdf.size() && cdf[t] <= u.x) ++t;
  t = std::clamp<size_t>(t, 1, cdf.size() - 1);
  double ux = (u.x - cdf[t - 1]) / std::max(cdf[t] - cdf[t - 1], 1e-300);
  Vec2f bary = SampleUniformTriangle({float(std::min(ux, 0.99999994)), float(u.y)});
  const Vec2d &a = poly.vertices[0], &bb = poly.vertices[t], &c = poly.vertices[t + 1];
  double b2 = 1 - bary.x - bary.y;
  Vec2d p(a.x * bary.x + bb.x * bary.y + c.x * b2, a.y * bary.x + bb.y * bary.y + c.y * b2);
  if (frame.mirrored) p.y = -p.y;
  // From the table's frame to lens space.
  const double cs = frame.cos_sin.x, sn = frame.cos_sin.y;
  return {{p.x * cs - p.y * sn, p.x * sn + p.y * cs, rear_z_}, 1 / poly.area};
}

}  // namespace objektiv
