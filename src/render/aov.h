// Arbitrary output variables: what the camera ray's first hit is, beside the radiance, as
// Mitsuba 3's `aov` integrator gives them (`<integrator type="aov">` with `aovs` =
// "name:type,..." and the integrator of the image nested in it). Each pixel holds its camera
// rays' values averaged with the filter's weights; a ray that hits nothing counts zero, a
// sample that starts no ray (through a real lens: stopped by a rim or the stop) is left out
// (a pixel that no ray leaves holds zero).
//   depth       the distance along the camera ray from where it starts   channel NAME
//               (the near clip plane; the realistic camera: its front element) to the hit
//   position    the hit point (world)                                     NAME.X, .Y, .Z
//   uv          the surface's texture coordinates                         NAME.U, .V
//   geo_normal  the geometric normal (world, unit)                        NAME.X, .Y, .Z
//   sh_normal   the shading normal (world, unit)                          NAME.X, .Y, .Z
//   albedo      the surface's reflectance toward the camera: the fraction NAME.R, .G, .B
//               of light from all directions it scatters toward the camera (reflected
//               and transmitted: white diffuse 1, clear glass 1, a tinted metal its tint),
//               estimated with one BSDF sample per camera sample (its own random numbers:
//               the image stays the nested integrator's) at the sample's wavelengths; the
//               film keeps XYZ under D65 (Y = 1 for a reflectance of 1), written as RGB of
//               the film's colour space, where D65 is white: a reflectance of 1 is (1, 1, 1)
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/integrator.h"

namespace objektiv {

enum class AovType { kDepth, kPosition, kUv, kGeoNormal, kShNormal, kAlbedo };

struct Aov {
  std::string name;
  AovType type;
  int Channels() const { return type == AovType::kDepth ? 1 : type == AovType::kUv ? 2 : 3; }
  std::vector<std::string> ChannelNames() const;
};

// "dd.y:depth,nn:sh_normal" -> the AOVs; throws std::invalid_argument naming what is wrong.
std::vector<Aov> ParseAovs(const std::string& text);

// The nested integrator's image, and the AOVs of every camera sample's first hit.
class AovIntegrator final : public CameraPathIntegrator {
 public:
  AovIntegrator(const Scene& scene, std::vector<Aov> aovs, std::unique_ptr<CameraPathIntegrator> inner)
      : CameraPathIntegrator(scene), aovs_(std::move(aovs)), inner_(std::move(inner)) {}
  SampledSpectrum Li(const Ray& ray, const std::optional<SurfaceInteraction>& first_hit, SampledWavelengths& lambda,
                     Sampler& sampler, BlockContext& ctx) const override {
    return inner_->Li(ray, first_hit, lambda, sampler, ctx);
  }
  void TraceLightPaths(Sampler& sampler, BlockContext& ctx) const override { inner_->TraceLightPaths(sampler, ctx); }
  bool TracesLightToCamera() const override { return inner_->TracesLightToCamera(); }
  bool LightsTheSceneItself() const override { return inner_->LightsTheSceneItself(); }
  // The image is the inner integrator's; the AOVs stay those of the first surface hit (a null
  // medium boundary included), which the loader warns about.
  bool RendersMedia() const override { return inner_->RendersMedia(); }
  int WavelengthSets() const override { return inner_->WavelengthSets(); }
  bool NearlyNoiseFree() const override { return inner_->NearlyNoiseFree(); }
  int AovChannels() const override;
  // The AOVs' exact sums in the film, then their float channels in the image (twice: the
  // image is copied): 16 + 2 x 4 bytes per channel and the weight.
  uint64_t BytesPerPixel() const override { return uint64_t(AovChannels() + 1) * (16 + 2 * 4); }
  void EvaluateAovs(const Ray& ray, const std::optional<SurfaceInteraction>& hit, const SampledWavelengths& lambda,
                    uint64_t seed, float* out) const override;
  const std::vector<Aov>& aovs() const { return aovs_; }

 private:
  std::vector<Aov> aovs_;
  std::unique_ptr<CameraPathIntegrator> inner_;
};

}  // namespace objektiv
