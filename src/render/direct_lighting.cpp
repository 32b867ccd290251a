#include "render/direct_lighting.h"

#include "render/medium_transport.h"

namespace objektiv {

SampledSpectrum SampleLightMIS(const Scene& scene, const SurfaceInteraction& si, const BSDF& bsdf,
                               const SampledWavelengths& lambda, float u_light, Vec2f u, RayCounts& counts,
                               float light_count, float bsdf_count, const Medium* medium) {
  float pmf;
  const Light* light = scene.SampleLight(u_light, &pmf);
  if (!light) return {};
  std::optional<LightSample> ls = light->SampleLi(si.p, u, lambda);
  if (!ls || ls->pdf == 0 || ls->L.IsBlack()) return {};
  BSDF::Evaluation eval = bsdf.EvalWithPdf(si.wo, ls->wi);
  SampledSpectrum f = eval.f * AbsDot(ls->wi, bsdf.frame().n);
  if (f.IsBlack()) return {};
  Ray shadow;
  if (ls->infinite) {
    shadow = si.SpawnRay(ls->wi);
  } else {
    shadow = si.SpawnRayTo(ls->p, ls->p_error, ls->n);
  }
  if (scene.HasMedia()) {
    f *= Transmittance(scene, shadow, si.shape->MediumToward(si.n, ls->wi, medium), lambda, counts);
    if (f.IsBlack()) return {};
  } else {
    ++counts.shadow;
    if (scene.Occluded(shadow)) return {};
  }
  float light_pdf = pmf * ls->pdf;
  if (light->IsDelta() || bsdf_count == 0) return f * ls->L / (light_pdf * light_count);
  float w = PowerHeuristic(light_count * light_pdf, bsdf_count * eval.pdf);
  return f * ls->L * (w / (light_pdf * light_count));
}

SampledSpectrum EmittedRadiance(const SurfaceInteraction& si, const SampledWavelengths& lambda) {
  const AreaLight* area = si.shape ? si.shape->area_light : nullptr;
  if (!area) return {};
  return area->L(si.n, si.uv, si.wo, lambda);
}

float AreaLightPdf(const Scene& scene, const Vec3f& ref, const SurfaceInteraction& si) {
  const AreaLight* area = si.shape->area_light;
  return scene.LightPmf(area) * area->PdfLi(ref, si);
}

SampledSpectrum EscapedRadiance(const Scene& scene, const Ray& ray, const SampledWavelengths& lambda, bool full,
                                float bsdf_pdf) {
  SampledSpectrum L(0.f);
  for (const InfiniteLight* light : scene.infinite_lights()) {
    const SampledSpectrum Le = light->Le(ray.d, lambda);
    if (Le.IsBlack()) continue;
    L += full ? Le : Le * PowerHeuristic(bsdf_pdf, scene.LightPmf(light) * light->PdfLi(ray.d));
  }
  return L;
}

SampledSpectrum HitEmission(const Scene& scene, const SurfaceInteraction& si, const SampledWavelengths& lambda,
                            bool full, float bsdf_pdf, const Vec3f& prev_p) {
  const SampledSpectrum Le = EmittedRadiance(si, lambda);
  if (full || Le.IsBlack()) return Le;
  return Le * PowerHeuristic(bsdf_pdf, AreaLightPdf(scene, prev_p, si));
}

SampledSpectrum SegmentTransmittance(const Ray& ray, const SurfaceInteraction& si, const SampledWavelengths& lambda) {
  const Material* m = si.shape ? si.shape->material.get() : nullptr;
  const Spectrum* sigma = m ? m->Absorption() : nullptr;
  if (!sigma || Dot(ray.d, si.n) <= 0) return SampledSpectrum(1.f);
  float dist = si.t * Length(ray.d);
  return Exp(sigma->Sample(lambda) * -dist);
}

}  // namespace objektiv
