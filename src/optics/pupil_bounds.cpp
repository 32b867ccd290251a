#include "optics/pupil_bounds.h"

#include <algorithm>
#include <cmath>

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
// Traces, from film points (r, 0) for each radius and wavelength, rays aimed at the given
// points of the sampling plane; returns for each point whether any of them got through.
std::vector<uint8_t> Passes(const BatchLensTracer& fast, const std::vector<double>& radii, double film_z,
                            double plane_z, const std::vector<Vec2d>& points, const std::vector<double>& wavelengths) {
  std::vector<uint8_t> any(points.size(), 0);
  RayBatch b;
  for (size_t c = 0; c < radii.size() * wavelengths.size(); ++c) {
    const double r = radii[c % radii.size()], lambda_nm = wavelengths[c / radii.size()];
    b.Resize(points.size());
    for (size_t n = 0; n < points.size(); ++n) {
      Vec3d d = Normalize(Vec3d(points[n].x - r, points[n].y, plane_z - film_z));
      b.ox[n] = float(r), b.oy[n] = 0, b.oz[n] = float(film_z);
      b.dx[n] = float(d.x), b.dy[n] = float(d.y), b.dz[n] = float(d.z);
      b.lambda[n] = float(lambda_nm);
    }
    fast.TraceFromFilm(b, false);
    for (size_t n = 0; n < points.size(); ++n) any[n] |= b.alive[n];
  }
  return any;
}

// Grid x grid cell centres over [lo, hi].
std::vector<Vec2d> GridCentres(Vec2d lo, Vec2d hi, int grid, Vec2d* cell) {
  *cell = Vec2d((hi.x - lo.x) / grid, (hi.y - lo.y) / grid);
  std::vector<Vec2d> c;
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j) c.push_back({lo.x + (i + 0.5) * cell->x, lo.y + (j + 0.5) * cell->y});
  return c;
}
}  // namespace

PupilBounds::PupilBounds(const LensTracer& tracer, double film_radius, const PupilBoundsOptions& options)
    : film_radius_(film_radius) {
  const int bins = options.bins, grid = options.grid;
  const std::vector<double>& lambdas = options.wavelengths;
  const double lambda_nm = lambdas.front();
  const LensPrescription& lens = tracer.lens();
  const int last = int(lens.surfaces.size()) - 1;
  // Sample on the exit pupil's plane: light from every film point passes the same image of the
  // stop there, trimmed slowly by vignetting, so the region changes little across an annulus
  // (on the rear vertex plane it slides with the film position).
  ParaxialData p = ComputeParaxial(lens, lambda_nm, tracer.StopSemiDiameter());
  rear_z_ = tracer.VertexZ(last) + p.exit_pupil_position;
  const double rear = std::max(lens.surfaces[last].semi_diameter, 1.5 * p.exit_pupil_diameter);
  const double film_z = tracer.FilmZ();
  BatchLensTracer fast(tracer);
  if (!options.rims) fast.IgnoreRims();
  bounds_.resize(bins);
  triangle_cdf_.resize(bins);
  // Bins are independent: build them in parallel.
  tbb::parallel_for(0, bins, [&](int bin) {
    // Film radii across the annulus, its ends included, so the bound covers every film point
    // the bin will serve.
    std::vector<double> radii;
    for (int k = 0; k < 4; ++k) radii.push_back(film_radius * (bin + k / 3.0) / bins);
    // Coarse pass over the whole plane to find where light gets through.
    Vec2d coarse_cell;
    std::vector<Vec2d> coarse = GridCentres({-rear, -rear}, {rear, rear}, grid / 2, &coarse_cell);
    std::vector<uint8_t> coarse_ok = Passes(fast, radii, film_z, rear_z_, coarse, lambdas);
    Vec2d lo(-rear, -rear), hi(rear, rear);
    bool found = false;
    for (size_t n = 0; n < coarse.size(); ++n)
      if (coarse_ok[n]) {
        lo = found ? Vec2d(std::min(lo.x, coarse[n].x), std::min(lo.y, coarse[n].y)) : coarse[n];
        hi = found ? Vec2d(std::max(hi.x, coarse[n].x), std::max(hi.y, coarse[n].y)) : coarse[n];
        found = true;
      }
    if (found) {
      lo = lo - coarse_cell * 1.5;
      hi = hi + coarse_cell * 1.5;
    } else {
      lo = {-rear, -rear}, hi = {rear, rear};
    }
    // Fine pass over that box, then cells on the region's edge (a passing cell next to a
    // blocked one, or the reverse) are probed again at 4 x 4 finer resolution. The region's
    // edge lies within one probe spacing of a passing probe, so each passing probe contributes
    // the square one spacing around it; the bound is the convex hull of those squares.
    Vec2d cell;
    std::vector<Vec2d> fine = GridCentres(lo, hi, grid, &cell);
    std::vector<uint8_t> ok = Passes(fast, radii, film_z, rear_z_, fine, lambdas);
    auto at = [&](int i, int j) { return i >= 0 && j >= 0 && i < grid && j < grid && ok[size_t(i) * grid + j]; };
    std::vector<Vec2d> sub;
    const int k = 4;
    for (int i = 0; i < grid; ++i)
      for (int j = 0; j < grid; ++j) {
        bool self = at(i, j);
        bool edge = false;
        for (int di = -1; di <= 1; ++di)
          for (int dj = -1; dj <= 1; ++dj) edge |= at(i + di, j + dj) != self;
        if (!edge) continue;
        Vec2d c0 = fine[size_t(i) * grid + j] - cell * 0.5;
        for (int a = 0; a < k; ++a)
          for (int bb = 0; bb < k; ++bb) sub.push_back({c0.x + (a + 0.5) * cell.x / k, c0.y + (bb + 0.5) * cell.y / k});
      }
    std::vector<uint8_t> sub_ok = Passes(fast, radii, film_z, rear_z_, sub, lambdas);
    std::vector<Vec2d> corners;
    for (size_t n = 0; n < sub.size(); ++n)
      if (sub_ok[n])
        for (double dx : {-1.0, 1.0})
          for (double dy : {-1.0, 1.0}) corners.push_back({sub[n].x + dx * cell.x / k, sub[n].y + dy * cell.y / k});
    // Interior cells (all neighbours passing) lie inside the hull of the edge cells; a region
    // too small to have interior cells still has its passing coarse cells among the edges.
    ConvexPolygon poly;
    poly.vertices = ConvexHull(corners);
    poly.area = poly.vertices.size() >= 3 ? PolygonArea(poly.vertices) : 0;
    std::vector<double> cdf;
    if (poly.area > 0) {
      // Fan triangles from vertex 0, chosen in proportion to their area.
      double acc = 0;
      cdf.push_back(0);
      for (size_t t = 1; t + 1 < poly.vertices.size(); ++t) {
        acc += 0.5 * Cross(poly.vertices[0], poly.vertices[t], poly.vertices[t + 1]);
        cdf.push_back(acc);
      }
      for (double& c : cdf) c /= acc;
    } else {
      poly.vertices.clear();
    }
    bounds_[bin] = std::move(poly);
    triangle_cdf_[bin] = std::move(cdf);
  });
}

const ConvexPolygon* PupilBounds::BoundAt(double r) const {
  int bin = int(r / film_radius_ * bounds_.size());
  if (bin < 0 || bin >= int(bounds_.size()) || bounds_[bin].area <= 0) return nullptr;
  return &bounds_[bin];
}

PupilBounds::Sample PupilBounds::SampleRear(Vec2d film, Vec2d u) const {
  double r = std::hypot(film.x, film.y);
  int bin = int(r / film_radius_ * bounds_.size());
  if (bin < 0 || bin >= int(bounds_.size()) || bounds_[bin].area <= 0) return {{0, 0, rear_z_}, 0};
  const ConvexPolygon& poly = bounds_[bin];
  const std::vector<double>& cdf = triangle_cdf_[bin];
  // Pick a fan triangle by area (reusing u.x), then a uniform point in it.
  size_t t = size_t(std::upper_bound(cdf.begin(), cdf.end(), u.x) - cdf.begin());
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
