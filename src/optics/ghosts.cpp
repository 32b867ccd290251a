#include "optics/ghosts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "optics/colour_lattice.h"
#include "optics/compiled_sequence.h"

namespace objektiv {

std::vector<int> ReflectingSurfaces(const LensSystem& lens) {
  // At the d line: a change anywhere is a change there.
  std::vector<int> reflecting;
  for (int i = 0; i < lens.SurfaceCount(); ++i) {
    const double before = lens.prescription().IndexBefore(size_t(i), kLambdad);
    if (before != lens.surface(i).IndexAfter(kLambdad)) reflecting.push_back(i);
  }
  return reflecting;
}

std::vector<Ghost> TwoReflectionGhosts(const LensSystem& lens) {
  const std::vector<int> reflecting = ReflectingSurfaces(lens);
  std::vector<Ghost> ghosts;
  for (size_t a = 0; a < reflecting.size(); ++a)
    for (size_t b = 0; b < a; ++b) ghosts.push_back({reflecting[a], reflecting[b]});
  return ghosts;
}

std::vector<SurfaceVisit> GhostPath(const LensSystem& lens, const Ghost& g) {
  std::vector<SurfaceVisit> path;
  for (int i = 0; i <= g.first; ++i) path.push_back({i, i == g.first, true});
  for (int i = g.first - 1; i >= g.second; --i) path.push_back({i, i == g.second, false});
  for (int i = g.second + 1; i < lens.SurfaceCount(); ++i) path.push_back({i, false, true});
  return path;
}

namespace {

// A grid of rays from the source through points of a square on a plane in front of the lens,
// traced along `path` to the film.
class BundleTracer {
 public:
  // `geometry_only`: for where the rays go alone (Region), without their losses.
  BundleTracer(const LensSystem& lens, std::span<const SurfaceVisit> path, const PointSource& source, double lambda_nm,
               const BundleOptions& options = {}, bool geometry_only = false)
      : lens_(lens), path_(path), source_(source), options_(options), lambda_(lambda_nm), geometry_only_(geometry_only),
        // With a spectrum, the rays' geometry alone; their losses at the lattice's nodes.
        compiled_(CompiledSequence::Compile(lens, path, lambda_nm, {}, nullptr, !geometry_only && !options.spectrum)) {
    if (options.spectrum && !geometry_only) {
      spectral_ = CompiledSequence::Compile(lens, path, lambda_nm, options.spectrum->wavelengths, options.coating_tables);
      for (const Vec3d& w : options.spectrum->weights) weight_sum_ += w.x + w.y + w.z;
    }
    for (const SurfaceVisit& v : path)
      if (const SurfaceDirt* dirt = lens.surface(v.surface).dirt.get()) mean_dirt_ *= dirt->MeanTransmittance();
    const LensSurface& front = lens.surface(0);
    // The rim's depth (a toroid's differs along x and y: the deeper one).
    double sag_x = 0, sag_y = 0;
    front.SagAt(front.semi_diameter, 0, sag_x);
    front.SagAt(0, front.semi_diameter, sag_y);
    const double rim_z = lens.VertexZ(0) + (std::abs(sag_x) > std::abs(sag_y) ? sag_x : sag_y);
    start_z_ = std::min(lens.VertexZ(0), rim_z) - 1;
    // Oblique light reaches the front element displaced sideways from where it crosses the
    // start plane: the square is centred where the light toward the element's middle depth
    // crosses it, and widened by the displacement over the element's depth (a fisheye's deep
    // front element at 60 degrees was missed entirely).
    const Vec3d d = source.at_infinity ? source.direction : Normalize(Vec3d(0, 0, lens.VertexZ(0)) - source.position);
    const double slope_x = d.z > 0 ? d.x / d.z : 0, slope_y = d.z > 0 ? d.y / d.z : 0;
    const double middle = 0.5 * (lens.VertexZ(0) + rim_z) - start_z_, depth = std::abs(rim_z - lens.VertexZ(0)) + 1;
    // A decentred front element: the square follows it (a tilted one reaches a little further).
    const Vec3d off = front.placement ? front.placement->offset : Vec3d(0, 0, 0);
    const double tilt = front.placement ? std::sqrt(std::max(0.0, 1 - front.placement->ez.z * front.placement->ez.z)) : 0;
    centre_ = Vec2d(off.x - slope_x * middle, off.y - slope_y * middle);
    reach_ = front.semi_diameter * (1 + tilt) + 0.5 * depth * std::max(std::abs(slope_x), std::abs(slope_y));
  }

  struct Corner {
    bool alive = false;
    Vec2d film;
    double transmittance = 0;  // with a spectrum: of its colour (Colour)
    Vec3d colour{0.0};         // with a spectrum: the colour it carries
    double clear = 1;          // the share dust and the aperture mask leave
    // A blocked corner's ray followed past the openings (a compiled path): where it would meet
    // the film.
    bool placed = false;
    Vec2d placed_film;
  };

  // `place`: a blocked corner is followed past the openings (Corner::placed), where an edge
  // cell needs it.
  Corner Trace(Vec2d p, bool place = false) const {
    const Vec3d at(p.x, p.y, start_z_);
    const Vec3d d = source_.at_infinity ? source_.direction : Normalize(at - source_.position);
    Corner c;
    if (!(d.z > 0)) return c;
    thread_local std::vector<Vec3d> points;
    points.clear();
    const bool masked = bool(options_.stop_transmittance);
    // Where the ray crossed the stop (each time: a ghost's path may cross it three times).
    thread_local std::vector<Vec3d> stop_points;
    stop_points.clear();
    std::optional<LensRay> out;
    double transmittance = 1;
    if (compiled_) {
      const CompiledSequence::Result r = compiled_->Trace({at, d}, masked ? &stop_points : nullptr, place && !geometry_only_);
      if (r.alive) out = r.ray;
      if (r.followed && r.ray.d.z > 0) {
        c.placed_film = OnFilm(r.ray);
        c.placed = std::isfinite(c.placed_film.x) && std::isfinite(c.placed_film.y);
      }
      transmittance = r.surface_transmittance * r.internal_transmittance;
    } else {
      const TraceResult r = TraceSequence(lens_, {at, d}, lambda_, path_, masked ? &points : nullptr);
      out = r.ray;  // (r.dirt, the corner's own, gives way to mean_dirt_)
      transmittance = r.surface_transmittance * r.internal_transmittance;
      for (size_t k = 0; k < points.size() && k < path_.size(); ++k)
        if (path_[k].surface == lens_.StopIndex()) stop_points.push_back(points[k]);
    }
    if (!out || !(out->d.z > 0)) return c;
    c.alive = true;
    c.film = OnFilm(*out);
    // Dust and scratches by the share of each surface they leave clear: the grid's cells are
    // far coarser than the particles, which a corner ray would take for whole cells.
    double clear = mean_dirt_;
    if (masked) {
      const double inv = 1 / lens_.StopSemiDiameter();
      for (const Vec3d& p : stop_points) clear *= options_.stop_transmittance(p.x * inv, p.y * inv);
    }
    c.clear = clear;
    if (!options_.spectrum) {
      c.transmittance = (options_.lossless ? 1.0 : transmittance) * clear;
    } else if (!lattice_.empty()) {
      Colour(c, p);
    }
    return c;
  }

  // With a spectrum: a live corner at start point p takes its colour from the lattice.
  void Colour(Corner& c, Vec2d p) const {
    c.colour = lattice_.At(p) * c.clear;
    c.transmittance = weight_sum_ > 0 ? (c.colour.x + c.colour.y + c.colour.z) / weight_sum_ : 0;
  }

  // With a spectrum: the colour of the ray from start point p, its losses at each of the
  // spectrum's wavelengths (followed past the openings where the path is compiled: a node
  // outside the light still says what its colour is there); none where it misses a surface or
  // is reflected totally.
  std::optional<Vec3d> NodeColour(Vec2d p) const {
    const BundleSpectrum& spectrum = *options_.spectrum;
    const Vec3d at(p.x, p.y, start_z_);
    const Vec3d d = source_.at_infinity ? source_.direction : Normalize(at - source_.position);
    if (!(d.z > 0)) return std::nullopt;
    std::array<double, CompiledSequence::kMaxBands> t{};
    if (spectral_) {
      const CompiledSequence::Result r =
          spectral_->Trace({at, d}, nullptr, /*follow_blocked=*/true, std::span(t.data(), size_t(spectral_->band_count())));
      if (!r.alive && !r.followed) return std::nullopt;
    } else {
      for (size_t k = 0; k < spectrum.wavelengths.size(); ++k) {
        const TraceResult r = TraceSequence(lens_, {at, d}, spectrum.wavelengths[k], path_);
        if (!r.ray) return std::nullopt;
        t[k] = r.surface_transmittance * r.internal_transmittance;
      }
    }
    Vec3d colour(0.0);
    for (size_t k = 0; k < spectrum.weights.size(); ++k) colour += spectrum.weights[k] * t[k];
    return colour;
  }

  // With a spectrum: the lattice over the grid [lo, hi] of `grid` cells a side, then the
  // colours of its live corners (row by row).
  void ColourGrid(Vec2d lo, Vec2d hi, int grid, std::vector<Corner>& corners) {
    const BundleSpectrum& spectrum = *options_.spectrum;
    if (options_.lossless) {
      Vec3d sum(0.0);
      for (const Vec3d& w : spectrum.weights) sum += w;
      lattice_ = ColourLattice::Uniform(sum);
    } else {
      const int cells = std::max(1, spectrum.lattice_cells);
      lattice_ = ColourLattice(lo, hi, (grid + cells - 1) / cells + 1, [this](Vec2d p) { return NodeColour(p); });
    }
    const int w = grid + 1;
    auto at = [&](size_t k) {
      return Vec2d(lo.x + (hi.x - lo.x) * double(k % size_t(w)) / grid, lo.y + (hi.y - lo.y) * double(k / size_t(w)) / grid);
    };
    // No node's ray found a colour (a path that barely gets through): a live corner's, everywhere.
    for (size_t k = 0; k < corners.size() && lattice_.empty(); ++k)
      if (corners[k].alive)
        if (const std::optional<Vec3d> c = NodeColour(at(k))) lattice_ = ColourLattice::Uniform(*c);
    if (lattice_.empty()) lattice_ = ColourLattice::Uniform(Vec3d(0.0));
    for (size_t k = 0; k < corners.size(); ++k)
      if (corners[k].alive) Colour(corners[k], at(k));
  }

  // Where a ray leaving the lens toward the film (d.z > 0) meets the film plane.
  Vec2d OnFilm(const LensRay& ray) const {
    const double t = (lens_.FilmZ() - ray.o.z) / ray.d.z;
    return {ray.o.x + t * ray.d.x, ray.o.y + t * ray.d.y};
  }

  // The flux into the cell of size du x dv centred at p, per unit intensity (or irradiance).
  double CellFlux(Vec2d p, double du, double dv) const {
    if (source_.at_infinity) return du * dv * source_.direction.z;
    const Vec3d to = Vec3d(p.x, p.y, start_z_) - source_.position;
    const double r2 = Dot(to, to);
    return du * dv * std::abs(to.z) / (r2 * std::sqrt(r2));
  }

  // The part of the start square [-reach, reach]^2 whose rays get through: found on a coarse
  // grid of `coarse` cells a side, widened by one coarse step. Empty: none do. A grid of 32 has
  // a step finer than a quarter of the entrance pupil unless the stop is small; then a finer
  // grid, with the step a quarter of the pupil's diameter, makes sure (the light of any path
  // crosses the stop). A coarser grid than 32 (a preview's) is followed by a second one of the
  // same size over what the first found, which narrows the region to its finer step.
  bool Region(Vec2d& lo, Vec2d& hi, int coarse = 32) const {
    const double pupil = lens_.paraxial().entrance_pupil_diameter;
    const int fine = pupil > 0 ? int(std::clamp(std::ceil(8 * reach_ / pupil), 32.0, 256.0)) : 256;
    const Vec2d square = centre_ - Vec2d(reach_, reach_);
    for (int n : {coarse, fine}) {
      if (!Search(square, Vec2d(2 * reach_, 2 * reach_), n, lo, hi)) {
        if (fine == n) break;  // the coarse grid was fine enough
        continue;
      }
      if (n < 32) {
        const Vec2d first_lo = lo, first_hi = hi;
        if (!Search(first_lo, first_hi - first_lo, n, lo, hi)) lo = first_lo, hi = first_hi;
      }
      return true;
    }
    return false;
  }

  // The rays of an (n + 1) x (n + 1) grid over the rectangle from `from` of `size` that get
  // through: their bounds, widened by one step within the rectangle. False: none does.
  bool Search(Vec2d from, Vec2d size, int n, Vec2d& lo, Vec2d& hi) const {
    const Vec2d step(size.x / n, size.y / n), to(from.x + size.x, from.y + size.y);
    lo = Vec2d(INFINITY, INFINITY), hi = Vec2d(-INFINITY, -INFINITY);
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const Vec2d p(from.x + i * step.x, from.y + j * step.y);
        if (!Trace(p).alive) continue;
        lo = Vec2d(std::min(lo.x, p.x), std::min(lo.y, p.y));
        hi = Vec2d(std::max(hi.x, p.x), std::max(hi.y, p.y));
      }
    if (!(lo.x <= hi.x)) return false;
    lo = Vec2d(std::max(from.x, lo.x - step.x), std::max(from.y, lo.y - step.y));
    hi = Vec2d(std::min(to.x, hi.x + step.x), std::min(to.y, hi.y + step.y));
    return true;
  }

  std::vector<FilmTriangle> Bundle(int grid, const BundleRegion* region) {
    std::vector<FilmTriangle> out;
    Vec2d lo, hi;
    if (region) {
      lo = region->lo, hi = region->hi;
    } else if (!Region(lo, hi)) {
      return out;
    }
    if (grid < 1) return out;
    const double du = (hi.x - lo.x) / grid, dv = (hi.y - lo.y) / grid;
    std::vector<Corner> corners(size_t(grid + 1) * (grid + 1));
    for (int j = 0; j <= grid; ++j)
      for (int i = 0; i <= grid; ++i) corners[size_t(j) * (grid + 1) + i] = Trace(Vec2d(lo.x + i * du, lo.y + j * dv));
    if (options_.spectrum && !geometry_only_) ColourGrid(lo, hi, grid, corners);
    // The blocked corners of the cells the opening's edge crosses, followed past it (traced
    // again: most blocked corners lie away from the edge, where following them costs rays).
    const int w = grid + 1;
    for (int j = 0; j < grid; ++j)
      for (int i = 0; i < grid; ++i) {
        const size_t at[4] = {size_t(j) * w + i, size_t(j) * w + i + 1, size_t(j + 1) * w + i + 1, size_t(j + 1) * w + i};
        const int alive = corners[at[0]].alive + corners[at[1]].alive + corners[at[2]].alive + corners[at[3]].alive;
        if (alive == 0 || alive == 4) continue;
        for (const size_t k : at)
          if (!corners[k].alive && !corners[k].placed)
            corners[k] = Trace(Vec2d(lo.x + double(k % w) * du, lo.y + double(k / w) * dv), /*place=*/true);
      }
    // The irradiance at each grid corner: the mean over the whole cells around it of their
    // flux over their area on the film (the triangles' corners take it: see FilmTriangle).
    std::vector<double> cell_e(size_t(grid) * grid, -1);
    for (int j = 0; j < grid; ++j)
      for (int i = 0; i < grid; ++i) {
        const Corner* c = &corners[size_t(j) * w + i];
        if (!(c[0].alive && c[1].alive && c[w + 1].alive && c[w].alive)) continue;
        const double area = FilmTriangle{c[0].film, c[1].film, c[w + 1].film, 0}.Area() +
                            FilmTriangle{c[0].film, c[w + 1].film, c[w].film, 0}.Area();
        const double t = 0.25 * (c[0].transmittance + c[1].transmittance + c[w + 1].transmittance + c[w].transmittance);
        if (area > 0) cell_e[size_t(j) * grid + i] = t * CellFlux(Vec2d(lo.x + (i + 0.5) * du, lo.y + (j + 0.5) * dv), du, dv) / area;
      }
    std::vector<double> corner_e(size_t(w) * w, 0);
    for (int j = 0; j <= grid; ++j)
      for (int i = 0; i <= grid; ++i) {
        double sum = 0;
        int n = 0;
        for (int dj = -1; dj <= 0; ++dj)
          for (int di = -1; di <= 0; ++di) {
            const int ci = i + di, cj = j + dj;
            if (ci < 0 || cj < 0 || ci >= grid || cj >= grid) continue;
            const double e = cell_e[size_t(cj) * grid + ci];
            if (e >= 0) sum += e, ++n;
          }
        corner_e[size_t(j) * w + i] = n ? sum / n : 0;
      }
    for (int j = 0; j < grid; ++j)
      for (int i = 0; i < grid; ++i) {
        const Corner* c = &corners[size_t(j) * w + i];
        const double* e = &corner_e[size_t(j) * w + i];
        const std::array<double, 4> ce = {e[0], e[1], e[w + 1], e[w]};
        Cell(Vec2d(lo.x + i * du, lo.y + j * dv), du, dv, {c[0], c[1], c[w + 1], c[w]}, options_.edge_levels, out,
             cell_e[size_t(j) * grid + i] > 0 ? &ce : nullptr);
      }
    return out;
  }

 private:
  // A cell whose corners (counter-clockwise from its low corner) all get through becomes two
  // triangles on the film; one where only some do lies across the edge of what gets through
  // (a rim, the stop's blades): it is split in four, down to BundleOptions::edge_levels
  // levels, so that the bundle's edge follows the opening.
  // `e`: the irradiance at the corners of a whole cell of the grid (a smooth picture); none:
  // uniform over each triangle.
  void Cell(Vec2d p, double du, double dv, const std::array<Corner, 4>& c, int depth, std::vector<FilmTriangle>& out,
            const std::array<double, 4>* e = nullptr) const {
    const int alive = c[0].alive + c[1].alive + c[2].alive + c[3].alive;
    if (alive == 4) {
      const double t = 0.25 * (c[0].transmittance + c[1].transmittance + c[2].transmittance + c[3].transmittance);
      const double flux = t * CellFlux(Vec2d(p.x + du / 2, p.y + dv / 2), du, dv);
      // The cell's flux split between its triangles by their area (their irradiance the same).
      FilmTriangle t1{c[0].film, c[1].film, c[2].film, 0}, t2{c[0].film, c[2].film, c[3].film, 0};
      t1.tint = t2.tint = Tint(c.data(), 4, t);
      const double a1 = t1.Area(), a2 = t2.Area();
      const double share = a1 + a2 > 0 ? a1 / (a1 + a2) : 0.5;
      t1.flux = flux * share, t2.flux = flux * (1 - share);
      if (e && (*e)[0] > 0 && (*e)[1] > 0 && (*e)[2] > 0 && (*e)[3] > 0) {
        t1.ea = (*e)[0], t1.eb = (*e)[1], t1.ec = (*e)[2];
        t2.ea = (*e)[0], t2.eb = (*e)[2], t2.ec = (*e)[3];
      }
      out.push_back(t1);
      out.push_back(t2);
      return;
    }
    if (alive == 0) return;
    if (depth == 0) {
      EdgeCell(p, du, dv, c, alive, out);
      return;
    }
    const double hu = du / 2, hv = dv / 2;
    // The 3 x 3 corners of the four halves (the old ones at the corners).
    Corner g[3][3];
    g[0][0] = c[0], g[0][2] = c[1], g[2][2] = c[2], g[2][0] = c[3];
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        if ((i % 2) || (j % 2)) g[j][i] = Trace(Vec2d(p.x + i * hu, p.y + j * hv), /*place=*/true);
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        Cell(Vec2d(p.x + i * hu, p.y + j * hv), hu, hv, {g[j][i], g[j][i + 1], g[j + 1][i + 1], g[j + 1][i]}, depth - 1, out);
  }

  // A cell at the finest level that the opening's edge crosses: left out, such cells would
  // lose a strip of half a cell along the whole outline (0.8% of the light at grid 32). The
  // part inside is estimated as a straight edge crossing the cell leaves it: one corner
  // inside, an eighth of the cell; two neighbours, half; three, seven eighths (two opposite
  // corners: a quarter). Its flux lands on the live corners' triangle (or segment, or point:
  // a finest cell lands within a fraction of a pixel).
  // Where the blocked corners' rays can be followed past the openings (a compiled path), the
  // part lands where that straight edge puts it: the live corners and the midpoints of the
  // cell's sides that the edge crosses, placed on the film by the corners' film points (a
  // preview's finest cells, half a cell of a 16 x 16 grid, span pixels: as a point or a
  // segment their light made a bright dot each along every ghost's outline).
  void EdgeCell(Vec2d p, double du, double dv, const std::array<Corner, 4>& c, int alive,
                std::vector<FilmTriangle>& out) const {
    Vec2d live[4];
    Corner alive_corners[4];
    double t = 0;
    int n = 0;
    for (const Corner& k : c)
      if (k.alive) alive_corners[n] = k, live[n++] = k.film, t += k.transmittance;
    const bool opposite = alive == 2 && c[0].alive == c[2].alive;
    const double fraction = alive == 1 ? 0.125 : alive == 3 ? 0.875 : opposite ? 0.25 : 0.5;
    const double flux = (t / alive) * fraction * CellFlux(Vec2d(p.x + du / 2, p.y + dv / 2), du, dv);
    const Vec3d tint = Tint(alive_corners, n, t / alive);
    // The corners' film points, the blocked ones' past the openings.
    std::array<Vec2d, 4> film;
    bool placed = true;
    for (size_t k = 0; k < 4; ++k) {
      film[k] = c[k].alive ? c[k].film : c[k].placed_film;
      placed &= c[k].alive || c[k].placed;
    }
    // Else (or where the outline has no area): on the live corners' triangle, segment or point.
    auto on_live_corners = [&] {
      FilmTriangle tri{live[0], live[std::min(1, n - 1)], live[std::min(2, n - 1)], flux};
      tri.tint = tint;
      out.push_back(tri);
    };
    if (!placed) return on_live_corners();
    // The lit part's outline: live corners, and the midpoints of the sides between a live
    // and a blocked corner (two opposite live corners: a triangle at each).
    // At most two parts of up to five points, fanned into at most three triangles.
    Vec2d parts[2][5];
    int sizes[2] = {0, 0}, part_count = 0;
    auto middle = [&](int k, int l) { return (film[size_t(k)] + film[size_t(l)]) * 0.5; };
    if (opposite) {
      for (int k = 0; k < 4; ++k)
        if (c[size_t(k)].alive) {
          Vec2d* part = parts[part_count];
          part[0] = film[size_t(k)], part[1] = middle(k, (k + 1) % 4), part[2] = middle(k, (k + 3) % 4);
          sizes[part_count++] = 3;
        }
    } else {
      part_count = 1;
      for (int k = 0; k < 4; ++k) {
        const int next = (k + 1) % 4;
        if (c[size_t(k)].alive) parts[0][sizes[0]++] = film[size_t(k)];
        if (c[size_t(k)].alive != c[size_t(next)].alive) parts[0][sizes[0]++] = middle(k, next);
      }
    }
    // A fan of triangles from each part's first point, the flux by their area.
    FilmTriangle triangles[3];
    double areas[3], area = 0;
    int count = 0;
    for (int q = 0; q < part_count; ++q)
      for (int k = 1; k + 1 < sizes[q]; ++k) {
        triangles[count] = FilmTriangle{parts[q][0], parts[q][k], parts[q][k + 1], 0};
        triangles[count].tint = tint;
        area += areas[count] = triangles[count].Area();
        ++count;
      }
    if (!(area > 0)) return on_live_corners();
    for (int k = 0; k < count; ++k) {
      triangles[k].flux = flux * areas[k] / area;
      out.push_back(triangles[k]);
    }
  }

  // With a spectrum: the mean of `n` corners' colours over `mean`, their mean transmittance
  // (FilmTriangle::tint: the colour per unit flux); without, white.
  Vec3d Tint(const Corner* corners, int n, double mean) const {
    if (!options_.spectrum || !(mean > 0)) return Vec3d(1, 1, 1);
    Vec3d sum(0.0);
    for (int k = 0; k < n; ++k) sum += corners[k].colour;
    return sum * (1 / (n * mean));
  }

  const LensSystem& lens_;
  std::span<const SurfaceVisit> path_;
  double mean_dirt_ = 1;  // the product of the visited surfaces' clear shares
  PointSource source_;
  BundleOptions options_;
  double lambda_;
  bool geometry_only_;
  double start_z_, reach_;
  Vec2d centre_{0, 0};  // of the start square
  std::optional<CompiledSequence> compiled_;  // the path at lambda_, where it can be compiled
  // With a spectrum: the path with its losses at the spectrum's wavelengths, the sum of the
  // weights' X, Y and Z (a colour's transmittance is its sum over this), the lattice.
  std::optional<CompiledSequence> spectral_;
  double weight_sum_ = 0;
  ColourLattice lattice_;
};

}  // namespace

namespace {

void CheckSpectrum(const BundleOptions& options, const char* who) {
  if (const BundleSpectrum* s = options.spectrum)
    if (s->wavelengths.size() > size_t(CompiledSequence::kMaxBands) || s->weights.size() != s->wavelengths.size())
      throw std::invalid_argument(std::string(who) + ": a spectrum of more than " +
                                  std::to_string(CompiledSequence::kMaxBands) + " wavelengths, or not one weight each");
}

std::vector<SurfaceVisit> DirectPath(const LensSystem& lens) {
  std::vector<SurfaceVisit> path;
  for (int i = 0; i < lens.SurfaceCount(); ++i) path.push_back({i, false, true});
  return path;
}

std::optional<BundleRegion> FindRegion(const LensSystem& lens, std::span<const SurfaceVisit> path,
                                       const PointSource& source, double lambda_nm, int search_grid) {
  BundleRegion r;
  if (!BundleTracer(lens, path, source, lambda_nm, {}, /*geometry_only=*/true).Region(r.lo, r.hi, search_grid)) return std::nullopt;
  // Other wavelengths' light gets through a region a little moved (the pupils' chromatic
  // shift, far less than the search's step, which the region is already widened by): 2% more.
  const Vec2d margin = (r.hi - r.lo) * 0.02;
  r.lo = r.lo - margin, r.hi = r.hi + margin;
  return r;
}

}  // namespace

std::optional<BundleRegion> GhostRegion(const LensSystem& lens, const Ghost& ghost, const PointSource& source,
                                        double lambda_nm, int search_grid) {
  return FindRegion(lens, GhostPath(lens, ghost), source, lambda_nm, search_grid);
}

std::optional<BundleRegion> DirectRegion(const LensSystem& lens, const PointSource& source, double lambda_nm,
                                         int search_grid) {
  return FindRegion(lens, DirectPath(lens), source, lambda_nm, search_grid);
}

std::vector<FilmTriangle> GhostBundle(const LensSystem& lens, const Ghost& ghost, const PointSource& source,
                                      double lambda_nm, const BundleOptions& options) {
  CheckSpectrum(options, "GhostBundle");
  const std::vector<SurfaceVisit> path = GhostPath(lens, ghost);
  return BundleTracer(lens, path, source, lambda_nm, options).Bundle(options.grid, options.region);
}

std::vector<FilmTriangle> GhostBundle(const LensSystem& lens, const Ghost& ghost, const PointSource& source,
                                      double lambda_nm, int grid, const BundleRegion* region) {
  BundleOptions options;
  options.grid = grid, options.region = region;
  return GhostBundle(lens, ghost, source, lambda_nm, options);
}

std::vector<FilmTriangle> DirectBundle(const LensSystem& lens, const PointSource& source, double lambda_nm,
                                       const BundleOptions& options) {
  CheckSpectrum(options, "DirectBundle");
  const std::vector<SurfaceVisit> path = DirectPath(lens);
  return BundleTracer(lens, path, source, lambda_nm, options).Bundle(options.grid, options.region);
}

std::vector<FilmTriangle> DirectBundle(const LensSystem& lens, const PointSource& source, double lambda_nm, int grid,
                                       const BundleRegion* region) {
  BundleOptions options;
  options.grid = grid, options.region = region;
  return DirectBundle(lens, source, lambda_nm, options);
}

double FrontElementFlux(const LensSystem& lens, const PointSource& source) {
  const double s = lens.surface(0).semi_diameter, area = M_PI * s * s;
  if (source.at_infinity) return area * source.direction.z;
  const Vec3d to = Vec3d(0, 0, lens.VertexZ(0)) - source.position;
  const double r2 = Dot(to, to);
  return area * std::abs(to.z) / (r2 * std::sqrt(r2));
}

}  // namespace objektiv
