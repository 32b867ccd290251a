#include "camera/lens_camera_setup.h"

#include <chrono>
#include <cmath>

#include "base/error.h"
#include "base/log.h"
#include "camera/paraxial_lens_camera.h"
#include "camera/realistic_camera.h"
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

}  // namespace

std::unique_ptr<Camera> MakeLensCamera(const Transform& to_world, int width, int height, const LensCameraSpec& spec) {
  auto start = std::chrono::steady_clock::now();
  LensSetup setup = SetUpLens(spec.lens, {spec.fnumber, spec.stop_diameter, StopOpening(spec)}, Focus(spec, to_world));
  const LensSystem& lens = setup.lens;
  spdlog::info("{}", setup.report);
  std::unique_ptr<Camera> camera;
  if (spec.model == LensModel::kReal) {
    auto real = std::make_unique<RealisticCamera>(to_world, width, height, lens, spec.settings);
    if (real->dispersive()) spdlog::debug("lens {}: dispersive glass, one wavelength per camera ray", spec.lens.name);
    camera = std::move(real);
  } else {
    ParaxialLensModel m = MakeParaxialModel(lens, setup.focus.plane_of_focus_to_film, spec.model == LensModel::kThin);
    camera = std::make_unique<ParaxialLensCamera>(to_world, width, height, m, lens.stop_shape(), spec.settings);
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  spdlog::info("lens camera set up in {:.3f} s", seconds);
  return camera;
}

}  // namespace objektiv
