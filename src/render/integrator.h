// Integrators turn blocks of work (a tile of pixels, a range of sample indices) into film
// writes: they make and trace their own rays (camera paths, light paths, photons) against the
// contract of render/block_context.h, and the renderer schedules the blocks.
#pragma once
#include "render/block_context.h"
#include "scene/scene.h"

namespace objektiv {

class Integrator {
 public:
  explicit Integrator(const Scene& scene) : scene_(scene) {}
  virtual ~Integrator() = default;
  // Takes the block's samples of every pixel of the block (ctx.ForEachPixel) and writes what
  // they estimate through ctx. Called for many blocks at once on different threads: const, with
  // whatever changes kept in locals.
  virtual void RenderBlock(BlockContext& ctx) const = 0;
  // Whether the integrator carries light to the camera from the light side
  // (Camera::SampleImportance): the scene loader refuses cameras that cannot be reached so.
  virtual bool TracesLightToCamera() const { return false; }
  // Whether it lights the scene without emitters (whitted's ambient term).
  virtual bool LightsTheSceneItself() const { return false; }
  // Whether one sample per pixel is nearly free of noise (the classic tracer), so that where a
  // pixel's samples differ the image does: what adaptive whitted subdivision is meant for.
  virtual bool NearlyNoiseFree() const { return false; }
  // Whether it follows light through participating media and across null surfaces
  // (Scene::HasMedia): the scene loader refuses such scenes to integrators that do not.
  virtual bool RendersMedia() const { return false; }
  // Memory it holds per pixel of the crop window during a render, beside the film (counted in
  // the render's memory budget with the film's own, app/render_finish.cpp).
  virtual uint64_t BytesPerPixel() const { return 0; }
  const Scene& scene() const { return scene_; }

 protected:
  const Scene& scene_;
};

// Integrators that estimate the radiance arriving along camera rays. They share the block loop
// (render/camera_path_integrator.cpp): per pixel, up to 64 samples at a time, the filter places
// each sample on the film, the camera makes their rays together (a lens traces them faster
// together) and their first hits are traced together (coherent rays: Embree packets pay); then
// Li per sample, each with its own sampler state, written as the pixel's filtered sample.
class CameraPathIntegrator : public Integrator {
 public:
  using Integrator::Integrator;
  void RenderBlock(BlockContext& ctx) const final;
  // Radiance along a camera ray whose first intersection is given (empty: a miss). Rays are
  // counted in ctx.rays(); what a path brings elsewhere on the film (a light subpath seen by
  // the camera) may be splatted through ctx.AddSplat.
  virtual SampledSpectrum Li(const Ray& ray, const std::optional<SurfaceInteraction>& first_hit,
                             SampledWavelengths& lambda, Sampler& sampler, BlockContext& ctx) const = 0;
  // Values of the first hit kept beside the image (render/aov.h): how many, and each camera
  // sample's (written to `out`, AovChannels() of them; `hit` empty: a miss), at the sample's
  // wavelengths, with `seed` for any random numbers they need (the sample's own stay the image's).
  virtual int AovChannels() const { return 0; }
  virtual void EvaluateAovs(const Ray&, const std::optional<SurfaceInteraction>&, const SampledWavelengths&, uint64_t,
                            float*) const {}
  // Light paths of the camera sample (the light tracer's): called once per camera sample,
  // after Li, whether or not the camera made a ray for it, with the sample's sampler.
  virtual void TraceLightPaths(Sampler& /*sampler*/, BlockContext& /*ctx*/) const {}

  // Wavelength sets: how many sets of kSpectrumSamples wavelengths each camera sample is
  // estimated at (1 to kMaxWavelengthSets). With n sets, a sample's wavelength number u places
  // its n x kSpectrumSamples wavelengths at u + j / (n kSpectrumSamples) (mod 1) of the visible
  // density, set k taking j = k, k + n, ...: stratified, each set alone distributed as one
  // set is; set k's hero (the wavelength dispersive glass keeps) is its (k mod 4)th, so that
  // the sets' heroes spread over the range too. Each set is a camera ray (the same one where
  // the camera does not depend on wavelength: traced to its first hit once) and a call of Li
  // with a copy of the sample's sampler started alike, so that everything but the spectra
  // repeats; the sample is the sets' average in XYZ. Four wavelengths a sample leave colour
  // noise in every pixel (a flat white's Z estimate 50% rms); sixteen, 1.7%. For an
  // integrator that repeats its paths' rays cheaply (whitted's RayMemo).
  static constexpr int kMaxWavelengthSets = 8;
  virtual int WavelengthSets() const { return 1; }

 protected:
  // The radiance along the camera ray straight from an emitter (Li's first term): what the
  // first hit emits through the segment's absorption, or the environment on a miss.
  SampledSpectrum DirectEmission(const Ray& ray, const std::optional<SurfaceInteraction>& hit,
                                 const SampledWavelengths& lambda) const;
};

// Unidirectional path tracing with next-event estimation and multiple importance sampling.
// max_depth counts path segments as Mitsuba does (1: emitters seen directly, 2: direct
// lighting, -1: unbounded); Russian roulette from rr_depth on.
//
// With `caustics`, the paths of light focused by specular surfaces onto a surface the camera
// sees directly (emitter, one or more specular bounces, then that surface: L S+ D E) are left
// to a light path per camera sample (render/light_paths.h, LightPathVertices::kCaustics), which
// finds them from point lights too and without the fireflies of small lights behind glass:
// camera paths drop an emitter they reach after a non-specular bounce at their first hit
// followed by specular bounces only. The two halves are disjoint and together are every path:
// the image converges to the same as without (test_light_tracer.cpp).
//
// Participating media (scene/medium.h): the path tracks the medium its ray travels in (the
// camera's, then changed where it leaves a surface that bounds media, by the side of the
// geometric normal it leaves toward), samples a free-flight distance in it, and where it
// scatters there estimates the direct light (next-event estimation through the media's
// transmittance, combined with phase-function sampling by the power heuristic) and samples the
// phase function for the next segment; Russian roulette as at surfaces. Surfaces with a `null`
// BSDF are stepped over without counting toward max_depth. Light paths (caustics) do not
// follow media: with caustics, a scene with media is refused.
class PathIntegrator final : public CameraPathIntegrator {
 public:
  PathIntegrator(const Scene& scene, int max_depth, int rr_depth, bool caustics = false)
      : CameraPathIntegrator(scene), max_depth_(max_depth), rr_depth_(rr_depth), caustics_(caustics) {}
  SampledSpectrum Li(const Ray& ray, const std::optional<SurfaceInteraction>& first_hit, SampledWavelengths& lambda,
                     Sampler& sampler, BlockContext& ctx) const override;
  void TraceLightPaths(Sampler& sampler, BlockContext& ctx) const override;
  bool TracesLightToCamera() const override { return caustics_; }
  bool RendersMedia() const override { return !caustics_; }

 private:
  int max_depth_, rr_depth_;
  bool caustics_;
};

// Direct illumination only: emitter and BSDF samples combined with the power heuristic
// (Mitsuba's `direct`).
class DirectIntegrator final : public CameraPathIntegrator {
 public:
  DirectIntegrator(const Scene& scene, int emitter_samples, int bsdf_samples)
      : CameraPathIntegrator(scene), emitter_samples_(emitter_samples), bsdf_samples_(bsdf_samples) {}
  SampledSpectrum Li(const Ray& ray, const std::optional<SurfaceInteraction>& first_hit, SampledWavelengths& lambda,
                     Sampler& sampler, BlockContext& ctx) const override;

 private:
  int emitter_samples_, bsdf_samples_;
};

}  // namespace objektiv
