// A path through the lens chosen at random, as the light itself divides: entering from the
// object side, the ray meets one surface after another; at each interface it is reflected with
// some probability q and refracted otherwise (always reflected beyond the critical angle),
// until it reaches the film plane, leaves the lens toward the object, or is stopped by a rim
// or the stop. Every sequence of reflections (the direct image, each two-reflection ghost,
// the four-reflection veiling glare, ...) comes out with the probability of its choices, and
// the walk's weight corrects that to the light's own share: R / q at each reflection,
// (1 - R) / (1 - q) at each refraction, times the glasses' absorption and the stop's
// transmittance (an aperture mask) at each crossing. With q = R the weight is the absorption
// alone (the light's own odds); a larger q sends more walks into the dim reflected paths, at
// the cost of weights below one on them.
//
// Lens space: millimetres, z toward the film (optics/lens_tracer.h).
#pragma once
#include <functional>
#include <optional>

#include "base/rng.h"
#include "optics/lens_tracer.h"

namespace objektiv {

struct LensWalkOptions {
  // The probability of reflecting at an interface of reflectance R: max(R, min_reflect_probability).
  double min_reflect_probability = 0;
  // Walks that would reflect more often than this stop there (their light is lost).
  int max_reflections = 8;
  // Without the surfaces' reflections and the glasses' absorption (the camera's
  // `transmission false`): the walk never reflects.
  bool lossless = false;
  // The stop's transmittance at (u, v) in stop radii where its opening lets light through (an
  // aperture mask's grey levels); none: 1.
  std::function<double(double u, double v)> stop_transmittance;
};

struct LensWalk {
  std::optional<LensRay> film;  // where the ray meets the film plane, and its direction there
  double weight = 0;            // see above; 0 where the light does not reach the film
  int reflections = 0;
};

// From the object side (ray.d.z > 0, in front of the first surface).
LensWalk WalkFromObject(const LensSystem& lens, const LensRay& ray, double lambda_nm, PCG32& rng,
                        const LensWalkOptions& options = {});

}  // namespace objektiv
