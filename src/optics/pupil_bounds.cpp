#include "optics/pupil_bounds.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <tbb/parallel_for.h>

#include "base/sampling.h"
#include "optics/batch_tracer.h"
#include "optics/paraxial.h"

namespace objektiv {

namespace {

double Cross(Vec2d o, Vec2d a, Vec2d b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Andrew's monotone chain: the convex hull, counter-clockwise.
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

}  // namespace

bool ConvexPolygon::Contains(Vec2d p) const {
  if (vertices.size() < 3) return false;
  for (size_t i = 0; i < vertices.size(); ++i)
    if (Cross(vertices[i], vertices[(i + 1) % vertices.size()], p) < 0) return false;
  return true;
}

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
std::vector<Vec2d> GrownHull(std::initializer_list<const std::vector<Vec2d>*> edges, double grow) {
  std::vector<Vec2d> corners;
  for (const std::vector<Vec2d>* edge : edges)
    for (const Vec2d& q : *edge)
      for (double dx : {-grow, grow})
        for (double dy : {-grow, grow}) corners.push_back({q.x + dx, q.y + dy});
  return ConvexHull(corners);
}

double HullArea(const std::vector<Vec2d>& hull) { return hull.size() >= 3 ? PolygonArea(hull) : 0; }

}  // namespace

PupilBounds::Region PupilBounds::MakeRegion(std::vector<Vec2d> hull) {
  Region region;
  ConvexPolygon& poly = region.poly;
  poly.area = HullArea(hull);
  if (!(poly.area > 0)) return region;
  poly.vertices = std::move(hull);
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
    : film_radius_(film_radius) {
  const int bins = options.bins;
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
  // The edge of the passing region for one film radius, all wavelengths together, and the
  // area its grown hull bounds.
  struct Edge {
    std::vector<Vec2d> points;
    double grow = 0;  // 0.2% of the region's size (its largest distance from the probe's centre)
    double area = 0;
  };
  auto edge_at = [&](double r) {
    Edge edge;
    double size = 0;
    for (double lambda : lambdas) {
      RegionProbe probe(fast, tracer, r, film_z, rear_z_, lambda);
      std::optional<Vec2d> c = probe.Inside(half);
      if (!c) continue;
      // Tolerance: a thousandth of the region's size (its first estimate: the exit pupil).
      double tol = 1e-3 * std::max(p.exit_pupil_diameter, 1e-9);
      std::vector<Vec2d> e = TraceEdge(probe, *c, 2 * half, tol);
      for (const Vec2d& q : e) size = std::max(size, std::hypot(q.x - c->x, q.y - c->y));
      edge.points.insert(edge.points.end(), e.begin(), e.end());
    }
    edge.grow = 2e-3 * size;
    edge.area = HullArea(GrownHull({&edge.points}, edge.grow));
    return edge;
  };
  // Each bin is one annulus, or where the region changes fast across it (at the rim of a
  // fisheye's image circle, say), halves, quarters, ... of it: a sub-annulus is split while
  // the hull of both its ends is more than 4% larger than the smaller end (a film point at
  // that end would waste more than 4% of its rays).
  const int max_depth = 5;
  struct BinRegions {
    std::vector<Region> regions;
    std::vector<uint32_t> leaves;  // per finest sub-annulus, its region
  };
  std::vector<BinRegions> per_bin(bins);
  std::vector<Edge> ends(bins + 1);
  tbb::parallel_for(0, bins + 1, [&](int k) { ends[k] = edge_at(film_radius * k / bins); });
  tbb::parallel_for(0, bins, [&](int bin) {
    BinRegions& out = per_bin[bin];
    std::function<void(double, double, const Edge&, const Edge&, int)> build =
        [&](double r0, double r1, const Edge& e0, const Edge& e1, int depth) {
          std::vector<Vec2d> both = GrownHull({&e0.points, &e1.points}, std::max(e0.grow, e1.grow));
          if (depth < max_depth && HullArea(both) > 1.04 * std::min(e0.area, e1.area)) {
            double rm = 0.5 * (r0 + r1);
            Edge em = edge_at(rm);
            build(r0, rm, e0, em, depth + 1);
            build(rm, r1, em, e1, depth + 1);
            return;
          }
          out.leaves.insert(out.leaves.end(), size_t(1) << (max_depth - depth), uint32_t(out.regions.size()));
          out.regions.push_back(MakeRegion(std::move(both)));
        };
    build(film_radius * bin / bins, film_radius * (bin + 1) / bins, ends[bin], ends[bin + 1], 0);
  });
  // Flatten; a bin with one region needs no sub-annuli.
  for (int bin = 0; bin < bins; ++bin) {
    BinRegions& b = per_bin[bin];
    const uint32_t base = uint32_t(regions_.size());
    bin_first_.push_back(uint32_t(leaves_.size()));
    bin_levels_.push_back(b.regions.size() == 1 ? 0 : uint8_t(max_depth));
    if (b.regions.size() == 1) leaves_.push_back(base);
    else
      for (uint32_t leaf : b.leaves) leaves_.push_back(base + leaf);
    for (Region& r : b.regions) regions_.push_back(std::move(r));
  }
}

const PupilBounds::Region* PupilBounds::RegionAt(double r) const {
  double x = r / film_radius_ * bin_first_.size();
  int bin = int(x);
  if (bin < 0 || bin >= int(bin_first_.size())) return nullptr;
  int levels = bin_levels_[bin];
  int sub = std::min(int((x - bin) * (1 << levels)), (1 << levels) - 1);
  const Region& region = regions_[leaves_[bin_first_[bin] + sub]];
  return region.poly.area > 0 ? &region : nullptr;
}

const ConvexPolygon* PupilBounds::BoundAt(double r) const {
  const Region* region = RegionAt(r);
  return region ? &region->poly : nullptr;
}

PupilBounds::Sample PupilBounds::SampleRear(Vec2d film, Vec2d u) const {
  double r = std::sqrt(film.x * film.x + film.y * film.y);
  const Region* region = RegionAt(r);
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
  // The bound was built for a film point on +x: rotate it to the film point's azimuth.
  double cs = r > 0 ? film.x / r : 1, sn = r > 0 ? film.y / r : 0;
  return {{p.x * cs - p.y * sn, p.x * sn + p.y * cs, rear_z_}, 1 / poly.area};
}

}  // namespace objektiv
