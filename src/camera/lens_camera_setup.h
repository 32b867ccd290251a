// Setting up a camera from a lens prescription: the stop (f-number or diameter, blades), the
// focus (the lens moved as a whole, real rays, logged) and the model (the real lens, or the
// thick- or thin-lens camera from its paraxial data).
#pragma once
#include <memory>
#include <optional>

#include "camera/lens_camera.h"
#include "optics/lens_setup.h"

namespace objektiv {

enum class LensModel { kReal, kThick, kThin };

struct LensCameraSpec {
  LensPrescription lens;
  LensModel model = LensModel::kReal;
  double fnumber = 0;        // radiometric (see optics/real_fnumber.h); 0: wide open (or stop_diameter)
  double stop_diameter = 0;  // mm; 0: from the f-number
  int blades = 0;            // 0: circular
  double blade_curvature = 0, blade_rotation = 0;  // 0..1, degrees
  double focus_distance = INFINITY;  // metres from the film
  std::optional<Vec3f> focus_point;  // world space: focus on the plane through it instead
  std::optional<SurfacePlacement> tilt;  // a tilt-shift lens's tilt (optics/lens_setup.h: SetUpLens)
  std::optional<LensHood> hood;          // a lens hood on the front (optics/lens_hood.h); real lens only
  LensCameraSettings settings;
  // A stereo eye's offset along the camera's x axis and the convergence distance from the
  // entrance pupil (mm; 0: parallel): the sensor is shifted sideways (as a shift lens) by the
  // paraxial image height of the rig's axis point at that distance, so that it images at the
  // film's centre in both eyes. The camera itself is moved by whoever gives to_world.
  double eye_offset_mm = 0, convergence_mm = 0;
};

// Throws InputError (without a location) when the stop cannot be set as asked.
std::unique_ptr<Camera> MakeLensCamera(const Transform& to_world, int width, int height, const LensCameraSpec& spec);

}  // namespace objektiv
