#include "optics/lens_prescription.h"

#include <algorithm>
#include <cmath>

#include "base/error.h"

namespace objektiv {

void LensSurface::SetCurvature(double c) {
  flat = !std::isfinite(1 / c);
  radius = flat ? 0 : 1 / c;
}

int LensPrescription::StopIndex() const {
  for (size_t i = 0; i < surfaces.size(); ++i)
    if (surfaces[i].is_stop) return int(i);
  return -1;
}

int LensPrescription::MirrorCount() const {
  return int(std::count_if(surfaces.begin(), surfaces.end(), [](const LensSurface& s) { return s.mirror; }));
}

int LensPrescription::DirectionAfter(size_t i) const {
  int direction = 1;
  for (size_t k = 0; k <= i && k < surfaces.size(); ++k)
    if (surfaces[k].mirror) direction = -direction;
  return direction;
}

std::optional<std::pair<size_t, std::string>> FirstDirectionMismatch(const LensPrescription& lens) {
  int mirrors = 0;
  for (size_t i = 0; i < lens.surfaces.size(); ++i) {
    const LensSurface& s = lens.surfaces[i];
    mirrors += s.mirror;
    const bool toward_film = mirrors % 2 == 0;
    if (toward_film ? s.thickness < 0 : s.thickness > 0)
      return {{i, fmt::format("thickness {} goes against the light: after {} mirror(s) it travels toward the {}, so the "
                              "thickness to the next surface must be {} (a z step, as lens designers write it)",
                              s.thickness, mirrors, toward_film ? "film" : "object",
                              toward_film ? "positive" : "negative")}};
  }
  if (mirrors % 2)
    return {{lens.surfaces.size() - 1,
             fmt::format("the lens has {} mirror{}, an odd number: its image would lie on the object's side; a "
                         "camera needs an even number (a fold mirror needs a coordinate break, which is not supported)",
                         mirrors, mirrors == 1 ? "" : "s")}};
  return std::nullopt;
}

namespace {

// The lens-space z of surface s (its vertex nominally at vertex_z) over the lens-space point
// (X, Y), where that lies within its clear aperture: a placed surface's own point under (X, Y)
// found by Newton's method on its frame's x, y (a tilt below 90 degrees keeps it unique).
std::optional<double> SurfaceZOver(const LensSurface& s, double vertex_z, double X, double Y) {
  double z;
  if (!s.placement) {
    if (X * X + Y * Y > s.semi_diameter * s.semi_diameter || !s.SagAt(X, Y, z)) return std::nullopt;
    return vertex_z + z;
  }
  const SurfacePlacement& p = *s.placement;
  const Vec3d origin = Vec3d(0, 0, vertex_z) + p.offset;
  const Vec3d start = p.ToLocal(Vec3d(X, Y, 0) - origin);
  double lx = start.x, ly = start.y;
  for (int it = 0; it < 30; ++it) {
    double gx, gy;
    if (!s.SagAt(lx, ly, z, &gx, &gy)) return std::nullopt;
    const Vec3d q = origin + p.ex * lx + p.ey * ly + p.ez * z;
    const double ex = X - q.x, ey = Y - q.y;
    if (std::abs(ex) + std::abs(ey) < 1e-12 * (1 + std::abs(X) + std::abs(Y))) break;
    // d(q.x, q.y) / d(lx, ly), the sag's slope included.
    const double a = p.ex.x + p.ez.x * gx, b = p.ey.x + p.ez.x * gy, c = p.ex.y + p.ez.y * gx, d = p.ey.y + p.ez.y * gy;
    const double det = a * d - b * c;
    if (det == 0) return std::nullopt;
    lx += (d * ex - b * ey) / det, ly += (a * ey - c * ex) / det;
  }
  if (lx * lx + ly * ly > s.semi_diameter * s.semi_diameter || !s.SagAt(lx, ly, z)) return std::nullopt;
  return (origin + p.ex * lx + p.ey * ly + p.ez * z).z;
}

}  // namespace

std::optional<std::pair<size_t, std::string>> FirstCrossedGap(const LensPrescription& lens) {
  const size_t n = lens.surfaces.size();
  const std::vector<double> vertex_z = lens.VertexZs();
  // The next surfaces the light meets before it turns at a mirror (six rows ahead at most: a
  // stop or a thin element between two others) must lie beyond surface i along the light,
  // wherever both have glass (sampled on rings over surface i's aperture).
  for (size_t i = 0; i + 1 < n; ++i) {
    const LensSurface& a = lens.surfaces[i];
    const double direction = lens.DirectionAfter(i);
    const Vec3d centre = a.placement ? a.placement->offset : Vec3d(0, 0, 0);
    for (size_t j = i + 1; j < std::min(n, i + 7); ++j) {
      double worst = 0, worst_r = 0;
      for (int ring = 0; ring <= 24; ++ring)
        for (int k = 0; k < (ring ? 16 : 1); ++k) {
          const double r = a.semi_diameter * ring / 24, phi = 2 * M_PI * k / 16;
          const double X = centre.x + r * std::cos(phi), Y = centre.y + r * std::sin(phi);
          const std::optional<double> za = SurfaceZOver(a, vertex_z[i], X, Y), zb = SurfaceZOver(lens.surfaces[j], vertex_z[j], X, Y);
          if (!za || !zb) continue;
          if (const double gap = direction * (*zb - *za); gap < worst) worst = gap, worst_r = std::hypot(X, Y);
        }
      if (worst < -1e-6 * (1 + std::abs(vertex_z[j] - vertex_z[i])))
        return {{j, fmt::format("this surface crosses surface {} (row {}): {:.4g} mm from the axis it lies {:.4g} mm before "
                                "it, against the direction the light travels (a thickness too small for the sags, "
                                "decentres or tilts there)",
                                i + 1, i + 1, worst_r, -worst)}};
      if (lens.surfaces[j].mirror) break;  // the light turns: later surfaces lie the other way
    }
  }
  return std::nullopt;
}

std::vector<double> LensPrescription::VertexZs() const {
  std::vector<double> z(surfaces.size(), 0.0);
  for (size_t i = 1; i < surfaces.size(); ++i) z[i] = z[i - 1] + surfaces[i - 1].thickness;
  return z;
}

double LensPrescription::TotalTrack() const {
  double t = 0;
  for (size_t i = 0; i + 1 < surfaces.size(); ++i) t += surfaces[i].thickness;
  return t;
}

double LensSurface::Sag(double r) const {
  double z, slope;
  SagWithSlope(r, z, slope);
  return z;
}

double LensSurface::SagSlope(double r) const {
  double z, slope;
  SagWithSlope(r, z, slope);
  return slope;
}

void LensSurface::SagWithSlope(double r, double& z, double& slope) const {
  const double c = Curvature(), r2 = r * r;
  z = 0, slope = 0;
  if (c != 0) {
    const double arg = 1 - (1 + conic) * c * c * r2;
    z = c * r2 / (1 + std::sqrt(std::max(arg, 0.0)));
    slope = c * r / std::sqrt(std::max(arg, 1e-300));
  }
  z += a2 * r2, slope += 2 * a2 * r;
  double rp = r2 * r2, rd = r2 * r;  // r^4, r^3
  int order = 4;
  for (double a : aspheric) {
    z += a * rp, slope += order * a * rd;
    rp *= r2, rd *= r2, order += 2;
  }
  if (forbes) {
    double dz, ds;
    forbes->Departure(r, c, dz, ds);
    z += dz, slope += ds;
  }
}

bool LensSurface::SagAt(double x, double y, double& z, double* gx, double* gy) const {
  if (!NominalSagAt(x, y, z, gx, gy)) return false;
  if (form_error) {
    double ex, ey;
    z += form_error->Height(x, y, gx ? &ex : nullptr, gx ? &ey : nullptr);
    if (gx) *gx += ex, *gy += ey;
  }
  return true;
}

bool LensSurface::NominalSagAt(double x, double y, double& z, double* gx, double* gy) const {
  const double c = Curvature();
  if (!toroidal) {
    const double r = std::sqrt(x * x + y * y);
    if (c != 0 && (1 + conic) * c * c * r * r > 1) return false;
    double slope;
    SagWithSlope(r, z, slope);
    if (fresnel) z -= fresnel->BaseHeight(*this, fresnel->Zone(r));
    if (gx) {
      const double per_r = r > 0 ? slope / r : 0;
      *gx = per_r * x, *gy = per_r * y;
    }
    return true;
  }
  // The profile z_y(y), then the circle of radius u = 1 / curvature_x - z_y about the axis of
  // rotation: z = z_y + x^2 / (u (1 + q)), q = sqrt(1 - x^2 / u^2) (the sag of that circle,
  // written without the cancellation of R - sqrt(R^2 - x^2)).
  const double ay = std::abs(y);
  if (c != 0 && (1 + conic) * c * c * ay * ay > 1) return false;
  const double zy = Sag(ay), dzy = std::copysign(SagSlope(ay), y);
  if (curvature_x == 0) {
    z = zy;
    if (gx) *gx = 0, *gy = dzy;
    return true;
  }
  const double R = 1 / curvature_x, u = R - zy;
  if (!(u * R > 0)) return false;  // the profile crossed the axis of rotation
  const double q2 = 1 - (x / u) * (x / u);
  if (!(q2 > 0)) return false;
  const double q = std::sqrt(q2);
  z = zy + x * x / (u * (1 + q));
  if (gx) *gx = x / (u * q), *gy = dzy / q;
  return true;
}

double LensSurface::ParaxialCurvatureInY() const {
  if (!toroidal || !placement) return ParaxialCurvature();
  const Vec3d u = placement->ToLocal(Vec3d(0, 1, 0));
  const double norm = u.x * u.x + u.y * u.y;
  if (!(norm > 0)) return ParaxialCurvature();
  return (ParaxialCurvatureX() * u.x * u.x + ParaxialCurvature() * u.y * u.y) / norm;
}

LensPrescription TurnedAboutAxis(const LensPrescription& lens, double angle) {
  LensPrescription out = lens;
  const double c = std::cos(angle), s = std::sin(angle);
  auto turn = [&](const Vec3d& v) { return Vec3d(c * v.x - s * v.y, s * v.x + c * v.y, v.z); };
  for (LensSurface& surface : out.surfaces) {
    const bool leaning_crystal = surface.crystal && surface.crystal->Leans();
    if (!surface.toroidal && !surface.placement && !surface.is_stop && !leaning_crystal) continue;  // the same turned
    SurfacePlacement p = surface.placement.value_or(SurfacePlacement{});
    p.offset = turn(p.offset);
    p.ex = turn(p.ex), p.ey = turn(p.ey), p.ez = turn(p.ez);
    surface.placement = p;
  }
  return out;
}

LensPrescription CentredOnAxis(const LensPrescription& lens) {
  LensPrescription out = lens;
  for (LensSurface& s : out.surfaces) s.placement.reset();
  return out;
}

std::string ToroidTurnMismatch(const LensSurface& s) {
  if (!s.toroidal || !s.placement) return "";
  const Vec3d& ex = s.placement->ex;
  if (std::abs(ex.x) < 1e-9 || std::abs(ex.y) < 1e-9) return "";
  return fmt::format("a toroid turned {:.4g} degrees about the axis: its sections must lie along the film's x and y "
                     "(turns of 0, 90, 180 degrees), as crossed cylinders at other angles are not modelled",
                     std::atan2(ex.y, ex.x) * 180 / M_PI);
}

LensPrescription MovedAsAWhole(const LensPrescription& lens, const SurfacePlacement& motion, double pivot_z) {
  LensPrescription out = lens;
  const Vec3d pivot(0, 0, pivot_z);
  const std::vector<double> vertex_z = lens.VertexZs();
  for (size_t i = 0; i < out.surfaces.size(); ++i)
    out.surfaces[i].placement = out.surfaces[i].placement.value_or(SurfacePlacement{}).MovedBy(motion, pivot, Vec3d(0, 0, vertex_z[i]));
  return out;
}

bool LensPrescription::HasToroids() const {
  return std::any_of(surfaces.begin(), surfaces.end(), [](const LensSurface& s) { return s.toroidal; });
}

int LensPrescription::CrystalCount() const {
  return int(std::count_if(surfaces.begin(), surfaces.end(), [](const LensSurface& s) { return bool(s.crystal); }));
}

bool LensPrescription::HasTurnedCrystals() const {
  return std::any_of(surfaces.begin(), surfaces.end(), [](const LensSurface& s) {
    return s.crystal && s.crystal->Leans();
  });
}

bool LensPrescription::MirrorSymmetric(int axis) const {
  // A direction is its own mirror image, as a line, where its component along the axis is 0
  // or it lies along the axis (the surfaces themselves are symmetric about their own x and y:
  // those may swap); a decentre must have no component along it.
  auto own_image = [axis](const Vec3d& v) {
    const double along = axis == 0 ? v.x : v.y, across = std::sqrt(Dot(v, v) - along * along);
    return std::abs(along) <= 1e-12 * across || across <= 1e-12 * std::abs(along);
  };
  return !HasFormErrors() && std::all_of(surfaces.begin(), surfaces.end(), [&](const LensSurface& s) {
    const SurfacePlacement* p = s.placement ? &*s.placement : nullptr;
    // The surface's own axis must not lean along the mirror's (a surface turned side-on).
    if (p && !(std::abs(axis == 0 ? p->offset.x : p->offset.y) <= 1e-12 && own_image(p->ex) && own_image(p->ey) &&
               std::abs(axis == 0 ? p->ez.x : p->ez.y) <= 1e-12)) return false;
    return !s.crystal || own_image(p ? p->FromLocal(s.crystal->axis) : s.crystal->axis);
  });
}

bool LensPrescription::HasGradients() const {
  return std::any_of(surfaces.begin(), surfaces.end(), [](const LensSurface& s) { return bool(s.gradient); });
}

bool LensPrescription::HasFormErrors() const {
  return std::any_of(surfaces.begin(), surfaces.end(), [](const LensSurface& s) { return bool(s.form_error); });
}

bool LensPrescription::Centred() const {
  return std::none_of(surfaces.begin(), surfaces.end(), [](const LensSurface& s) { return s.placement.has_value(); });
}

void CheckReachable(const LensSurface& s, const std::string& path, int line) {
  double c = s.Curvature();
  if (c != 0 && s.conic > -1) {
    double limit = 1 / (std::abs(c) * std::sqrt(1 + s.conic));
    if (s.semi_diameter > limit)
      throw MakeInputError(path, line, "semi-diameter {} is larger than the surface can reach ({:.4g})", s.semi_diameter, limit);
    // A Qbfs departure divides by sqrt(1 - c^2 r^2): infinite at the sphere's equator.
    if (s.forbes && s.forbes->kind() == ForbesAsphere::Kind::kBestFitSphere && !(s.semi_diameter < limit))
      throw MakeInputError(path, line, "semi-diameter {} reaches the best-fit sphere's equator ({:.4g}), where a Qbfs departure "
                           "is infinite", s.semi_diameter, limit);
  }
  if (!s.toroidal || s.curvature_x == 0) return;
  // A toroid must be whole over its clear disc: the circle of x-z section at height y (radius
  // 1 / curvature_x less the profile's sag there) must reach the disc's edge, x^2 + y^2 = semi^2.
  double z;
  for (int k = 0; k <= 32; ++k) {
    const double y = s.semi_diameter * k / 32, x = std::sqrt(std::max(s.semi_diameter * s.semi_diameter - y * y, 0.0));
    if (!s.SagAt(x, y, z))
      throw MakeInputError(path, line, "semi-diameter {} is larger than the toroid can reach (x radius {:.4g})",
                           s.semi_diameter, 1 / s.curvature_x);
  }
}

std::optional<std::pair<size_t, std::string>> FirstCoatingMismatch(const LensPrescription& lens) {
  for (size_t i = 0; i < lens.surfaces.size(); ++i) {
    const LensSurface& s = lens.surfaces[i];
    const Glass* before = lens.MediumBefore(i).get();
    if (!s.coating || before == s.medium.get()) continue;  // coats nothing
    if (std::string why = CoatingMismatch(*s.coating, before, s.medium.get()); !why.empty()) return {{i, why}};
  }
  return std::nullopt;
}

void CheckSize(const LensSurface& s, const std::string& path, int line) {
  if (!(std::abs(s.thickness) <= kMaxLensLength))
    throw MakeInputError(path, line, "thickness {} mm is beyond {} mm: not a lens", s.thickness, kMaxLensLength);
  if (!(s.semi_diameter <= kMaxLensLength))
    throw MakeInputError(path, line, "semi-diameter {} mm is beyond {} mm: not a lens", s.semi_diameter, kMaxLensLength);
}

LensPrescription LensPrescription::Scaled(double factor) const {
  LensPrescription out = *this;
  for (LensSurface& s : out.surfaces) {
    s.radius *= factor;
    s.thickness *= factor;
    s.semi_diameter *= factor;
    s.obscuration *= factor;
    s.a2 /= factor;
    s.curvature_x /= factor;
    if (s.forbes) s.forbes = std::make_shared<const ForbesAsphere>(s.forbes->Scaled(factor));
    if (s.placement) s.placement->offset *= factor;
    double scale = factor * factor * factor;  // 2k - 1 = 3 for a4
    for (double& a : s.aspheric) {
      a /= scale;
      scale *= factor * factor;
    }
    if (s.form_error) s.form_error = std::make_shared<const FormError>(s.form_error->Scaled(factor));
    if (s.gradient) s.gradient = std::make_shared<const GradientIndex>(s.gradient->Scaled(factor));
    if (s.dirt) s.dirt = std::make_shared<const SurfaceDirt>(s.dirt->Scaled(factor));
    // The zones of the scaled profile (their slab follows it).
    if (s.fresnel) s.fresnel = std::make_shared<const FresnelZones>(s, s.fresnel->pitch() * factor);
  }
  if (out.design_focal_length > 0) out.design_focal_length *= factor;
  if (out.image_circle > 0) out.image_circle *= factor;
  return out;
}

}  // namespace objektiv

namespace objektiv {

void CoatAirGlassSurfaces(LensPrescription& lens, const std::shared_ptr<const Coating>& coating, bool only_bare) {
  for (size_t i = 0; i < lens.surfaces.size(); ++i) {
    LensSurface& s = lens.surfaces[i];
    const bool glass_before = bool(lens.MediumBefore(i)), glass_after = bool(s.medium);
    if (glass_before == glass_after) continue;  // air on both sides, or cemented
    if (!only_bare || !s.coating) s.coating = coating;
  }
}

}  // namespace objektiv
