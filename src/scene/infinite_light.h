// Lights at infinity that rays escaping the scene see: constant and image-based (envmap).
#pragma once
#include "base/image.h"
#include "base/sampling.h"
#include "base/transform.h"
#include "scene/light.h"

namespace objektiv {

class InfiniteLight : public Light {
 public:
  bool IsInfinite() const override { return true; }
  void Preprocess(const Bounds3f& b) override {
    scene_center_ = b.Empty() ? Vec3f(0.f) : b.Center();
    scene_radius_ = std::max(b.Radius(), 1e-3f);
  }
  // Radiance arriving along a ray that escaped in direction w.
  virtual SampledSpectrum Le(const Vec3f& w, const SampledWavelengths& lambda) const = 0;
  virtual float PdfLi(const Vec3f& w) const = 0;
  // A direction chosen as SampleLi chooses it, the ray's origin uniform over the disc across
  // the scene's bounding sphere, facing it from outside.
  std::optional<LightLeSample> SampleLe(Vec2f u_pos, Vec2f u_dir, const SampledWavelengths& lambda) const override;

 protected:
  Vec3f scene_center_{0.f};
  float scene_radius_ = 1;
};

class ConstantEnvironment final : public InfiniteLight {
 public:
  explicit ConstantEnvironment(Spectrum radiance) : radiance_(std::move(radiance)) {}
  std::optional<LightSample> SampleLi(const Vec3f& ref, Vec2f u, const SampledWavelengths& lambda) const override;
  SampledSpectrum Le(const Vec3f&, const SampledWavelengths& lambda) const override { return radiance_.Sample(lambda); }
  float PdfLi(const Vec3f&) const override { return UniformSpherePdf(); }
  float Power() const override;

 private:
  Spectrum radiance_;
};

// Latitude-longitude environment map in Mitsuba's convention (y up in the light's frame;
// u = atan2(x, -z) / 2pi, v = acos(y) / pi), importance-sampled by luminance * sin(theta).
class EnvironmentMap final : public InfiniteLight {
 public:
  EnvironmentMap(Image rgb, float scale, const Transform& to_world);
  std::optional<LightSample> SampleLi(const Vec3f& ref, Vec2f u, const SampledWavelengths& lambda) const override;
  SampledSpectrum Le(const Vec3f& w, const SampledWavelengths& lambda) const override;
  float PdfLi(const Vec3f& w) const override;
  float Power() const override;

 private:
  Vec2f DirectionToUv(const Vec3f& w_world) const;
  Vec3f UvToDirection(Vec2f uv) const;
  Vec3f Lookup(Vec2f uv) const;
  Image image_;
  float scale_;
  Transform to_world_, to_local_;
  Distribution2D distribution_;
  float mean_y_ = 0;
};

}  // namespace objektiv
