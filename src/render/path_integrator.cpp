#include "render/direct_lighting.h"
#include "render/integrator.h"
#include "render/light_paths.h"

#include <limits>

namespace objektiv {

SampledSpectrum PathIntegrator::Li(const Ray& camera_ray, const std::optional<SurfaceInteraction>& first_hit,
                                   SampledWavelengths& lambda, Sampler& sampler, BlockContext& ctx) const {
  RayCounts& counts = ctx.rays();
  SampledSpectrum L(0.f), beta(1.f);
  Ray ray = camera_ray;
  bool specular_bounce = false;
  // With caustics: whether the path so far is the camera's half of a caustic (a non-specular
  // bounce at the first hit, then specular bounces only, at least one), whose emitters the light
  // paths take.
  bool scattered_first = false;
  int specular_after_first = 0;
  float bsdf_pdf = 0, eta_scale = 1;
  Vec3f prev_p;
  // `depth` is the number of path segments traced so far, including the current ray.
  for (int depth = 1;; ++depth) {
    if (depth > 1) ++counts.closest;
    // Initialised by the call itself (an assignment would copy the interaction each bounce).
    std::optional<SurfaceInteraction> si = depth == 1 ? first_hit : scene_.Intersect(ray);
    const bool caustic = caustics_ && scattered_first && specular_after_first > 0;
    if (!si) {
      if (caustic) break;
      for (const InfiniteLight* light : scene_.infinite_lights()) {
        SampledSpectrum Le = light->Le(ray.d, lambda);
        if (Le.IsBlack()) continue;
        if (depth == 1 || specular_bounce) {
          L += beta * Le;
        } else {
          float light_pdf = scene_.LightPmf(light) * light->PdfLi(ray.d);
          L += beta * Le * PowerHeuristic(bsdf_pdf, light_pdf);
        }
      }
      break;
    }
    beta *= SegmentTransmittance(ray, *si, lambda);
    SampledSpectrum Le = caustic ? SampledSpectrum(0.f) : EmittedRadiance(*si, lambda);
    if (!Le.IsBlack()) {
      if (depth == 1 || specular_bounce) {
        L += beta * Le;
      } else {
        float light_pdf = AreaLightPdf(scene_, prev_p, *si);
        L += beta * Le * PowerHeuristic(bsdf_pdf, light_pdf);
      }
    }
    if (max_depth_ >= 0 && depth >= max_depth_) break;
    const Material* material = si->shape->material.get();
    if (!material) break;
    BSDF bsdf = material->GetBSDF(*si, lambda);

    // Next-event estimation adds one segment: only if the path may grow.
    if ((bsdf.Flags() & (kDiffuse | kGlossy)) && (max_depth_ < 0 || depth + 1 <= max_depth_)) {
      // Dimensions nobody uses are not drawn (one light: no choice to make).
      float ul = scene_.lights().size() > 1 ? sampler.Get1D() : 0.5f;
      Vec2f u = sampler.Get2D();
      L += beta * SampleLightMIS(scene_, *si, bsdf, lambda, ul, u, counts);
    }

    float uc = bsdf.UsesLobeChoice() ? sampler.Get1D() : 0.5f;
    Vec2f u = sampler.Get2D();
    std::optional<BSDFSample> bs = bsdf.Sample(si->wo, uc, u);
    if (!bs) break;
    // The BSDF's own normal: a bump or normal map may have perturbed the shape's.
    beta *= bs->f * (AbsDot(bs->wi, bsdf.frame().n) / bs->pdf);
    bsdf_pdf = bs->pdf;
    specular_bounce = bs->IsSpecular();
    if (depth == 1) {
      scattered_first = !specular_bounce;
    } else if (specular_bounce) {
      ++specular_after_first;
    } else {
      scattered_first = false;  // no longer a caustic's camera half
    }
    if (bs->IsTransmission()) eta_scale *= Sqr(bs->eta);
    prev_p = si->p;
    ray = si->SpawnRay(bs->wi);

    // A non-finite throughput would never be stopped by the roulette below: end the path
    // and report it, so that the renderer counts the sample instead of writing it.
    if (beta.HasNaN() || beta.HasInf()) return SampledSpectrum(std::numeric_limits<float>::quiet_NaN());
    // Russian roulette on the throughput with the radiance scaling of refraction removed.
    if (beta.IsBlack()) break;
    if (depth >= rr_depth_) {
      float q = std::min((beta * eta_scale).Max(), 0.95f);
      if (sampler.Get1D() >= q) break;
      beta = beta / q;
    }
  }
  return L;
}

void PathIntegrator::TraceLightPaths(Sampler& sampler, BlockContext& ctx) const {
  if (caustics_) TraceLightPath(scene_, {max_depth_, rr_depth_, LightPathVertices::kCaustics}, sampler, ctx);
}

}  // namespace objektiv
