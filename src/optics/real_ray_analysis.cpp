#include "optics/real_ray_analysis.h"

#include <algorithm>
#include <cmath>

#include "optics/anamorphic.h"
#include "optics/paraxial.h"

namespace objektiv {

namespace {
constexpr double kStartZ = -50;  // rays start this far in front of the first vertex (mm)

// The same lens with every aperture opened (semi-diameters and stop unbounded): chief rays and
// image heights are geometric, whatever the rims do to the rest of the beam.
LensSystem Unclipped(const LensSystem& lens, int last_surface) {
  LensPrescription open = lens.prescription();
  open.surfaces.resize(size_t(last_surface) + 1);
  for (LensSurface& s : open.surfaces) s.semi_diameter = 1e30, s.obscuration = 0;
  LensSystem t(open);
  t.SetStopSemiDiameter(1e30);
  return t;
}

// Height at which a ray from direction theta, entering at height y0 (at kStartZ), crosses the
// stop plane; nothing if it does not get there.
std::optional<double> HeightAtStop(const LensSystem& front, double theta, double y0, double lambda_nm) {
  LensRay r{{0, y0, kStartZ}, {0, std::sin(theta), std::cos(theta)}};
  TraceResult t = TraceFromObject(front, r, lambda_nm);
  if (!t.ray) return std::nullopt;
  return t.ray->o.y;
}
}  // namespace

std::optional<LensRay> ChiefRay(const LensSystem& lens, double field_deg, double lambda_nm) {
  double theta = field_deg * M_PI / 180;
  LensSystem front = Unclipped(lens, lens.prescription().StopIndex());
  auto make = [&](double y) { return LensRay{{0, y, kStartZ}, {0, std::sin(theta), std::cos(theta)}}; };
  // Secant iteration from the paraxial entrance pupil.
  ParaxialData p = lens.Paraxial(lambda_nm);
  double y_a = -std::tan(theta) * (p.entrance_pupil_position - kStartZ), y_b = y_a + 1e-3;
  std::optional<double> h_a = HeightAtStop(front, theta, y_a, lambda_nm), h_b = HeightAtStop(front, theta, y_b, lambda_nm);
  for (int it = 0; it < 60 && h_a && h_b && *h_b != *h_a; ++it) {
    if (std::abs(*h_b) < 1e-12) return make(y_b);
    double y_c = y_b - *h_b * (y_b - y_a) / (*h_b - *h_a);
    y_a = y_b, h_a = h_b, y_b = y_c;
    h_b = HeightAtStop(front, theta, y_b, lambda_nm);
  }
  if (h_b && std::abs(*h_b) < 1e-9) return make(y_b);
  // Far off axis the pupil moves and the secant can leave the lens: bracket a sign change by
  // scanning entrance heights, then bisect.
  double guess = -std::tan(theta) * (p.entrance_pupil_position - kStartZ);
  double span = 4 * lens.prescription().surfaces.front().semi_diameter / std::max(std::cos(theta), 0.05) + 1;
  const int steps = 400;
  std::optional<double> prev_h;
  double prev_y = 0;
  for (int i = 0; i <= steps; ++i) {
    double y = guess - span + 2 * span * i / steps;
    std::optional<double> h = HeightAtStop(front, theta, y, lambda_nm);
    if (h && prev_h && (*h > 0) != (*prev_h > 0)) {
      double lo = prev_y, hi = y, h_lo = *prev_h;
      for (int it = 0; it < 100; ++it) {
        double mid = 0.5 * (lo + hi);
        std::optional<double> hm = HeightAtStop(front, theta, mid, lambda_nm);
        if (!hm) break;
        if ((*hm > 0) == (h_lo > 0)) lo = mid, h_lo = *hm;
        else hi = mid;
      }
      std::optional<double> hf = HeightAtStop(front, theta, 0.5 * (lo + hi), lambda_nm);
      if (hf && std::abs(*hf) < 1e-9) return make(0.5 * (lo + hi));
    }
    prev_h = h, prev_y = y;
  }
  return std::nullopt;
}

std::optional<double> RealImageHeight(const LensSystem& lens, double field_deg, double lambda_nm) {
  std::optional<LensRay> chief = ChiefRay(lens, field_deg, lambda_nm);
  if (!chief) return std::nullopt;
  const int last = int(lens.prescription().surfaces.size()) - 1;
  LensSystem open = Unclipped(lens, last);
  TraceResult t = TraceFromObject(open, *chief, lambda_nm);
  if (!t.ray || t.ray->d.z <= 0) return std::nullopt;
  return t.ray->o.y + t.ray->d.y * (lens.FilmZ() - t.ray->o.z) / t.ray->d.z;
}

std::optional<double> Distortion(const LensSystem& lens, double efl, double field_deg, double lambda_nm) {
  std::optional<double> h = RealImageHeight(lens, field_deg, lambda_nm);
  if (!h) return std::nullopt;
  // Light travelling toward +y comes from an object below the axis, imaged (inverted) above it.
  double ideal = efl * std::tan(field_deg * M_PI / 180);
  return (*h - ideal) / ideal;
}

namespace {
// Launch a parallel beam from a field angle over a disk of `radius` (perpendicular to the
// beam, centred on the chief ray's entrance) and trace it; returns the film points and the
// launch count. `rim_passed` tells whether rays on the outer ring got through.
struct Beam {
  std::vector<Vec2d> points;
  int launched = 0;
  bool rim_passed = false;
};
Beam TraceBeam(const LensSystem& lens, double field_deg, double lambda_nm, double y_centre, double radius, int n) {
  Beam b;
  double theta = field_deg * M_PI / 180;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double x = radius * (2.0 * (i + 0.5) / n - 1), y = radius * (2.0 * (j + 0.5) / n - 1);
      double rr = x * x + y * y;
      if (rr > radius * radius) continue;
      ++b.launched;
      // Perpendicular to the beam the offset is y; in the plane z = kStartZ it is y / cos.
      LensRay r{{x, y_centre + y / std::cos(theta), kStartZ}, {0, std::sin(theta), std::cos(theta)}};
      TraceResult t = TraceFromObject(lens, r, lambda_nm);
      if (!t.ray || t.ray->d.z <= 0) continue;
      if (rr > 0.8 * 0.8 * radius * radius) b.rim_passed = true;
      double s = (lens.FilmZ() - t.ray->o.z) / t.ray->d.z;
      b.points.push_back({t.ray->o.x + t.ray->d.x * s, t.ray->o.y + t.ray->d.y * s});
    }
  return b;
}

double BeamCentre(const LensSystem& lens, double field_deg, double lambda_nm) {
  std::optional<LensRay> chief = ChiefRay(lens, field_deg, lambda_nm);
  if (chief) return chief->o.y;
  ParaxialData p = lens.Paraxial(lambda_nm);
  return -std::tan(field_deg * M_PI / 180) * (p.entrance_pupil_position - kStartZ);
}
}  // namespace

std::optional<double> RelativeIllumination(const LensSystem& lens, double field_deg, double lambda_nm) {
  const int n = 61;
  ParaxialData p = lens.Paraxial(lambda_nm);
  // Beam cross-section that gets through, in a disk widened until its rim is blocked
  // (real pupils grow off axis, strongly so in fisheyes).
  auto beam_area = [&](double field) {
    double radius = 0.75 * p.entrance_pupil_diameter;
    for (int k = 0; k < 6; ++k) {
      Beam b = TraceBeam(lens, field, lambda_nm, BeamCentre(lens, field, lambda_nm), radius, n);
      if (!b.rim_passed || k == 5) return b.launched ? M_PI * radius * radius * b.points.size() / b.launched : 0.0;
      radius *= 1.6;
    }
    return 0.0;
  };
  double a0 = beam_area(0);
  if (field_deg == 0) return 1.0;
  double theta = field_deg * M_PI / 180, dtheta = 1e-3 * std::max(1.0, field_deg) * M_PI / 180;
  std::optional<double> h = RealImageHeight(lens, field_deg, lambda_nm);
  std::optional<double> h1 = RealImageHeight(lens, field_deg + dtheta * 180 / M_PI, lambda_nm);
  std::optional<double> h0 = RealImageHeight(lens, field_deg - dtheta * 180 / M_PI, lambda_nm);
  if (!h || !h0 || !h1 || a0 == 0) return std::nullopt;
  double dh = (*h1 - *h0) / (2 * dtheta);
  if (*h * dh <= 0) return std::nullopt;
  double e = beam_area(field_deg) * std::sin(theta) / (*h * dh);
  // On axis the same ratio tends to A / f^2 (h ~ f theta, dh/dtheta ~ f).
  const double f = p.object_index * p.efl;  // the object side's focal length
  double e0 = a0 / (f * f);
  return e / e0;
}

std::optional<FieldCurvature> FieldCurvatureAt(const LensSystem& lens, double field_deg, double lambda_nm) {
  std::optional<LensRay> chief = ChiefRay(lens, field_deg, lambda_nm);
  if (!chief) return std::nullopt;
  ParaxialData p = lens.Paraxial(lambda_nm);
  double theta = field_deg * M_PI / 180, eps = 1e-4 * p.entrance_pupil_diameter;
  // Rays next to the chief ray, through the lens without its stop's limit or a central
  // obstruction (which would block them); set up once for the four rays.
  LensSystem open = lens.WithoutObstructions();
  open.SetStopSemiDiameter(1e30);
  auto trace = [&](double dx, double dy) -> std::optional<LensRay> {
    LensRay r{{dx, chief->o.y + dy / std::cos(theta), kStartZ}, chief->d};
    TraceResult t = TraceFromObject(open, r, lambda_nm);
    if (!t.ray) return std::nullopt;
    return t.ray;
  };
  auto c = trace(0, 0), tp = trace(0, eps), tm = trace(0, -eps), sp = trace(eps, 0);
  if (!c || !tp || !tm || !sp) return std::nullopt;
  // Tangential focus: where the two meridional neighbours cross (in the y-z plane).
  auto cross_yz = [](const LensRay& a, const LensRay& b) {
    double sa = a.d.y / a.d.z, sb = b.d.y / b.d.z;
    return (b.o.y - sb * b.o.z - (a.o.y - sa * a.o.z)) / (sa - sb);
  };
  double zt = cross_yz(*tp, *tm);
  // Sagittal focus: where the skew neighbour crosses the meridional plane x = 0.
  double zs = sp->o.z - sp->o.x * sp->d.z / sp->d.x;
  return FieldCurvature{zt - lens.FilmZ(), zs - lens.FilmZ()};
}

Spot SpotDiagram(const LensSystem& lens, double field_deg, double lambda_nm, int n) {
  Spot spot;
  ParaxialData p = lens.Paraxial(lambda_nm);
  double theta = field_deg * M_PI / 180;
  std::optional<LensRay> chief = ChiefRay(lens, field_deg, lambda_nm);
  // Centre the grid on the chief ray's entrance (the real entrance pupil's centre).
  double y_centre = chief ? chief->o.y : -std::tan(theta) * (p.entrance_pupil_position - kStartZ);
  // 1.2 pupil radii; an anamorphic's pupil is an oval: the larger of its sections' (the same
  // grid, turned a quarter, for the lens turned a quarter: both sections' spots agree).
  double pupil = p.entrance_pupil_diameter;
  if (lens.prescription().HasToroids()) pupil = std::max(pupil, XSectionSystem(lens).Paraxial(lambda_nm).entrance_pupil_diameter);
  double radius = 0.6 * pupil;
  int launched = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double x = radius * (2.0 * (i + 0.5) / n - 1), y = radius * (2.0 * (j + 0.5) / n - 1);
      if (x * x + y * y > radius * radius) continue;
      ++launched;
      // Parallel rays: same direction, shifted in the plane perpendicular to the axis
      // (entrance heights measured at kStartZ along the tilted beam).
      LensRay r{{x, y_centre + y / std::cos(theta), kStartZ}, {0, std::sin(theta), std::cos(theta)}};
      TraceResult t = TraceFromObject(lens, r, lambda_nm);
      if (!t.ray || t.ray->d.z <= 0) continue;
      double s = (lens.FilmZ() - t.ray->o.z) / t.ray->d.z;
      spot.points.push_back({t.ray->o.x + t.ray->d.x * s, t.ray->o.y + t.ray->d.y * s});
    }
  spot.transmitted = launched ? double(spot.points.size()) / launched : 0;
  if (spot.points.empty()) return spot;
  for (const Vec2d& q : spot.points) spot.centroid = spot.centroid + q * (1.0 / spot.points.size());
  double sum2 = 0;
  for (const Vec2d& q : spot.points) {
    double d2 = (q.x - spot.centroid.x) * (q.x - spot.centroid.x) + (q.y - spot.centroid.y) * (q.y - spot.centroid.y);
    sum2 += d2;
    spot.geometric_radius = std::max(spot.geometric_radius, std::sqrt(d2));
  }
  spot.rms_radius = std::sqrt(sum2 / spot.points.size());
  return spot;
}

namespace {
// The largest field angle (degrees) the lens forms an image of: light from it still gets
// through the real apertures (the edge of the image circle), and its chief ray exists.
double MaxImagedField(const LensSystem& lens, double lambda_nm) {
  auto images = [&](double field) {
    return RealImageHeight(lens, field, lambda_nm) && SpotDiagram(lens, field, lambda_nm, 15).transmitted > 0;
  };
  double lo = 0, hi = 89.9;
  if (images(hi)) return hi;
  for (double f = 89; f > 0; f -= 1)
    if (images(f)) {
      lo = f, hi = f + 1;
      break;
    }
  for (int it = 0; it < 30; ++it) {
    double mid = 0.5 * (lo + hi);
    (images(mid) ? lo : hi) = mid;
  }
  return lo;
}

// The field angle whose real image height is h; the edge of the image circle when h lies
// beyond it (as for a fisheye's corners).
double FieldForHeight(const LensSystem& lens, double h, double max_field, double lambda_nm) {
  std::optional<double> h_max = RealImageHeight(lens, max_field, lambda_nm);
  if (!h_max || std::abs(*h_max) <= h) return max_field;
  double lo = 0, hi = max_field;
  for (int it = 0; it < 60; ++it) {
    double mid = 0.5 * (lo + hi);
    std::optional<double> hm = RealImageHeight(lens, mid, lambda_nm);
    (hm && std::abs(*hm) < h ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}
}  // namespace

FieldOfView SensorFieldOfView(const LensSystem& lens, double width, double height, double lambda_nm) {
  if (!lens.prescription().Centred()) {  // the lens's own field, centred on its axis
    LensSystem centred(CentredOnAxis(lens.prescription()));
    centred.SetStopSemiDiameter(lens.StopSemiDiameter());
    centred.SetBackFocus(lens.BackFocus());
    return SensorFieldOfView(centred, width, height, lambda_nm);
  }
  double max_field = MaxImagedField(lens, lambda_nm);
  if (lens.prescription().HasToroids() && lens.prescription().Centred()) {
    // Horizontal in the x-z section, vertical in the y-z one; the corner's chief ray is skew.
    const LensSystem x = XSectionSystem(lens);
    return {2 * FieldForHeight(x, width / 2, MaxImagedField(x, lambda_nm), lambda_nm),
            2 * FieldForHeight(lens, height / 2, max_field, lambda_nm), NAN};
  }
  return {2 * FieldForHeight(lens, width / 2, max_field, lambda_nm),
          2 * FieldForHeight(lens, height / 2, max_field, lambda_nm),
          2 * FieldForHeight(lens, std::hypot(width, height) / 2, max_field, lambda_nm)};
}

double RealBackFocus(const LensSystem& lens, double lambda_nm) {
  ParaxialData p = lens.Paraxial(lambda_nm);
  LensSystem t = lens;
  auto rms = [&](double back_focus) {
    t.SetBackFocus(back_focus);
    return SpotDiagram(t, 0, lambda_nm, 41).rms_radius;
  };
  // Golden-section search within 5% of the EFL about the paraxial focus; where the minimum
  // lands at an end of that window (strong spherical aberration moves the best focus far), the
  // window grows on that side and the search runs again.
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  auto golden = [&](double a, double b) {
    double c = b - g * (b - a), d = a + g * (b - a), fc = rms(c), fd = rms(d);
    for (int it = 0; it < 80 && b - a > 1e-7 * std::abs(p.efl); ++it) {
      if (fc < fd) {
        b = d, d = c, fd = fc;
        c = b - g * (b - a), fc = rms(c);
      } else {
        a = c, c = d, fc = fd;
        d = a + g * (b - a), fd = rms(d);
      }
    }
    return 0.5 * (a + b);
  };
  double lo = p.bfl - 0.05 * std::abs(p.efl), hi = p.bfl + 0.05 * std::abs(p.efl), best = golden(lo, hi);
  for (int grow = 0; grow < 8; ++grow) {
    const double span = hi - lo, edge = 0.01 * span;
    if (best - lo > edge && hi - best > edge) break;
    if (best - lo <= edge) lo -= span;
    else hi += span;
    best = golden(lo, hi);
  }
  return best;
}

std::optional<double> LongitudinalAberration(const LensSystem& lens, double height, double lambda_nm) {
  ParaxialData p = lens.Paraxial(lambda_nm);
  TraceResult t = TraceFromObject(lens, {{0, height, kStartZ}, {0, 0, 1}}, lambda_nm);
  if (!t.ray || t.ray->d.y == 0) return std::nullopt;
  double z = t.ray->o.z - t.ray->o.y * t.ray->d.z / t.ray->d.y;
  double last = lens.VertexZ(int(lens.prescription().surfaces.size()) - 1);
  return (z - last) - p.bfl;
}

AxialTransmittance AxialTransmittanceOf(const LensSystem& lens, double lambda_nm) {
  auto trace = [&](double y) { return TraceFromObject(lens, {{0, y, -1}, {0, 0, 1}}, lambda_nm); };
  TraceResult r = trace(0);
  if (!r.ray) {
    // Blocked on the axis: scan outward for the first zone that lets light through.
    const double rim = lens.prescription().surfaces.front().semi_diameter;
    constexpr int kSteps = 256;
    int first = -1, last = -1;
    for (int k = 1; k < kSteps; ++k) {
      const bool passes = trace(rim * k / kSteps).ray.has_value();
      if (passes && first < 0) first = k;
      if (first >= 0 && !passes) break;
      if (passes) last = k;
    }
    if (first < 0) return {};
    r = trace(rim * 0.5 * (first + last) / kSteps);
    if (!r.ray) return {};
  }
  // Dust and scratches by their mean over each surface (one ray would find them or not).
  double dirt = 1;
  for (int i = 0; i < lens.SurfaceCount(); ++i)
    if (lens.surface(i).dirt) dirt *= lens.surface(i).dirt->MeanTransmittance();
  return {r.surface_transmittance * dirt, r.internal_transmittance};
}

}  // namespace objektiv
