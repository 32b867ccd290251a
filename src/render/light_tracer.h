// Light tracing (Mitsuba 3's `ptracer`, pbrt-v4's `lighttracer`): paths of light from the
// emitters, every vertex on a surface that is not purely specular joined to the camera and
// splatted where its light lands on the film (render/light_paths.h). It finds what camera paths
// cannot: light focused by glass and mirrors onto diffuse surfaces (caustics), from point lights
// too, whose caustics a path tracer never sees, in the colours a dispersive prism splits white
// light into.
//
// Per camera sample (the block loop of CameraPathIntegrator): the camera ray gives what the
// camera sees of emitters directly (area lights and the environment; point lights stay
// invisible, as for the path tracer), and one light path is traced with the sample's own random
// numbers. Surfaces that are purely specular show black where the camera sees them (they take
// light on only through camera paths, which this integrator ends at the first hit): as in the
// references, a light tracer renders caustics, not what glass looks like (the path tracer's
// `caustics` option renders both).
#pragma once
#include "render/integrator.h"
#include "render/light_paths.h"

namespace objektiv {

class LightTracerIntegrator final : public CameraPathIntegrator {
 public:
  LightTracerIntegrator(const Scene& scene, int max_depth, int rr_depth)
      : CameraPathIntegrator(scene), paths_{max_depth, rr_depth, LightPathVertices::kAll} {}
  // What the camera sees of emitters directly.
  SampledSpectrum Li(const Ray& ray, const std::optional<SurfaceInteraction>& first_hit, SampledWavelengths& lambda,
                     Sampler&, BlockContext&) const override {
    return DirectEmission(ray, first_hit, lambda);
  }
  void TraceLightPaths(Sampler& sampler, BlockContext& ctx) const override {
    TraceLightPath(scene_, paths_, sampler, ctx);
  }
  bool TracesLightToCamera() const override { return true; }

 private:
  LightPathSettings paths_;
};

}  // namespace objektiv
