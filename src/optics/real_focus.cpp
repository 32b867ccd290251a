#include "optics/real_focus.h"

#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "base/log.h"
#include "optics/focusing.h"
#include "optics/paraxial.h"

namespace objektiv {

namespace {

constexpr double kInfinity = 1e12;

// Paraxially, moving the film to z' = 2f behind the back principal plane brings the object
// to 2f in front of the front one: the closest object-to-film distance of unit focusing.
double ClosestFocusBackFocus(const ParaxialData& p) { return p.back_principal_plane + 2 * p.efl; }

// The plane (lens z) where the rays' RMS spread about their centroid is least: each ray's
// transverse position is linear in z, so the RMS is quadratic in z and its minimum closed form.
std::optional<double> LeastRmsPlane(const std::vector<LensRay>& rays) {
  if (rays.size() < 8) return std::nullopt;
  double n = double(rays.size());
  Vec2d a_mean(0, 0), b_mean(0, 0);
  std::vector<Vec2d> a(rays.size()), b(rays.size());
  for (size_t i = 0; i < rays.size(); ++i) {
    const LensRay& r = rays[i];
    b[i] = Vec2d(r.d.x / r.d.z, r.d.y / r.d.z);  // dx/dz
    a[i] = Vec2d(r.o.x - r.o.z * b[i].x, r.o.y - r.o.z * b[i].y);  // x at z = 0
    a_mean = a_mean + a[i] * (1 / n);
    b_mean = b_mean + b[i] * (1 / n);
  }
  double num = 0, den = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    Vec2d da = a[i] - a_mean, db = b[i] - b_mean;
    num += da.x * db.x + da.y * db.y;
    den += db.x * db.x + db.y * db.y;
  }
  if (!(den > 0)) return std::nullopt;
  return -num / den;
}

// Rays from the axial object point (at lens z = object_z, or at infinity) through a grid
// over the paraxial entrance pupil (a little enlarged); those that reach the last surface,
// as they leave it.
std::vector<LensRay> AxialBundle(const LensSystem& lens, const ParaxialData& p, double object_z, bool infinite,
                                 double lambda_nm) {
  const double front = 0.6 * p.entrance_pupil_diameter, pupil_z = p.entrance_pupil_position;
  const int n = 25;
  std::vector<LensRay> out;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double x = front * (2 * (i + 0.5) / n - 1), y = front * (2 * (j + 0.5) / n - 1);
      if (x * x + y * y > front * front) continue;
      LensRay ray;
      if (infinite) {
        ray = {{x, y, -1}, {0, 0, 1}};
      } else {
        ray.o = {0, 0, object_z};
        ray.d = Normalize(Vec3d(x, y, pupil_z) - ray.o);
      }
      if (TraceResult t = TraceFromObject(lens, ray, lambda_nm); t.ray) out.push_back(*t.ray);
    }
  return out;
}

}  // namespace

double ClosestFocusDistance(const LensPrescription& rx, double lambda_nm) {
  ParaxialData p = ComputeParaxial(rx, lambda_nm);
  double t = ClosestFocusBackFocus(p);
  // Object distance from the first vertex for the image at back focus t: Gaussian optics
  // about the principal planes (exact paraxially).
  double image = t - p.back_principal_plane;  // from H'
  double object = p.object_index / (1 / p.efl - 1 / image);  // in front of H: n0 / s + 1 / s' = 1 / EFL
  return t + rx.TotalTrack() + object - p.front_principal_plane;
}

LensFocus ParaxialFocus(const LensPrescription& rx, double distance_from_film, double lambda_nm) {
  ParaxialData p = ComputeParaxial(rx, lambda_nm);
  LensFocus focus;
  if (!(distance_from_film < kInfinity)) {
    focus.back_focus = p.bfl;
    focus.plane_of_focus_to_film = INFINITY;
  } else if (auto s = FocusAtDistance(rx, distance_from_film, lambda_nm)) {
    focus.back_focus = s->back_focus;
    focus.plane_of_focus_to_film = distance_from_film;
  } else {
    focus.back_focus = ClosestFocusBackFocus(p);
    focus.plane_of_focus_to_film = ClosestFocusDistance(rx, lambda_nm);
    focus.clamped = true;
  }
  return focus;
}

LensFocus FocusLens(const LensSystem& lens, double distance_from_film, double lambda_nm) {
  const LensPrescription& rx = lens.prescription();
  ParaxialData p = lens.Paraxial(lambda_nm);
  LensFocus focus = ParaxialFocus(rx, distance_from_film, lambda_nm);
  const bool infinite = std::isinf(focus.plane_of_focus_to_film);
  // Real rays: the object stays at its distance from the film while the lens moves, so the
  // object point follows each new back focus; a few rounds converge.
  LensSystem t = lens;
  const int last = int(rx.surfaces.size()) - 1;
  double back = focus.back_focus;
  for (int round = 0; round < 12; ++round) {
    t.SetBackFocus(back);
    double object_z = t.FilmZ() - focus.plane_of_focus_to_film;
    std::vector<LensRay> rays = AxialBundle(t, p, object_z, infinite, lambda_nm);
    std::optional<double> z = LeastRmsPlane(rays);
    if (!z) {  // too few rays: keep the paraxial focus
      spdlog::warn("lens {}: too few real rays get through to find its best focus; the paraxial focus is kept", rx.name);
      return focus;
    }
    double next = *z - t.VertexZ(last);
    // Real and paraxial focus differ by the aberrations, a small fraction of f.
    if (!std::isfinite(next) || std::abs(next - focus.back_focus) > 0.2 * std::abs(p.efl)) {
      spdlog::warn("lens {}: its real rays focus {} from the paraxial focus (more than a fifth of its focal length: "
                   "aberrations too strong to trust); the paraxial focus is kept and the image may be soft",
                   rx.name, std::isfinite(next) ? fmt::format("{:.4g} mm", next - focus.back_focus) : std::string("far"));
      return focus;
    }
    bool converged = std::abs(next - back) < 1e-9 * std::abs(p.efl);
    back = next;
    focus.rays_used = int(rays.size());
    if (converged) break;
  }
  focus.back_focus = back;
  focus.real_rays = true;
  return focus;
}

std::string DescribeFocus(const LensFocus& f, double infinity_back_focus) {
  std::string where = std::isinf(f.plane_of_focus_to_film) ? std::string("infinity")
                                                    : fmt::format("{:.4g} m from the film", f.plane_of_focus_to_film * 1e-3);
  return fmt::format("focused at {}{}: lens {:.3f} mm forward of its infinity position, back focus {:.3f} mm ({})",
                     where, f.clamped ? " (the closest the lens can focus)" : "", f.back_focus - infinity_back_focus,
                     f.back_focus,
                     f.real_rays ? fmt::format("best RMS focus of {} real rays", f.rays_used) : "paraxial focus");
}

}  // namespace objektiv
