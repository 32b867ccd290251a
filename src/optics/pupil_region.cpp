#include "optics/pupil_region.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "optics/dispersion.h"
#include "optics/lens_tracer.h"

namespace objektiv {

namespace {

// What a probe's ray carries: its wavelength and the waves it takes in the lens's birefringent
// crystals (LensRay::wave_choices).
struct ProbeLight {
  double lambda;
  uint32_t waves;
};

// Probing the region of the sampling plane through which light from one film point leaves the
// lens: light of any of several kinds (wavelengths, crystal waves), a point passing where any
// of them gets through. Each kind's region holding the probe's centre, the points along a
// line from the centre that pass are those before the farthest of their edges: the bisection
// finds that edge, and their hull is the hull of all.
class RegionProbe {
 public:
  RegionProbe(const BatchLensTracer& fast, const LensSystem& exact, Vec2d film, double film_z, double plane_z,
              std::vector<ProbeLight> lights)
      : fast_(fast), exact_(exact), film_(film), film_z_(film_z), plane_z_(plane_z), lights_(std::move(lights)) {}

  // Whether the rays aimed at each point get through (in any light: each further one is traced
  // only for the points that the ones before did not pass).
  std::vector<uint8_t> Passes(const std::vector<Vec2d>& points) const {
    std::vector<uint8_t> passed(points.size(), 0);
    std::vector<size_t> pending(points.size());
    for (size_t n = 0; n < points.size(); ++n) pending[n] = n;
    for (const ProbeLight& light : lights_) {
      if (pending.empty()) break;
      batch_.Resize(pending.size());
      for (size_t m = 0; m < pending.size(); ++m) {
        const Vec2d q = points[pending[m]];
        Vec3d d = Normalize(Vec3d(q.x - film_.x, q.y - film_.y, plane_z_ - film_z_));
        batch_.ox[m] = float(film_.x), batch_.oy[m] = float(film_.y), batch_.oz[m] = float(film_z_);
        batch_.dx[m] = float(d.x), batch_.dy[m] = float(d.y), batch_.dz[m] = float(d.z);
        batch_.lambda[m] = float(light.lambda);
        batch_.wave_choices[m] = light.waves;
      }
      fast_.TraceFromFilm(batch_, false);
      size_t still = 0;
      for (size_t m = 0; m < pending.size(); ++m)
        if (batch_.alive[m]) passed[pending[m]] = 1;
        else pending[still++] = pending[m];
      pending.resize(still);
    }
    return passed;
  }

  // Whether the ray aimed at c gets through in every light (one batch, a ray per light).
  bool PassesInEveryLight(Vec2d c) const {
    const Vec3d d = Normalize(Vec3d(c.x - film_.x, c.y - film_.y, plane_z_ - film_z_));
    batch_.Resize(lights_.size());
    for (size_t m = 0; m < lights_.size(); ++m) {
      batch_.ox[m] = float(film_.x), batch_.oy[m] = float(film_.y), batch_.oz[m] = float(film_z_);
      batch_.dx[m] = float(d.x), batch_.dy[m] = float(d.y), batch_.dz[m] = float(d.z);
      batch_.lambda[m] = float(lights_[m].lambda);
      batch_.wave_choices[m] = lights_[m].waves;
    }
    fast_.TraceFromFilm(batch_, false);
    return std::all_of(batch_.alive.begin(), batch_.alive.end(), [](uint8_t a) { return a != 0; });
  }

  // The aim point whose ray (in the first light) crosses the stop's centre (the real chief
  // ray), by the secant method from the axis (in the meridional plane, for a film point on +x
  // of a rotationally symmetric lens; else by Newton's method in both coordinates); nothing if
  // the ray does not reach the stop.
  std::optional<Vec2d> ChiefAim() const {
    if (film_.y != 0 || !exact_.prescription().RotationallySymmetric() || (exact_.hood() && exact_.hood()->radius == 0))
      return ChiefAimSkew();
    const double r = film_.x;
    auto stop_x = [&](double a) -> std::optional<double> {
      Vec3d o(r, 0, film_z_);
      std::optional<Vec3d> hit =
          StopCrossingFromFilm(exact_, {o, Normalize(Vec3d(a, 0, plane_z_) - o), false, lights_[0].waves}, lights_[0].lambda);
      return hit ? std::optional<double>(hit->x) : std::nullopt;
    };
    double a0 = 0, a1 = 1e-3 * (1 + std::abs(r));
    std::optional<double> f0 = stop_x(a0), f1 = stop_x(a1);
    for (int it = 0; it < 30 && f0 && f1; ++it) {
      if (std::abs(*f1) < 1e-9 || *f1 == *f0) return Vec2d(a1, 0);
      double a2 = a1 - *f1 * (a1 - a0) / (*f1 - *f0);
      a0 = a1, f0 = f1, a1 = a2, f1 = stop_x(a1);
    }
    if (f1 && std::abs(*f1) < 1e-6) return Vec2d(a1, 0);
    return std::nullopt;
  }

  // The chief ray's aim where it need not lie in a plane through the axis: Newton's method on
  // the stop crossing (x, y) as a function of the aim, its Jacobian by finite differences.
  std::optional<Vec2d> ChiefAimSkew() const {
    const Vec3d o(film_.x, film_.y, film_z_);
    auto stop_at = [&](Vec2d a) -> std::optional<Vec2d> {
      std::optional<Vec3d> hit = StopCrossingFromFilm(exact_, {o, Normalize(Vec3d(a.x, a.y, plane_z_) - o), false, lights_[0].waves},
                                                      lights_[0].lambda);
      return hit ? std::optional<Vec2d>(Vec2d(hit->x, hit->y)) : std::nullopt;
    };
    const double h = 1e-4 * (1 + std::hypot(film_.x, film_.y));
    Vec2d a(0, 0);
    for (int it = 0; it < 30; ++it) {
      std::optional<Vec2d> f = stop_at(a), fx = stop_at(a + Vec2d(h, 0)), fy = stop_at(a + Vec2d(0, h));
      if (!f || !fx || !fy) return std::nullopt;
      if (std::hypot(f->x, f->y) < 1e-7) return a;
      const double j11 = (fx->x - f->x) / h, j21 = (fx->y - f->y) / h, j12 = (fy->x - f->x) / h, j22 = (fy->y - f->y) / h;
      const double det = j11 * j22 - j12 * j21;
      if (det == 0 || !std::isfinite(det)) return std::nullopt;
      a = a - Vec2d((j22 * f->x - j12 * f->y) / det, (j11 * f->y - j21 * f->x) / det);
    }
    std::optional<Vec2d> f = stop_at(a);
    if (f && std::hypot(f->x, f->y) < 1e-6) return a;
    return std::nullopt;
  }

  // A point inside the region: the chief ray's aim if it passes, else (`search`) the centroid
  // of the passing probes of a grid over the window |x|, |y| <= half; nothing if none passes.
  std::optional<Vec2d> Inside(double half, bool search = true) const {
    if (std::optional<Vec2d> c = ChiefAim(); c && Passes({*c})[0]) return c;
    if (!search) return std::nullopt;
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
  // precision of 4e-4 (bisection, all directions in one batch per step; tiny regions, such as
  // a pinhole's, take a few more steps). Where `guess` estimates the distances (from the edge
  // points on either side), the bisection starts between 0.9 and 1.1 times the estimate, once
  // a probe at each end confirms it (else from what those probes tell).
  std::vector<double> EdgeDistances(Vec2d c, const std::vector<Vec2d>& dirs, double limit,
                                    const std::vector<double>* guess = nullptr) const {
    std::vector<double> lo(dirs.size(), 0), hi(dirs.size(), limit);
    std::vector<Vec2d> pts(dirs.size());
    if (guess) {
      std::vector<Vec2d> ends;
      for (size_t k = 0; k < dirs.size(); ++k)
        for (double f : {0.9, 1.1}) ends.push_back(c + dirs[k] * std::min(f * (*guess)[k], limit));
      const std::vector<uint8_t> ok = Passes(ends);
      for (size_t k = 0; k < dirs.size(); ++k) {
        const double near = std::min(0.9 * (*guess)[k], limit), far = std::min(1.1 * (*guess)[k], limit);
        if (ok[2 * k]) lo[k] = near;
        else hi[k] = near;
        if (ok[2 * k + 1]) lo[k] = std::max(lo[k], far);
        else hi[k] = std::min(hi[k], far);
        if (lo[k] >= hi[k]) lo[k] = 0, hi[k] = limit;  // not one edge along the line: search it all
      }
    }
    for (int step = 0; step < 60; ++step) {
      bool done = true;
      for (size_t k = 0; k < dirs.size(); ++k) {
        pts[k] = c + dirs[k] * (0.5 * (lo[k] + hi[k]));
        done &= hi[k] - lo[k] <= 4e-4 * hi[k];
      }
      if (done) break;
      std::vector<uint8_t> ok = Passes(pts);
      for (size_t k = 0; k < dirs.size(); ++k) (ok[k] ? lo[k] : hi[k]) = 0.5 * (lo[k] + hi[k]);
    }
    return hi;  // the blocked side: just outside
  }

 private:
  const BatchLensTracer& fast_;
  const LensSystem& exact_;
  Vec2d film_;
  double film_z_, plane_z_;
  std::vector<ProbeLight> lights_;
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
  auto probe_angles = [&](const std::vector<double>& angles, const std::vector<double>* guess) {
    std::vector<Vec2d> dirs;
    for (double a : angles) dirs.push_back({std::cos(a), std::sin(a)});
    std::vector<double> t = probe.EdgeDistances(c, dirs, limit, guess);
    std::vector<EdgePoint> out;
    for (size_t k = 0; k < angles.size(); ++k) out.push_back({angles[k], c + dirs[k] * t[k]});
    return out;
  };
  const int initial = 32;
  std::vector<double> angles;
  for (int k = 0; k < initial; ++k) angles.push_back(2 * M_PI * k / initial);
  std::vector<EdgePoint> edge = probe_angles(angles, nullptr);
  std::vector<uint8_t> pending(edge.size(), 1);  // gap k: between edge[k] and edge[k + 1]
  for (int level = 0; level < 6; ++level) {
    std::vector<double> mids, guess;  // the farther neighbour's distance: the edge's estimate between them
    for (size_t k = 0; k < edge.size(); ++k)
      if (pending[k]) {
        const EdgePoint& next = edge[(k + 1) % edge.size()];
        double a = edge[k].angle, b = k + 1 < edge.size() ? next.angle : next.angle + 2 * M_PI;
        mids.push_back(0.5 * (a + b));
        guess.push_back(std::max(std::hypot(edge[k].p.x - c.x, edge[k].p.y - c.y), std::hypot(next.p.x - c.x, next.p.y - c.y)));
      }
    if (mids.empty()) break;
    std::vector<EdgePoint> found = probe_angles(mids, &guess);
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

}  // namespace

PupilSearch PupilSearchFor(const LensSystem& lens, double plane_z, double lambda_nm) {
  const int last = lens.SurfaceCount() - 1;
  const ParaxialData p = lens.Paraxial(lambda_nm);
  return {std::max(lens.surface(last).semi_diameter, 1.5 * p.exit_pupil_diameter) + std::abs(plane_z - lens.VertexZ(last)),
          1e-3 * std::max(p.exit_pupil_diameter, 1e-9)};
}

PupilRegion TracePupilRegion(const PupilRegionProbe& probe, double r, const std::vector<double>& lambdas,
                             double turn) {
  return TracePupilRegionAt(probe, Vec2d(r, 0), lambdas, turn);
}

PupilRegion TracePupilRegionAt(const PupilRegionProbe& probe, Vec2d film, const std::vector<double>& lambdas,
                               double turn) {
  // Light of every wavelength and, through birefringent crystals, of every combination of their
  // two waves (each crystal is entered once on the way from the film), the first wavelength
  // nearest the middle of the spectrum (the chief ray's, which finds the centre).
  std::vector<ProbeLight> lights;
  const uint32_t combinations = 1u << probe.exact.prescription().CrystalCount();
  std::vector<double> order = lambdas;
  std::stable_sort(order.begin(), order.end(), [](double a, double b) { return std::abs(a - kLambdad) < std::abs(b - kLambdad); });
  for (double lambda : order)
    for (uint32_t waves = 0; waves < combinations; ++waves) lights.push_back({lambda, waves});
  std::vector<Vec2d> points;
  double size = 0;
  auto trace = [&](const RegionProbe& rays, Vec2d centre) {
    for (const Vec2d& q : TraceEdge(rays, centre, 2 * probe.window, probe.tolerance)) {
      size = std::max(size, std::hypot(q.x - centre.x, q.y - centre.y));
      points.push_back(q);
    }
  };
  // All lights at once, from a centre inside each one's region; else each from its own. (The
  // edge refined is then their union's, which finds each light's corners and tips as its own
  // would where the regions have nearly one shape, shifted a little by dispersion or a
  // crystal's walk-off: a tip of one light far narrower than the others' could be missed.)
  const RegionProbe all(probe.fast, probe.exact, film, probe.film_z, probe.plane_z, lights);
  std::optional<Vec2d> centre = all.Inside(probe.window);
  if (centre && probe.recentre) centre = all.Centred(*centre, 2 * probe.window);
  if (centre && (lights.size() == 1 || all.PassesInEveryLight(*centre))) {
    trace(all, *centre);
  } else {
    // Where no light passed the grid (outside the image circle), only the chief rays of the
    // other lights may find a region smaller than its spacing.
    const bool search = centre.has_value();
    for (const ProbeLight& light : lights) {
      const RegionProbe rays(probe.fast, probe.exact, film, probe.film_z, probe.plane_z, {light});
      std::optional<Vec2d> own = rays.Inside(probe.window, search);
      if (!own) continue;
      if (probe.recentre) own = rays.Centred(*own, 2 * probe.window);
      trace(rays, *own);
    }
  }
  if (turn != 0) {
    const double c = std::cos(turn), s = std::sin(turn);
    for (Vec2d& q : points) q = Vec2d(c * q.x - s * q.y, s * q.x + c * q.y);
  }
  PupilRegion region;
  region.hull = ConvexHull(std::move(points));
  region.grow = 2e-3 * size;
  region.area = HullOfGrown({&region.hull}, region.grow).area;
  return region;
}

}  // namespace objektiv
