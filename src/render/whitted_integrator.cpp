#include "render/whitted_integrator.h"

#include <algorithm>
#include <cmath>

#include "render/direct_lighting.h"
#include "scene/infinite_light.h"

namespace objektiv {

namespace {

// Point k of an n x n grid's cell centres, all moved by one random offset (wrapping around):
// every point is uniform over [0,1)^2 (over the light, or the BSDF's directions), and the n x n
// of them cover it evenly.
Vec2f GridPoint(int k, int grid, Vec2f offset) {
  Vec2f u(((k % grid) + 0.5f) / grid + offset.x, ((k / grid) + 0.5f) / grid + offset.y);
  u.x -= std::floor(u.x);
  u.y -= std::floor(u.y);
  return Vec2f(std::min(u.x, 0x1.fffffep-1f), std::min(u.y, 0x1.fffffep-1f));
}

}  // namespace

SampledSpectrum WhittedIntegrator::Li(const Ray& ray, const std::optional<SurfaceInteraction>& si,
                                      SampledWavelengths& lambda, Sampler& sampler, BlockContext& ctx) const {
  SampledSpectrum L = DirectEmission(ray, si, lambda);
  if (!si) return L;
  RayMemo& rays = memos_.local();
  rays.Begin(scene_, ray, ctx.rays(), settings_.wavelength_sets > 1);
  return L + SegmentTransmittance(ray, *si, lambda) * Shade(*si, lambda, sampler, rays, SampledSpectrum(1.f), 1);
}

SampledSpectrum WhittedIntegrator::Shade(const SurfaceInteraction& si, SampledWavelengths& lambda, Sampler& sampler,
                                         RayMemo& rays, const SampledSpectrum& weight, int segments) const {
  // Each shadow ray and each reflected or refracted ray is one segment more.
  if (segments + 1 > settings_.max_depth) return {};
  const Material* material = si.shape->material.get();
  if (!material) return {};
  const BSDF bsdf = material->GetBSDF(si, lambda);
  SampledSpectrum L(0.f);
  if (bsdf.Flags() & (kDiffuse | kGlossy)) {
    L += LightFromSources(si, bsdf, lambda, sampler, rays);
    if (settings_.ambient) L += settings_.ambient->Sample(lambda) * bsdf.DiffuseReflectance(si.wo);
  }
  SpecularLobe lobes[kMaxSpecularLobes];
  const int n = bsdf.SpecularLobes(si.wo, lobes);
  for (int i = 0; i < n; ++i) {
    const SampledSpectrum w = weight * lobes[i].weight;
    if (w.Max() < settings_.bailout) continue;
    const Ray ray = si.SpawnRay(lobes[i].wi);
    const std::optional<SurfaceInteraction> hit = rays.Intersect(ray);
    SampledSpectrum Li(0.f);
    if (!hit) {
      for (const InfiniteLight* light : scene_.infinite_lights()) Li += light->Le(ray.d, lambda);
    } else {
      Li = EmittedRadiance(*hit, lambda) + Shade(*hit, lambda, sampler, rays, w, segments + 1);
      Li *= SegmentTransmittance(ray, *hit, lambda);
    }
    L += lobes[i].weight * Li;
  }
  if ((bsdf.Flags() & kGlossy) && (bsdf.Flags() & kTransmission))
    L += GlossyTransmission(si, bsdf, lambda, sampler, rays, weight, segments);
  return L;
}

SampledSpectrum WhittedIntegrator::GlossyTransmission(const SurfaceInteraction& si, const BSDF& bsdf,
                                                      SampledWavelengths& lambda, Sampler& sampler, RayMemo& rays,
                                                      const SampledSpectrum& weight, int segments) const {
  const float uc = sampler.Get1D();
  const Vec2f u = sampler.Get2D();
  const std::optional<BSDFSample> bs = bsdf.Sample(si.wo, uc, u);
  if (!bs || bs->IsSpecular() || !bs->IsTransmission() || !(bs->pdf > 0)) return {};
  const SampledSpectrum t = bs->f * (AbsDot(bs->wi, bsdf.frame().n) / bs->pdf);
  const SampledSpectrum w = weight * t;
  if (!(w.Max() >= settings_.bailout)) return {};
  const Ray ray = si.SpawnRay(bs->wi);
  const std::optional<SurfaceInteraction> hit = rays.Intersect(ray);
  if (!hit) return {};  // the sky through it: BsdfSamplesOfLight's
  return t * SegmentTransmittance(ray, *hit, lambda) * Shade(*hit, lambda, sampler, rays, w, segments + 1);
}

SampledSpectrum WhittedIntegrator::LightFromSources(const SurfaceInteraction& si, const BSDF& bsdf,
                                                    const SampledWavelengths& lambda, Sampler& sampler,
                                                    RayMemo& rays) const {
  const Vec3f n = bsdf.frame().n;  // a bump map may have turned it
  auto visible = [&](const Ray& ray) { return !rays.Occluded(ray); };
  const int grid = std::max(1, settings_.shadow_grid), count = grid * grid;
  // A glossy lobe (Phong, rough metal and glass) is also sampled by the BSDF, as many times as
  // the light, the two combined by the power heuristic: light samples alone put a sharp
  // highlight of a large light (the sky) on a few of them, which glitters.
  const bool glossy = bsdf.Flags() & kGlossy;
  SampledSpectrum L(0.f);
  for (const auto& light : scene_.lights()) {
    if (light->IsDelta()) {  // one shadow ray: a hard shadow
      const std::optional<LightSample> ls = light->SampleLi(si.p, Vec2f(0.5f, 0.5f), lambda);
      if (!ls || ls->pdf == 0 || ls->L.IsBlack()) continue;
      const SampledSpectrum f = bsdf.f(si.wo, ls->wi) * AbsDot(ls->wi, n);
      if (!f.IsBlack() && visible(ls->infinite ? si.SpawnRay(ls->wi) : si.SpawnRayTo(ls->p, ls->p_error, ls->n)))
        L += f * ls->L / ls->pdf;
      continue;
    }
    const Vec2f offset = sampler.Get2D();
    SampledSpectrum sum(0.f);
    for (int k = 0; k < count; ++k) {
      const std::optional<LightSample> ls = light->SampleLi(si.p, GridPoint(k, grid, offset), lambda);
      if (!ls || ls->pdf == 0 || ls->L.IsBlack()) continue;
      const BSDF::Evaluation e = bsdf.EvalWithPdf(si.wo, ls->wi);
      const SampledSpectrum f = e.f * AbsDot(ls->wi, n);
      if (f.IsBlack() || !visible(ls->infinite ? si.SpawnRay(ls->wi) : si.SpawnRayTo(ls->p, ls->p_error, ls->n)))
        continue;
      const float w = glossy ? PowerHeuristic(ls->pdf, e.pdf) : 1.f;
      sum += f * ls->L * (w / ls->pdf);
    }
    if (glossy) sum += BsdfSamplesOfLight(si, bsdf, *light, lambda, sampler, rays);
    L += sum / float(count);
  }
  return L;
}

SampledSpectrum WhittedIntegrator::BsdfSamplesOfLight(const SurfaceInteraction& si, const BSDF& bsdf, const Light& light,
                                                      const SampledWavelengths& lambda, Sampler& sampler,
                                                      RayMemo& rays) const {
  const int grid = std::max(1, settings_.shadow_grid);
  const Vec2f offset = sampler.Get2D();
  const float uc0 = sampler.Get1D();
  // Called for the lights that are not delta (not point, spot or directional): an environment,
  // or a shape's area light.
  const auto* infinite = light.IsInfinite() ? static_cast<const InfiniteLight*>(&light) : nullptr;
  const auto* area = infinite ? nullptr : static_cast<const AreaLight*>(&light);
  SampledSpectrum sum(0.f);
  for (int k = 0; k < grid * grid; ++k) {
    const float uc = std::min((k + uc0) / float(grid * grid), 0x1.fffffep-1f);  // the lobe choice, stratified too
    const std::optional<BSDFSample> bs = bsdf.Sample(si.wo, uc, GridPoint(k, grid, offset));
    if (!bs || bs->IsSpecular()) continue;
    const Ray ray = si.SpawnRay(bs->wi);
    const std::optional<SurfaceInteraction> hit = rays.Intersect(ray);
    SampledSpectrum Le;
    float light_pdf = 0;
    if (hit) {
      if (!area || hit->shape->area_light != area) continue;
      Le = EmittedRadiance(*hit, lambda) * SegmentTransmittance(ray, *hit, lambda);
      light_pdf = area->PdfLi(si.p, *hit);
    } else {
      if (!infinite) continue;
      Le = infinite->Le(ray.d, lambda);
      light_pdf = infinite->PdfLi(ray.d);
    }
    if (Le.IsBlack()) continue;
    const SampledSpectrum f = bs->f * AbsDot(bs->wi, bsdf.frame().n);
    sum += f * Le * (PowerHeuristic(bs->pdf, light_pdf) / bs->pdf);
  }
  return sum;
}

}  // namespace objektiv
