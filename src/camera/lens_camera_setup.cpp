#include "camera/lens_camera_setup.h"

#include <chrono>
#include <cmath>

#include "base/error.h"
#include "base/log.h"
#include "camera/paraxial_lens_camera.h"
#include "camera/realistic_camera.h"
#include "optics/anamorphic.h"
#include "optics/lens_setup.h"

namespace objektiv {

namespace {

// The stop's opening: the iris, cut to where the aperture mask lets light through.
StopShape StopOpening(const LensCameraSpec& spec) {
  StopShape shape = StopShape::Iris(spec.blades, spec.blade_curvature, spec.blade_rotation * M_PI / 180);
  if (spec.settings.aperture_mask) shape.Cut(spec.settings.aperture_mask->OpenHull());
  return shape;
}

// The plane to focus on: at a distance from the film, or through a world point (its depth
// along the view axis, from the entrance pupil where camera space has its origin).
FocusRequest Focus(const LensCameraSpec& spec, const Transform& to_world) {
  FocusRequest focus;
  if (!spec.focus_point) {
    focus.distance_mm = spec.focus_distance * 1e3;
    return focus;
  }
  Vec3f origin = to_world.Point(Vec3f(0, 0, 0)), forward = Normalize(to_world.Vector(Vec3f(0, 0, 1)));
  double depth = Dot(*spec.focus_point - origin, forward) * spec.settings.metres_per_unit * 1e3;
  if (!(depth > 0)) throw InputError("focus_point lies behind the camera");
  focus.distance_mm = depth;
  focus.from = FocusRequest::From::kEntrancePupil;
  return focus;
}

// Where the chief ray from the point `offset` mm beside the axis (toward -x), `distance` mm in front
// of the entrance pupil, meets the film (lens x, mm): its slope offset / distance at the entrance
// pupil, times the pupils' angular magnification D_ep / D_xp at the exit pupil, over the exit
// pupil's distance to the film (paraxial; the centre of the point's blur spot when defocused).
double ChiefRayFilmX(double offset, double distance, double ep_diameter, double xp_diameter, double xp_to_film) {
  return offset / distance * (ep_diameter / xp_diameter) * xp_to_film;
}

}  // namespace

std::unique_ptr<Camera> MakeLensCamera(const Transform& to_world, int width, int height, const LensCameraSpec& spec) {
  auto start = std::chrono::steady_clock::now();
  LensSetup setup =
      SetUpLens(spec.lens, {spec.fnumber, spec.stop_diameter, StopOpening(spec)}, Focus(spec, to_world), spec.tilt);
  if (spec.hood) {  // (checked against the lens by the scene's reader, which names the line)
    setup.lens.SetHood(spec.hood);
    setup.report += fmt::format("; hood {}", spec.hood->Describe());
  }
  const LensSystem& lens = setup.lens;
  if (!(lens.BackFocus() > 0))
    throw InputError(fmt::format("{} images {:.4g} mm {} its last surface (back focus {:.4g} mm): no film can lie there",
                                 spec.lens.Described(), std::abs(lens.BackFocus()), lens.BackFocus() < 0 ? "inside" : "on",
                                 lens.BackFocus()));
  spdlog::info("{}", setup.report);
  std::unique_ptr<Camera> camera;
  LensCameraSettings settings = spec.settings;
  if (spec.model == LensModel::kReal) {
    if (spec.convergence_mm > 0) {
      // The shift is horizontal: an anamorphic lens's x-z section's pupils.
      const ParaxialData p = spec.lens.HasToroids() ? XSectionSystem(lens).paraxial() : lens.paraxial();
      const double xp_z = lens.VertexZ(lens.SurfaceCount() - 1) + p.exit_pupil_position;
      settings.shift.x += ChiefRayFilmX(spec.eye_offset_mm, spec.convergence_mm, p.entrance_pupil_diameter,
                                        p.exit_pupil_diameter, lens.FilmZ() - xp_z);
    }
    auto real = std::make_unique<RealisticCamera>(to_world, width, height, lens, settings);
    if (real->dispersive()) spdlog::debug("lens {}: dispersive glass, one wavelength per camera ray", spec.lens.name);
    camera = std::move(real);
  } else {
    // The thin and thick models put nodal points on the principal planes: true in air only.
    // Nor do they know a mirror lens's central obstruction (their pupil is a full disc).
    const char* model = spec.model == LensModel::kThin ? "thin" : "thick";
    if (spec.lens.object_medium)
      throw InputError(fmt::format("lens_model {}: the paraxial models need air in front of the lens; {} looks into "
                                   "another medium (its object_medium): use lens_model real",
                                   model, spec.lens.name));
    if (spec.tilt)
      throw InputError(fmt::format("lens_model {}: the paraxial models cannot be tilted (tilt_x, tilt_y): use lens_model "
                                   "real", model));
    if (!spec.lens.RotationallySymmetric())
      throw InputError(fmt::format("lens_model {}: the paraxial models are rotationally symmetric; {} is not ({}): "
                                   "use lens_model real", model, spec.lens.name,
                                   spec.lens.HasToroids()      ? "anamorphic, toroidal surfaces"
                                   : spec.lens.HasFormErrors() ? "surfaces with form errors"
                                   : spec.lens.HasTurnedCrystals() ? "a crystal whose optic axis is not the lens's"
                                                               : "decentred or tilted surfaces"));
    for (const LensSurface& s : spec.lens.surfaces)
      if (s.obscuration > 0)
        throw InputError(fmt::format("lens_model {}: the paraxial models have no central obstruction, which {} has: "
                                     "use lens_model real", model, spec.lens.name));
    if (std::any_of(spec.lens.surfaces.begin(), spec.lens.surfaces.end(), [](const LensSurface& s) { return bool(s.dirt); }))
      spdlog::warn("lens_model {}: {} has dust or scratches on its surfaces, which the paraxial models (no surfaces) "
                   "leave out: use lens_model real", model, spec.lens.name);
    if (spec.lens.CrystalCount() > 0)
      spdlog::warn("lens_model {}: {} has birefringent crystals, whose second (extraordinary) image the paraxial models "
                   "leave out: use lens_model real", model, spec.lens.name);
    ParaxialLensModel m = MakeParaxialModel(lens, setup.focus.plane_of_focus_to_film, spec.model == LensModel::kThin);
    if (spec.convergence_mm > 0)
      settings.shift.x += ChiefRayFilmX(spec.eye_offset_mm, spec.convergence_mm, m.entrance_pupil_radius,
                                        m.exit_pupil_radius, m.film_z - m.exit_pupil_z);
    camera = std::make_unique<ParaxialLensCamera>(to_world, width, height, m, lens.stop_shape(), settings);
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  spdlog::info("lens camera set up in {:.3f} s", seconds);
  return camera;
}

}  // namespace objektiv
