#include "camera/lens_camera_setup.h"

#include <chrono>
#include <cmath>

#include "base/error.h"
#include "base/log.h"
#include "camera/paraxial_lens_camera.h"
#include "camera/realistic_camera.h"
#include "optics/dispersion.h"
#include "optics/paraxial.h"
#include "optics/real_fnumber.h"
#include "optics/real_focus.h"

namespace objektiv {

double WideOpenFNumber(const LensPrescription& lens) { return RealFNumber(LensTracer(lens)); }

namespace {

// The stop's opening: the iris, cut to where the aperture mask lets light through.
StopShape StopOpening(const LensCameraSpec& spec) {
  StopShape shape = StopShape::Iris(spec.blades, spec.blade_curvature, spec.blade_rotation * M_PI / 180);
  if (spec.settings.aperture_mask) shape.Cut(spec.settings.aperture_mask->OpenHull());
  return shape;
}

// The lens with its stop set as asked; `fnumber` receives the f-number of the round stop
// (before blades are put in).
LensTracer StoppedDown(const LensCameraSpec& spec, double* fnumber) {
  LensTracer tracer(spec.lens);
  const double full = tracer.StopSemiDiameter();
  if (spec.stop_diameter > 0) {
    if (spec.stop_diameter / 2 > full * (1 + 1e-9))
      throw InputError(fmt::format("stop diameter {} mm is larger than {}'s stop ({:.4g} mm)", spec.stop_diameter,
                                   spec.lens.name, 2 * full));
    tracer.SetStopSemiDiameter(spec.stop_diameter / 2);
  } else if (spec.fnumber > 0) {
    std::optional<double> semi = StopSemiDiameterForFNumber(tracer, spec.fnumber);
    if (!semi) {
      // A lens sold as f/2.8 may open to f/2.81 by the real rays: a request within 2% of the
      // widest aperture means wide open.
      const double wide_open = WideOpenFNumber(spec.lens);
      if (spec.fnumber < wide_open / 1.02)
        throw InputError(fmt::format("f/{} is faster than {} opens (f/{:.3g})", spec.fnumber, spec.lens.name, wide_open));
      spdlog::info("lens {}: f/{} taken as wide open (f/{:.3g})", spec.lens.name, spec.fnumber, wide_open);
      semi = full;
    }
    tracer.SetStopSemiDiameter(*semi);
  }
  *fnumber = RealFNumber(tracer);
  tracer.SetStopShape(StopOpening(spec));
  return tracer;
}

// Film-to-object distance (mm) for focusing on the plane through a world point: its depth
// along the view axis from the entrance pupil plus the pupil's distance from the film, which
// itself depends on where the lens goes (a few rounds settle it).
double FocusPointDistance(const LensTracer& tracer, const Transform& to_world, Vec3f point, double metres_per_unit) {
  Vec3f origin = to_world.Point(Vec3f(0, 0, 0)), forward = Normalize(to_world.Vector(Vec3f(0, 0, 1)));
  double depth = Dot(point - origin, forward) * metres_per_unit * 1e3;  // mm in front of the entrance pupil
  if (!(depth > 0)) throw InputError("focus_point lies behind the camera");
  ParaxialData p = ComputeParaxial(tracer.lens(), kLambdad, tracer.StopSemiDiameter());
  // First-order focusing is enough here: the pupil moves by the focusing travel, a few mm on a
  // distance of metres, and real rays move it by a fraction of that.
  LensTracer t = tracer;
  double distance = depth;
  for (int round = 0; round < 6; ++round) {
    t.SetBackFocus(ParaxialFocus(t.lens(), distance).back_focus);
    double pupil_to_film = t.FilmZ() - (t.VertexZ(0) + p.entrance_pupil_position);
    distance = depth + pupil_to_film;
  }
  return distance;
}

}  // namespace

std::unique_ptr<Camera> MakeLensCamera(const Transform& to_world, int width, int height, const LensCameraSpec& spec) {
  auto start = std::chrono::steady_clock::now();
  double fnumber = 0;
  LensTracer tracer = StoppedDown(spec, &fnumber);
  ParaxialData p = ComputeParaxial(spec.lens, kLambdad, tracer.StopSemiDiameter());
  double distance = spec.focus_point
                        ? FocusPointDistance(tracer, to_world, *spec.focus_point, spec.settings.metres_per_unit)
                        : spec.focus_distance * 1e3;
  LensFocus focus = FocusLens(tracer, distance);
  tracer.SetBackFocus(focus.back_focus);
  spdlog::info("lens {}: EFL {:.2f} mm, f/{:.3g} (paraxial f/{:.3g}){}; {}", spec.lens.name, p.efl, fnumber, p.fnumber,
               spec.blades >= 3 ? fmt::format(", {} blades", spec.blades) : "", DescribeFocus(focus, p.bfl));
  std::unique_ptr<Camera> camera;
  if (spec.model == LensModel::kReal) {
    auto real = std::make_unique<RealisticCamera>(to_world, width, height, tracer, spec.settings);
    if (real->dispersive()) spdlog::debug("lens {}: dispersive glass, one wavelength per camera ray", spec.lens.name);
    camera = std::move(real);
  } else {
    ParaxialLensModel m = MakeParaxialModel(tracer, focus.object_distance, spec.model == LensModel::kThin);
    camera = std::make_unique<ParaxialLensCamera>(to_world, width, height, m, tracer.stop_shape(), spec.settings);
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  spdlog::info("lens camera set up in {:.3f} s", seconds);
  return camera;
}

}  // namespace objektiv
