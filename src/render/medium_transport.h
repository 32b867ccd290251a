// Light through participating media (scene/medium.h) for the path tracer: transmittance along
// shadow rays, and next-event estimation from a scattering point inside a medium.
//
// A shadow ray passes surfaces with a `null` BSDF (medium boundaries), crossing into the medium
// on their far side, and multiplies the transmittance exp(-sigma_t d) of every medium segment
// (per wavelength; homogeneous media need no tracking); any other surface blocks it.
#pragma once
#include "render/integrator.h"

namespace objektiv {

// Null surfaces a ray may cross before it is given up as caught (a ray grazing along a
// boundary, or geometry layered thousands deep): beyond, a shadow ray counts as blocked
// and a path ends.
inline constexpr int kMaxNullCrossings = 1000;

// Transmittance along `ray` up to ray.tmax (in units of ray.d) that starts in `medium`.
SampledSpectrum Transmittance(const Scene& scene, Ray ray, const Medium* medium, const SampledWavelengths& lambda,
                              RayCounts& counts);

// A scattering point inside a medium: where, the direction back along the arriving ray, and
// the medium.
struct MediumVertex {
  Vec3f p, wo;
  const Medium* medium;
};

// Next-event estimate at a medium vertex: one light chosen by power, one point on it, the
// transmittance toward it; weighted against phase-function sampling by the power heuristic
// (as SampleLightMIS against BSDF sampling). Returns phase x Tr x L x weight / pdf.
SampledSpectrum SampleLightFromMedium(const Scene& scene, const MediumVertex& v, const SampledWavelengths& lambda,
                                      float u_light, Vec2f u, RayCounts& counts);

}  // namespace objektiv
