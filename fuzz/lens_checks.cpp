#include "lens_checks.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "optics/focusing.h"
#include "optics/lens_setup.h"
#include "optics/lens_tracer.h"
#include "optics/paraxial.h"
#include "optics/real_ray_analysis.h"

namespace objektiv::fuzz {

namespace {

constexpr double kLambdaD = 587.5618;

void Require(bool ok, const char* what, size_t surface) {
  if (ok) return;
  std::fprintf(stderr, "accepted lens, surface %zu: %s\n", surface, what);
  std::abort();
}

// What every reader promises about a prescription it returns.
void CheckPrescription(const LensPrescription& lens) {
  Require(!lens.surfaces.empty(), "no surfaces", 0);
  Require(lens.StopIndex() >= 0, "no stop", 0);
  for (size_t i = 0; i < lens.surfaces.size(); ++i) {
    const LensSurface& s = lens.surfaces[i];
    Require(std::isfinite(s.radius) && (s.flat || s.is_stop || s.radius != 0), "radius neither finite nor flat", i);
    Require(std::isfinite(s.thickness), "thickness not finite", i);
    Require(std::isfinite(s.semi_diameter) && s.semi_diameter > 0, "semi-diameter not positive and finite", i);
    Require(std::isfinite(s.conic) && std::isfinite(s.a2), "conic or r^2 term not finite", i);
    for (double a : s.aspheric) Require(std::isfinite(a), "aspheric coefficient not finite", i);
    if (s.forbes) {
      Require(std::isfinite(s.forbes->norm_radius()) && s.forbes->norm_radius() > 0, "Q-type normalisation not positive", i);
      for (double a : s.forbes->terms()) Require(std::isfinite(a), "Q-type term not finite", i);
      Require(std::isfinite(s.ParaxialCurvature()), "Q-type paraxial curvature not finite", i);
    }
    if (s.form_error)
      Require(s.form_error->peak_to_valley() > 0 && s.form_error->peak_to_valley() <= 1, "form error not in (0, 1 mm]", i);
    if (s.fresnel) {
      Require(s.fresnel->pitch() > 0 && s.semi_diameter / s.fresnel->pitch() <= 100000, "Fresnel zones not bounded", i);
      Require(std::isfinite(s.fresnel->slab_lo()) && std::isfinite(s.fresnel->slab_hi()), "Fresnel slab not finite", i);
    }
    if (s.gradient) {
      for (double c : s.gradient->coefficients()) Require(std::isfinite(c), "gradient term not finite", i);
      Require(s.medium != nullptr, "gradient-index medium without its glass", i);
    }
    double n = s.IndexAfter(kLambdaD);
    Require(std::isfinite(n) && n >= 1, "index after the surface below 1 or not finite", i);
  }
}

}  // namespace

void ExerciseLens(const LensPrescription& lens) {
  CheckPrescription(lens);
  ParaxialData d = ComputeParaxial(lens, kLambdaD);
  // The lens commands and the realistic camera refuse afocal systems.
  if (!std::isfinite(d.efl) || std::abs(d.efl) > 1e12) return;
  FocusAtDistance(lens, 2000, kLambdaD);
  const LensSystem system = AtParaxialInfinityFocus(lens, kLambdaD);
  // Every surface's reflectance, bare or coated, both ways, is a fraction.
  for (int i = 0; i < system.SurfaceCount(); ++i)
    for (double cos_i : {1.0, 0.4})
      for (bool toward_film : {true, false}) {
        double r = system.SurfaceReflectance(i, 480, cos_i, toward_film);
        Require(r >= 0 && r <= 1, "surface reflectance not in [0, 1]", size_t(i));
      }
  RealBackFocus(system, kLambdaD);
  ChiefRay(system, 0, kLambdaD);
  ChiefRay(system, 15, kLambdaD);
  SpotDiagram(system, 5, 486.1327, 5);
  LongitudinalAberration(system, 0.5 * lens.surfaces.front().semi_diameter, 656.2725);
  TraceFromFilm(system, {{0, 0, system.FilmZ()}, {0, 0.1, -1}}, kLambdaD);
}

}  // namespace objektiv::fuzz
