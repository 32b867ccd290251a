#include "render/whitted_integrator.h"

#include <algorithm>
#include <cmath>

#include "render/direct_lighting.h"

namespace objektiv {

SampledSpectrum WhittedIntegrator::Li(const Ray& ray, const std::optional<SurfaceInteraction>& si,
                                      SampledWavelengths& lambda, Sampler& sampler, BlockContext& ctx) const {
  SampledSpectrum L = DirectEmission(ray, si, lambda);
  if (!si) return L;
  return L + SegmentTransmittance(ray, *si, lambda) * Shade(*si, lambda, sampler, ctx.rays(), SampledSpectrum(1.f), 1);
}

SampledSpectrum WhittedIntegrator::Shade(const SurfaceInteraction& si, SampledWavelengths& lambda, Sampler& sampler,
                                         RayCounts& counts, const SampledSpectrum& weight, int segments) const {
  // Each shadow ray and each reflected or refracted ray is one segment more.
  if (settings_.max_depth >= 0 && segments + 1 > settings_.max_depth) return {};
  const Material* material = si.shape->material.get();
  if (!material) return {};
  const BSDF bsdf = material->GetBSDF(si, lambda);
  SampledSpectrum L(0.f);
  if (bsdf.Flags() & (kDiffuse | kGlossy)) {
    L += LightFromSources(si, bsdf, lambda, sampler, counts);
    if (settings_.ambient) L += settings_.ambient->Sample(lambda) * bsdf.DiffuseReflectance(si.wo);
  }
  SpecularLobe lobes[2];
  const int n = bsdf.SpecularLobes(si.wo, lobes);
  for (int i = 0; i < n; ++i) {
    const SampledSpectrum w = weight * lobes[i].weight;
    if (w.Max() < settings_.bailout) continue;
    const Ray ray = si.SpawnRay(lobes[i].wi);
    ++counts.closest;
    const std::optional<SurfaceInteraction> hit = scene_.Intersect(ray);
    SampledSpectrum Li(0.f);
    if (!hit) {
      for (const InfiniteLight* light : scene_.infinite_lights()) Li += light->Le(ray.d, lambda);
    } else {
      Li = EmittedRadiance(*hit, lambda) + Shade(*hit, lambda, sampler, counts, w, segments + 1);
      Li *= SegmentTransmittance(ray, *hit, lambda);
    }
    L += lobes[i].weight * Li;
  }
  return L;
}

SampledSpectrum WhittedIntegrator::LightFromSources(const SurfaceInteraction& si, const BSDF& bsdf,
                                                    const SampledWavelengths& lambda, Sampler& sampler,
                                                    RayCounts& counts) const {
  SampledSpectrum L(0.f);
  auto shadow_ray = [&](const Light& light, Vec2f u) -> SampledSpectrum {
    const std::optional<LightSample> ls = light.SampleLi(si.p, u, lambda);
    if (!ls || ls->pdf == 0 || ls->L.IsBlack()) return {};
    const SampledSpectrum f = bsdf.f(si.wo, ls->wi) * AbsDot(ls->wi, bsdf.frame().n);  // a bump map may have turned it
    if (f.IsBlack()) return {};
    ++counts.shadow;
    if (scene_.Occluded(ls->infinite ? si.SpawnRay(ls->wi) : si.SpawnRayTo(ls->p, ls->p_error, ls->n))) return {};
    return f * ls->L / ls->pdf;
  };
  const int n = std::max(1, settings_.shadow_grid);
  for (const auto& light : scene_.lights()) {
    if (light->IsDelta()) {
      L += shadow_ray(*light, Vec2f(0.5f, 0.5f));
      continue;
    }
    // The grid's cell centres, all moved by one random offset (wrapping around): every point is
    // uniform over the light, and the n x n of them cover it evenly.
    const Vec2f offset = sampler.Get2D();
    SampledSpectrum sum(0.f);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        Vec2f u((i + 0.5f) / n + offset.x, (j + 0.5f) / n + offset.y);
        u.x -= std::floor(u.x);
        u.y -= std::floor(u.y);
        sum += shadow_ray(*light, Vec2f(std::min(u.x, 0x1.fffffep-1f), std::min(u.y, 0x1.fffffep-1f)));
      }
    L += sum / float(n * n);
  }
  return L;
}

}  // namespace objektiv
