// Building blocks shared by the integrators: light sampling with MIS, emission at hits.
#pragma once
#include "render/integrator.h"

namespace objektiv {

// Next-event estimate at si: one light chosen by power, one point on it, a shadow ray.
// The MIS weight against BSDF sampling uses the power heuristic with the given sample
// counts (1 and 1 for the path tracer); bsdf_count = 0 disables MIS. In a scene with media
// (Scene::HasMedia) the shadow ray carries their transmittance (render/medium_transport.h),
// starting in the medium on the light's side of the surface (`medium`: the one the path
// arrived in).
SampledSpectrum SampleLightMIS(const Scene& scene, const SurfaceInteraction& si, const BSDF& bsdf,
                               const SampledWavelengths& lambda, float u_light, Vec2f u, RayCounts& counts,
                               float light_count = 1, float bsdf_count = 1, const Medium* medium = nullptr);

// Radiance emitted by the surface at si toward the ray's origin (zero if not an emitter).
SampledSpectrum EmittedRadiance(const SurfaceInteraction& si, const SampledWavelengths& lambda);

// Density (solid angle, including the light-selection probability) with which light
// sampling from `ref` would have produced the hit si on an area light.
float AreaLightPdf(const Scene& scene, const Vec3f& ref, const SurfaceInteraction& si);

// The emission a path meets, weighted as the path tracer weights it: in full where the vertex
// before could not sample the lights (`full`: the camera, a delta bounce), else by the power
// heuristic between that vertex's BSDF sample (density bsdf_pdf, solid angle) and light
// sampling from it (at prev_p). EscapedRadiance: the environment along a ray that left the
// scene; HitEmission: an area light hit at si.
SampledSpectrum EscapedRadiance(const Scene& scene, const Ray& ray, const SampledWavelengths& lambda, bool full,
                                float bsdf_pdf);
SampledSpectrum HitEmission(const Scene& scene, const SurfaceInteraction& si, const SampledWavelengths& lambda,
                            bool full, float bsdf_pdf, const Vec3f& prev_p);

// Beer-Lambert transmittance of the segment that ended at si if it ran inside an absorbing
// dielectric (the ray hit the back of the surface).
SampledSpectrum SegmentTransmittance(const Ray& ray, const SurfaceInteraction& si, const SampledWavelengths& lambda);

}  // namespace objektiv
