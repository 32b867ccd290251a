// Mitsuba 3's `blendbsdf` and `mask`: materials made of other materials.
#pragma once
#include <memory>

#include "scene/material.h"

namespace objektiv {

// A float in [0, 1] from a texture at uv: a number as written, a colour's or bitmap's
// luminance (a weight or an opacity map), clamped.
float TextureWeight(const SpectrumTexture& t, Vec2f uv);

// (1 - weight) a + weight b (BSDF::Blend). Where a part is a mask, the part that stops the
// ray is the one shaded: the weight of b becomes w o_b / ((1 - w) o_a + w o_b) (o: opacity)
// and the blend's opacity (1 - w) o_a + w o_b.
class BlendMaterial final : public Material {
 public:
  BlendMaterial(std::shared_ptr<Material> a, std::shared_ptr<Material> b, std::shared_ptr<const SpectrumTexture> weight)
      : a_(std::move(a)), b_(std::move(b)), weight_(std::move(weight)) {}
  BSDF GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const override;
  void SetTwoSided(bool v) override {
    a_->SetTwoSided(v);
    b_->SetTwoSided(v);
  }
  float Opacity(const SurfaceInteraction& si) const override;
  bool HasOpacity() const override { return a_->HasOpacity() || b_->HasOpacity(); }
  int Leaves() const override { return a_->Leaves() + b_->Leaves(); }
  bool MayTransmit() const override { return a_->MayTransmit() || b_->MayTransmit(); }

 private:
  std::shared_ptr<Material> a_, b_;
  std::shared_ptr<const SpectrumTexture> weight_;
};

// A cut-out: the nested material where it stops a ray, nothing where it lets it pass (the
// scene decides which, with probability opacity: Scene::Intersect). Its BSDF is the nested
// one's: a ray that reaches it has been stopped.
class MaskMaterial final : public Material {
 public:
  MaskMaterial(std::shared_ptr<Material> inner, std::shared_ptr<const SpectrumTexture> opacity)
      : inner_(std::move(inner)), opacity_(std::move(opacity)) {}
  BSDF GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const override {
    return inner_->GetBSDF(si, lambda);
  }
  Frame ShadingFrame(const SurfaceInteraction& si) const override { return inner_->ShadingFrame(si); }
  void SetTwoSided(bool v) override { inner_->SetTwoSided(v); }
  const Spectrum* Absorption() const override { return inner_->Absorption(); }
  float Opacity(const SurfaceInteraction& si) const override {
    return TextureWeight(*opacity_, si.uv) * inner_->Opacity(si);
  }
  bool HasOpacity() const override { return true; }
  int Leaves() const override { return inner_->Leaves(); }

 private:
  std::shared_ptr<Material> inner_;
  std::shared_ptr<const SpectrumTexture> opacity_;
};

}  // namespace objektiv
