#include "io/lens_plot.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "optics/paraxial.h"
#include "optics/real_ray_analysis.h"

namespace objektiv {

std::vector<double> DefaultFields(const LensSystem& lens, double lambda_nm) {
  ParaxialData p = lens.Paraxial(lambda_nm);
  double max_field = std::atan(21.63 / std::abs(p.object_index * p.efl)) * 180 / M_PI;
  while (max_field > 0.5 && !RealImageHeight(lens, max_field, lambda_nm)) max_field *= 0.95;
  return {0.0, 0.7 * max_field, max_field};
}

namespace {

// `object_mm`: the distance of the object plane before the entrance pupil (infinity: parallel
// fans, aimed by the chief ray).
Svg Layout(const LensSystem& lens, const std::vector<double>& fields, double lambda_nm, double object_mm) {
  const LensPrescription& rx = lens.prescription();
  const int n = int(rx.surfaces.size());
  ParaxialData p = lens.Paraxial(lambda_nm);
  double max_semi = 0;
  for (const LensSurface& s : rx.surfaces) max_semi = std::max(max_semi, s.semi_diameter);
  // The drawing spans the elements and the image of the largest field on the film.
  double y_extent = 1.3 * max_semi;
  for (double f : fields)
    if (std::optional<double> h = RealImageHeight(lens, f, lambda_nm)) y_extent = std::max(y_extent, 1.1 * std::abs(*h));
  // From a little before the front-most vertex (a Cassegrain's secondary lies before the first).
  double front = 0;
  for (int i = 0; i < n; ++i) front = std::min(front, lens.VertexZ(i));
  const double z_start = front - 0.25 * std::max(lens.FilmZ() - front, 4 * max_semi), z_end = lens.FilmZ();
  const double W = 960, H = 540, margin = 40;
  double scale = std::min((W - 2 * margin) / (z_end - z_start), (H - 2 * margin - 40) / (2 * y_extent));
  auto map = [&](double z, double y) { return Vec2d(margin + (z - z_start) * scale, H / 2 + 10 - y * scale); };
  Svg svg(W, H);
  svg.Text({margin, 24}, fmt::format("{}: EFL {:.2f} mm, f/{:.2f}, {:.1f} nm", rx.name, p.efl, p.fnumber, lambda_nm), 15);

  // Lens-space (z, y) of surface i where the lens's y-z plane cuts it at height y (a placed
  // surface: the point of its own frame under (0, y), carried back; a surface turned about the
  // axis, a toroid's x-z section drawn for `--section x`, then shows its curve).
  auto section = [&](int i, double y) {
    const LensSurface& s = lens.surface(i);
    const Vec3d under = s.placement ? s.placement->ToLocal(Vec3d(0, y, 0) - s.placement->offset) : Vec3d(0, y, 0);
    double sag = 0;
    s.SagAt(under.x, under.y, sag);
    const Vec3d local(under.x, under.y, sag);
    const Vec3d p = lens.FromSurfaceFrame(i, local);
    return Vec2d(p.z, p.y);
  };
  // Elements: the profile of each surface followed by the next one's, where glass lies between.
  auto profile = [&](int i, double from, double to) {
    std::vector<double> heights;
    const int steps = 48;
    for (int k = 0; k <= steps; ++k) heights.push_back(from + (to - from) * k / steps);
    // A Fresnel surface's risers: the profile on both sides of each zone's edge (a sawtooth).
    if (const FresnelZones* zones = lens.surface(i).fresnel.get()) {
      const double lo = std::min(from, to), hi = std::max(from, to), eps = 1e-6 * zones->pitch();
      for (double r = zones->pitch(); r < std::max(-lo, hi); r += zones->pitch())
        for (double y : {r - eps, r + eps, -r - eps, -r + eps})
          if (y > lo && y < hi) heights.push_back(y);
      std::sort(heights.begin(), heights.end());
      if (from > to) std::reverse(heights.begin(), heights.end());
    }
    std::vector<Vec2d> pts;
    for (double y : heights) {
      const Vec2d zy = section(i, y);
      pts.push_back(map(zy.x, zy.y));
    }
    return pts;
  };
  // A stop inside glass (the same medium on both sides) is no face of the element: it spans
  // from the surface before the stop to the one after.
  auto glass_through_stop = [&](int i) {
    return rx.surfaces[i].is_stop && !rx.surfaces[i].mirror && i > 0 && i + 1 < n &&
           rx.surfaces[i].IndexAfter(lambda_nm) == rx.surfaces[i - 1].IndexAfter(lambda_nm);
  };
  for (int i = 0; i + 1 < n; ++i) {
    if (!rx.surfaces[i].medium || glass_through_stop(i)) continue;
    const int j = glass_through_stop(i + 1) ? i + 2 : i + 1;  // the element's back face
    const double semi_i = rx.surfaces[i].semi_diameter, semi_j = rx.surfaces[j].semi_diameter;
    double h = std::max(semi_i, semi_j);
    std::vector<Vec2d> poly = profile(i, -semi_i, semi_i);
    // Flat rims out to the larger of the two apertures, as lens elements are ground.
    poly.push_back(map(section(i, semi_i).x, h));
    poly.push_back(map(section(j, semi_j).x, h));
    std::vector<Vec2d> back = profile(j, semi_j, -semi_j);
    poly.insert(poly.end(), back.begin(), back.end());
    poly.push_back(map(section(j, -semi_j).x, -h));
    poly.push_back(map(section(i, -semi_i).x, -h));
    svg.Polygon(poly, "#cfe3f5", "#2b5d8a", 1.2);
  }
  // Mirrors: their reflecting face, silvered; a central obstruction: a dark bar across it.
  for (int i = 0; i < n; ++i) {
    const LensSurface& s = rx.surfaces[i];
    if (s.mirror) svg.Polyline(profile(i, -s.semi_diameter, s.semi_diameter), "#555", 3.5, 1);
    if (s.obscuration > 0) svg.Polyline(profile(i, -s.obscuration, s.obscuration), "#222", 5, 1);
  }
  // Optical axis, stop, film.
  svg.Line(map(z_start, 0), map(z_end, 0), "#888", 0.8, "6,4");
  int stop = rx.StopIndex();
  if (stop >= 0) {
    double r = lens.StopSemiDiameter(), outer = std::max(r * 1.25, r + 0.08 * max_semi);
    const Vec2d a = section(stop, r), b = section(stop, outer), c = section(stop, -r), d = section(stop, -outer);
    svg.Line(map(a.x, a.y), map(b.x, b.y), "#000", 3);
    svg.Line(map(c.x, c.y), map(d.x, d.y), "#000", 3);
  }
  svg.Line(map(z_end, -y_extent), map(z_end, y_extent), "#444", 2);
  svg.Text(map(z_end, -y_extent) + Vec2d(0, 16), "film", 11, "middle");

  // Ray fans.
  const bool crystals = rx.CrystalCount() > 0;
  const char* colours[] = {"#1f5fd1", "#1a9e3a", "#d12f1f", "#a31fd1", "#d18a1f"};
  for (size_t f = 0; f < fields.size(); ++f) {
    double theta = fields[f] * M_PI / 180;
    std::optional<LensRay> chief;
    if (!std::isfinite(object_mm)) {
      chief = ChiefRay(lens, fields[f], lambda_nm);
      if (!chief) continue;
    }
    const double z_pupil = lens.VertexZ(0) + p.entrance_pupil_position;
    const Vec3d object(0, -object_mm * std::tan(theta), z_pupil - object_mm);
    for (double frac : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
      LensRay r;
      if (chief) {
        // Across the entrance pupil, perpendicular to the beam, measured at the chief ray's start.
        const Vec3d dir(0, std::sin(theta), std::cos(theta));
        r = LensRay{{0, chief->o.y + 0.98 * frac * p.entrance_pupil_diameter / 2 / std::cos(theta), chief->o.z}, dir};
      } else {
        // From the object point to a point across the paraxial entrance pupil.
        r = LensRay{object, Normalize(Vec3d(0, 0.98 * frac * p.entrance_pupil_diameter / 2, z_pupil) - object)};
      }
      // Begin the drawn ray at the left edge of the plot (or at the object, if nearer).
      const double back = (r.o.z - z_start) / r.d.z;
      if (back > 0) r.o = r.o - r.d * back;
      // Through birefringent crystals, the ordinary waves' rays and, dashed, the extraordinary ones'.
      for (int pass = 0; pass < (crystals ? 2 : 1); ++pass) {
        const uint32_t waves = pass ? ~0u : 0u;
        r.wave_choices = waves;
        std::vector<Vec3d> path;  // curved through a gradient-index medium
        TraceResult t = TraceFromObject(lens, r, lambda_nm, nullptr, nullptr, &path);
        std::vector<Vec2d> pts = {map(r.o.z, r.o.y)};
        for (const Vec3d& q : path) pts.push_back(map(q.z, q.y));
        if (t.ray && t.ray->d.z > 0) {
          double s = (z_end - t.ray->o.z) / t.ray->d.z;
          pts.push_back(map(z_end, t.ray->o.y + t.ray->d.y * s));
        }
        svg.Polyline(pts, colours[f % 5], 0.9, 0.85, waves ? "4,3" : "");
      }
    }
    svg.Text({W - margin, 24.0 + 16 * (f + 1)}, fmt::format("field {:.1f} deg", fields[f]), 12, "end", colours[f % 5]);
  }
  if (crystals)
    svg.Text({W - margin, 24.0 + 16 * (fields.size() + 1)}, "dashed: the crystals' extraordinary waves", 12, "end");
  if (std::isfinite(object_mm))
    svg.Text({W - margin, 24.0 + 16 * (fields.size() + 1 + crystals)},
             fmt::format("from {:.3g} m before the entrance pupil (paraxially conjugate to the film)", object_mm * 1e-3),
             12, "end");
  return svg;
}

}  // namespace

Svg PlotLensLayout(const LensSystem& lens, const std::vector<double>& fields, double lambda_nm) {
  return Layout(lens, fields, lambda_nm, INFINITY);
}

Svg PlotLensLayoutAsFocused(const LensSystem& lens, const std::vector<double>& fields, double lambda_nm) {
  const ParaxialData p = lens.Paraxial(lambda_nm);
  const double beyond_focus = lens.BackFocus() - p.bfl;  // x': the film beyond the back focal point
  double object = INFINITY;
  if (beyond_focus > 1e-9 * std::abs(p.efl)) {
    // x = -n0 f^2 / x' from the front focal point; the distance from the entrance pupil.
    const double x = -p.object_index * p.efl * p.efl / beyond_focus;
    const double z_object = lens.VertexZ(0) + p.ffl + x, z_pupil = lens.VertexZ(0) + p.entrance_pupil_position;
    if (z_pupil - z_object > 0) object = z_pupil - z_object;
  }
  return Layout(lens, fields, lambda_nm, object);
}

}  // namespace objektiv
