#include "render/direct_lighting.h"
#include "render/integrator.h"

namespace objektiv {

SampledSpectrum DirectIntegrator::Li(const Ray& ray, const std::optional<SurfaceInteraction>& si,
                                     SampledWavelengths& lambda, Sampler& sampler, BlockContext& ctx) const {
  RayCounts& counts = ctx.rays();
  SampledSpectrum L(0.f);
  if (!si) {
    for (const InfiniteLight* light : scene_.infinite_lights()) L += light->Le(ray.d, lambda);
    return L;
  }
  SampledSpectrum tr = SegmentTransmittance(ray, *si, lambda);
  L += EmittedRadiance(*si, lambda);
  const Material* material = si->shape->material.get();
  if (!material) return L * tr;
  BSDF bsdf = material->GetBSDF(*si, lambda);
  float ne = float(emitter_samples_), nb = float(bsdf_samples_);

  for (int i = 0; i < emitter_samples_; ++i) {
    float ul = scene_.lights().size() > 1 ? sampler.Get1D() : 0.5f;
    Vec2f u = sampler.Get2D();
    if (bsdf.Flags() & (kDiffuse | kGlossy)) L += SampleLightMIS(scene_, *si, bsdf, lambda, ul, u, counts, ne, nb);
  }
  for (int i = 0; i < bsdf_samples_; ++i) {
    float uc = bsdf.UsesLobeChoice() ? sampler.Get1D() : 0.5f;
    Vec2f u = sampler.Get2D();
    std::optional<BSDFSample> bs = bsdf.Sample(si->wo, uc, u);
    if (!bs) continue;
    SampledSpectrum beta = bs->f * (AbsDot(bs->wi, bsdf.frame().n) / bs->pdf) / nb;
    Ray next = si->SpawnRay(bs->wi);
    ++counts.closest;
    std::optional<SurfaceInteraction> hit = scene_.Intersect(next);
    // A specular sample can only find an emitter this way: full weight.
    auto weight = [&](float light_pdf) {
      if (bs->IsSpecular() || ne == 0) return 1.f;
      return PowerHeuristic(nb * bs->pdf, ne * light_pdf);
    };
    if (!hit) {
      for (const InfiniteLight* light : scene_.infinite_lights()) {
        SampledSpectrum Le = light->Le(next.d, lambda);
        if (!Le.IsBlack()) L += beta * Le * weight(scene_.LightPmf(light) * light->PdfLi(next.d));
      }
      continue;
    }
    SampledSpectrum Le = EmittedRadiance(*hit, lambda);
    if (!Le.IsBlack())
      L += beta * SegmentTransmittance(next, *hit, lambda) * Le * weight(AreaLightPdf(scene_, si->p, *hit));
  }
  return L * tr;
}

}  // namespace objektiv
