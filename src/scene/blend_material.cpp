#include "scene/blend_material.h"

#include <algorithm>

namespace objektiv {

float TextureWeight(const SpectrumTexture& t, Vec2f uv) {
  const float w = Luminance(t.Rgb(uv));
  return std::isnan(w) ? 0.f : std::clamp(w, 0.f, 1.f);
}

float BlendMaterial::Opacity(const SurfaceInteraction& si) const {
  const float w = TextureWeight(*weight_, si.uv);
  return (1 - w) * a_->Opacity(si) + w * b_->Opacity(si);
}

BSDF BlendMaterial::GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const {
  float w = TextureWeight(*weight_, si.uv);
  if (HasOpacity()) {
    const float oa = a_->Opacity(si), ob = b_->Opacity(si), stopped = (1 - w) * oa + w * ob;
    if (stopped > 0) w = w * ob / stopped;
  }
  if (w <= 0) return a_->GetBSDF(si, lambda);
  if (w >= 1) return b_->GetBSDF(si, lambda);
  BSDF a = a_->GetBSDF(si, lambda);
  BSDF b = b_->GetBSDF(si, lambda);
  return BSDF::Blend(si.shading, std::move(a), std::move(b), w);
}

}  // namespace objektiv
