// Light paths joined to the camera: the light-tracing half of the light tracer
// (render/light_tracer.h) and of the path tracer's light-traced caustics.
//
// A path: a light chosen by power, a ray of its light (Light::SampleLe), wavelengths of its own.
// Its flux starts at L |cos| / (pmf pdf_pos pdf_dir) and is multiplied per scattering by
// f |wo.ns| |wi.ng| / (|wo.ng| pdf) (Veach's adjoint BSDF for shading normals; refraction does
// not scale importance by 1/eta^2). A vertex of flux beta, seen from the camera
// (Camera::SampleImportance), sends it light of intensity J = beta f |wo.ns| |wi.ng| / |wo.ng|
// toward the lens point, which lands with the camera's importance weight; the shadow ray runs to
// the lens point. max_depth counts the segments of the whole path, the camera's included;
// Russian roulette from rr_depth on, on the throughput relative to the path's start.
//
// Which vertices are joined to the camera:
// - kAll: every vertex on a surface that is not purely specular (the light tracer);
// - kCaustics: only a path's first such vertex, after one or more specular bounces (the light
//   focused by glass and mirrors onto the surface the camera sees: L S+ D E in Heckbert's
//   notation); the path ends there. The path tracer leaves exactly these paths to it
//   (render/integrator.h, PathIntegrator).
//
// Normalisation: one light path per camera sample, the film dividing splats by the samples per
// pixel (BlockContext::LightPathScale corrects for a crop window, whose paths still land
// everywhere: those landing outside it are lost).
#pragma once
#include "render/block_context.h"
#include "scene/scene.h"

namespace objektiv {

enum class LightPathVertices { kAll, kCaustics };

struct LightPathSettings {
  int max_depth = -1, rr_depth = 5;
  LightPathVertices join = LightPathVertices::kAll;
};

// The adjoint BSDF's cosine for light scattered from wo into wi with a shading normal (the
// BSDF's, which a bump or normal map may have perturbed): what |wi.n| is where shading and
// geometry agree; 0 where wo grazes the geometric surface. Light paths and photons (sppm)
// multiply their flux by f times it over the pdf.
float ImportanceCosine(const SurfaceInteraction& si, const BSDF& bsdf, const Vec3f& wo, const Vec3f& wi);

// Traces one light path with the sampler's next numbers and splats what reaches the camera.
void TraceLightPath(const Scene& scene, const LightPathSettings& settings, Sampler& sampler, BlockContext& ctx);

}  // namespace objektiv
