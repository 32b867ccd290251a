// Light sources. Every light can be sampled from a reference point (next-event estimation)
// and can start a ray of its light (light tracing); area and infinite lights can also be hit
// by rays, and report the density with which they would have been sampled (for multiple
// importance sampling).
#pragma once
#include <memory>
#include <optional>

#include "base/bounds.h"
#include "base/spectrum.h"
#include "scene/interaction.h"
#include "scene/texture.h"

namespace objektiv {

class Shape;

struct LightSample {
  SampledSpectrum L;
  Vec3f wi;           // unit direction from the reference point toward the light
  float pdf = 0;      // solid angle at the reference point (or 1 for delta lights)
  Vec3f p, p_error, n;  // point on the light (for the shadow ray); n is zero for point lights
  bool infinite = false;  // shadow ray goes to infinity in direction wi
};

// A ray of a light's own light (light tracing): what the light emits along it (radiance for
// area and infinite lights, intensity for point and spot lights, irradiance for directional
// ones) and the densities with which it was chosen: of its origin (per unit area; 1 for a
// point) and of its direction (per unit solid angle at the origin; 1 for a single direction).
// Lights at infinity start their rays on a disc as wide as the scene, outside it.
struct LightLeSample {
  Ray ray;  // unit direction
  SampledSpectrum L;
  Vec3f n{0.f};  // the emitting surface's normal at the origin (area lights), zero elsewhere
  float pdf_pos = 0, pdf_dir = 0;
  // The flux the ray carries as one sample of the light's: L |cos| / (pdf_pos pdf_dir), the
  // cosine against n where the light is a surface.
  SampledSpectrum Flux() const {
    const float cos = n == Vec3f(0.f) ? 1.f : AbsDot(n, ray.d);
    return L * (cos / (pdf_pos * pdf_dir));
  }
};

class Light {
 public:
  virtual ~Light() = default;
  virtual std::optional<LightSample> SampleLi(const Vec3f& ref, Vec2f u, const SampledWavelengths& lambda) const = 0;
  // A ray leaving the light (u_pos picks its origin, u_dir its direction); nothing where the
  // light emits nothing there.
  virtual std::optional<LightLeSample> SampleLe(Vec2f u_pos, Vec2f u_dir, const SampledWavelengths& lambda) const = 0;
  // Approximate emitted power (Y), used to choose among lights.
  virtual float Power() const = 0;
  virtual bool IsDelta() const { return false; }
  virtual bool IsInfinite() const { return false; }
  // Called once the scene's bounds are known (directional and environment lights).
  virtual void Preprocess(const Bounds3f&) {}

  int index() const { return index_; }
  void set_index(int i) { index_ = i; }

 private:
  int index_ = -1;  // position in the scene's light list
};

class PointLight final : public Light {
 public:
  PointLight(const Vec3f& position, Spectrum intensity) : p_(position), intensity_(std::move(intensity)) {}
  std::optional<LightSample> SampleLi(const Vec3f& ref, Vec2f u, const SampledWavelengths& lambda) const override;
  // Uniform over the sphere of directions.
  std::optional<LightLeSample> SampleLe(Vec2f u_pos, Vec2f u_dir, const SampledWavelengths& lambda) const override;
  float Power() const override;
  bool IsDelta() const override { return true; }
  const Vec3f& position() const { return p_; }
  const Spectrum& intensity() const { return intensity_; }  // W/sr

 private:
  Vec3f p_;
  Spectrum intensity_;
};

// Mitsuba's spot: full intensity inside beam_width, smooth falloff to zero at cutoff_angle.
class SpotLight final : public Light {
 public:
  SpotLight(const Vec3f& position, const Vec3f& direction, Spectrum intensity, float cutoff_deg, float beam_width_deg);
  std::optional<LightSample> SampleLi(const Vec3f& ref, Vec2f u, const SampledWavelengths& lambda) const override;
  // Uniform over the cone of the cutoff angle.
  std::optional<LightLeSample> SampleLe(Vec2f u_pos, Vec2f u_dir, const SampledWavelengths& lambda) const override;
  float Power() const override;
  bool IsDelta() const override { return true; }
  float Falloff(const Vec3f& w_from_light) const;
  const Vec3f& position() const { return p_; }
  const Spectrum& intensity() const { return intensity_; }  // W/sr on the beam's axis

 private:
  Vec3f p_, dir_;
  Spectrum intensity_;
  float cos_cutoff_, cos_beam_, cutoff_, beam_;
};

// Parallel light arriving from one direction, irradiance per unit area perpendicular to it.
class DirectionalLight final : public Light {
 public:
  DirectionalLight(const Vec3f& direction, Spectrum irradiance) : dir_(Normalize(direction)), irradiance_(std::move(irradiance)) {}
  std::optional<LightSample> SampleLi(const Vec3f& ref, Vec2f u, const SampledWavelengths& lambda) const override;
  // Uniform over the disc across the scene's bounding sphere, facing the light.
  std::optional<LightLeSample> SampleLe(Vec2f u_pos, Vec2f u_dir, const SampledWavelengths& lambda) const override;
  float Power() const override;
  bool IsDelta() const override { return true; }
  bool IsInfinite() const override { return true; }
  void Preprocess(const Bounds3f& b) override {
    scene_center_ = b.Empty() ? Vec3f(0.f) : b.Center();
    scene_radius_ = std::max(b.Radius(), 1e-3f);
  }
  const Vec3f& direction() const { return dir_; }
  const Spectrum& irradiance() const { return irradiance_; }

 private:
  Vec3f dir_;  // direction the light travels
  Spectrum irradiance_;
  Vec3f scene_center_{0.f};
  float scene_radius_ = 1;
};

// Diffuse emission from a shape's surface (front side, or both sides).
class AreaLight final : public Light {
 public:
  AreaLight(const Shape* shape, std::shared_ptr<const SpectrumTexture> radiance, bool two_sided, float power_y)
      : shape_(shape), radiance_(std::move(radiance)), two_sided_(two_sided), power_y_(power_y) {}
  std::optional<LightSample> SampleLi(const Vec3f& ref, Vec2f u, const SampledWavelengths& lambda) const override;
  // A point uniform over the shape's area, a cosine-weighted direction on its emitting side
  // (either side with probability 1/2 when two-sided).
  std::optional<LightLeSample> SampleLe(Vec2f u_pos, Vec2f u_dir, const SampledWavelengths& lambda) const override;
  float Power() const override { return power_y_; }
  // Radiance leaving point (n, uv) toward w.
  SampledSpectrum L(const Vec3f& n, Vec2f uv, const Vec3f& w, const SampledWavelengths& lambda) const;
  float PdfLi(const Vec3f& ref, const SurfaceInteraction& hit) const;

 private:
  const Shape* shape_;
  std::shared_ptr<const SpectrumTexture> radiance_;
  bool two_sided_;
  float power_y_;
};

}  // namespace objektiv
