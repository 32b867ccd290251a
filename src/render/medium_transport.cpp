#include "render/medium_transport.h"

#include <cmath>

namespace objektiv {

SampledSpectrum Transmittance(const Scene& scene, Ray ray, const Medium* medium, const SampledWavelengths& lambda,
                              RayCounts& counts) {
  SampledSpectrum tr(1.f);
  const float length = Length(ray.d);
  for (int crossings = 0; crossings <= kMaxNullCrossings; ++crossings) {
    if (!(ray.tmax > 0)) return tr;
    ++counts.shadow;
    const std::optional<SurfaceInteraction> si = scene.Intersect(ray);
    if (si && !(si->shape->material && si->shape->material->IsNull())) return SampledSpectrum(0.f);
    if (medium) {
      tr *= medium->Transmittance((si ? si->t : ray.tmax) * length, lambda);
      if (tr.IsBlack()) return tr;
    }
    if (!si) return tr;
    medium = si->shape->MediumToward(si->n, ray.d, medium);
    ray = si->ContinueBeyond(ray);
  }
  return SampledSpectrum(0.f);
}

SampledSpectrum SampleLightFromMedium(const Scene& scene, const MediumVertex& v, const SampledWavelengths& lambda,
                                      float u_light, Vec2f u, RayCounts& counts) {
  float pmf;
  const Light* light = scene.SampleLight(u_light, &pmf);
  if (!light) return {};
  std::optional<LightSample> ls = light->SampleLi(v.p, u, lambda);
  if (!ls || ls->pdf == 0 || ls->L.IsBlack()) return {};
  const float phase = v.medium->phase().p(v.wo, ls->wi);
  if (!(phase > 0)) return {};
  // The point in the medium has no error bound to step off: the ray starts there.
  Ray shadow;
  if (ls->infinite) {
    shadow = Ray{v.p, ls->wi};
  } else {
    const Vec3f to = OffsetRayOrigin(ls->p, ls->p_error, ls->n, v.p - ls->p);
    shadow = Ray{v.p, to - v.p, 1 - 1e-4f};
  }
  const SampledSpectrum tr = Transmittance(scene, shadow, v.medium, lambda, counts);
  if (tr.IsBlack()) return {};
  const float light_pdf = pmf * ls->pdf;
  const float w = light->IsDelta() ? 1.f : PowerHeuristic(light_pdf, phase);
  return tr * ls->L * (phase * w / light_pdf);
}

}  // namespace objektiv
