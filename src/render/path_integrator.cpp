#include "render/direct_lighting.h"
#include "render/integrator.h"
#include "render/light_paths.h"
#include "render/medium_transport.h"

#include <algorithm>
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
  // Media (scene/medium.h): the medium the current ray travels in, and whether the path's last
  // scattering event sampled the emitters (a medium with sample_emitters off does not: an
  // emitter its phase sampling finds then counts in full).
  const bool media = scene_.HasMedia();
  const Medium* medium = scene_.camera_medium();
  bool sampled_emitters = true;
  // Spectral MIS over the distance sampling (scene/medium.h): the wavelength whose sigma_t
  // samples the path's distances (chosen at its first medium), and the ratios p_j / p_c of the
  // path's densities, kept with mean 1 (beta divided by their mean as they change, so that
  // beta is the estimate's own weight and neither grows beyond range).
  int channel = -1;
  SampledSpectrum ratio(1.f);
  // `depth` is the number of path segments traced so far, including the current ray. Steps
  // over null surfaces (medium boundaries) continue the segment and do not count.
  for (int depth = 1;; ++depth) {
    if (depth > 1) ++counts.closest;
    // Initialised by the call itself (an assignment would copy the interaction each bounce).
    std::optional<SurfaceInteraction> si = depth == 1 ? first_hit : scene_.Intersect(ray);
    // Through media and across null surfaces up to the next real surface, or to a scattering
    // event in a medium (free-flight sampling, MediumSample's weight in beta).
    bool scattered = false;
    Vec3f scatter_p;
    if (media) {
      int crossings = 0;
      for (;;) {
        if (medium) {
          const float length = Length(ray.d);
          const float d_max = si ? si->t * length : std::numeric_limits<float>::infinity();
          if (channel < 0) channel = std::min(int(sampler.Get1D() * kSpectrumSamples), kSpectrumSamples - 1);
          const MediumSample ms = medium->SampleDistance(d_max, lambda, channel, sampler.Get1D());
          const SampledSpectrum r = ratio * ms.ratio;
          const float mean = r.Average();
          // (Positive but for underflow after a long run of unlikely events: the path ends.)
          if (!(mean > 0) || !std::isfinite(mean)) return L;
          beta *= ms.weight / mean;
          ratio = r / mean;
          if (ms.scattered) {
            scattered = true;
            scatter_p = ray.o + ray.d * (ms.distance / length);
            break;
          }
        }
        if (!si || !(si->shape->material && si->shape->material->IsNull())) break;
        if (++crossings > kMaxNullCrossings) return L;
        medium = si->shape->MediumToward(si->n, ray.d, medium);
        ray = si->ContinueBeyond(ray);
        ++counts.closest;
        si = scene_.Intersect(ray);
      }
      if (beta.IsBlack()) break;
    }
    if (scattered) {
      // A scattering event in the medium: next-event estimation, then the phase function
      // chooses the next direction (sampled exactly: the weight is 1), as at a surface.
      if (max_depth_ >= 0 && depth >= max_depth_) break;
      const MediumVertex v{scatter_p, -ray.d / Length(ray.d), medium};
      sampled_emitters = medium->SamplesEmitters() && (max_depth_ < 0 || depth + 1 <= max_depth_);
      if (sampled_emitters) {
        float ul = scene_.lights().size() > 1 ? sampler.Get1D() : 0.5f;
        Vec2f u = sampler.Get2D();
        L += beta * SampleLightFromMedium(scene_, v, lambda, ul, u, counts);
      }
      const PhaseSample ps = medium->phase().Sample(v.wo, sampler.Get2D());
      bsdf_pdf = ps.p;
      specular_bounce = false;
      scattered_first = false;  // (caustics are not traced with media: the loader refuses)
      prev_p = scatter_p;
      ray = Ray{scatter_p, ps.wi};
      if (beta.HasNaN() || beta.HasInf()) return SampledSpectrum(std::numeric_limits<float>::quiet_NaN());
      // Russian roulette on the throughput as at surfaces, but with no floor of 5% for paths
      // that carry all their light (pbrt-v4's rule): in a dense, barely absorbing medium a path
      // scatters hundreds of times, and a 5% chance to end at each would leave the survivors
      // weighted by 1 / 0.95^n (fireflies in a glass of milk).
      if (depth >= rr_depth_) {
        const float q = std::min((beta * eta_scale).Max(), 1.f);
        if (q < 1) {
          if (sampler.Get1D() >= q) break;
          beta = beta / q;
        }
      }
      continue;
    }
    const bool caustic = caustics_ && scattered_first && specular_after_first > 0;
    // Emitters found by the path count in full where the last vertex could not sample them.
    const bool full_emission = depth == 1 || specular_bounce || !sampled_emitters;
    if (!si) {
      if (!caustic) L += beta * EscapedRadiance(scene_, ray, lambda, full_emission, bsdf_pdf);
      break;
    }
    beta *= SegmentTransmittance(ray, *si, lambda);
    if (!caustic) L += beta * HitEmission(scene_, *si, lambda, full_emission, bsdf_pdf, prev_p);
    if (max_depth_ >= 0 && depth >= max_depth_) break;
    const Material* material = si->shape->material.get();
    if (!material) break;
    BSDF bsdf = material->GetBSDF(*si, lambda);

    // Next-event estimation adds one segment: only if the path may grow.
    if ((bsdf.Flags() & (kDiffuse | kGlossy)) && (max_depth_ < 0 || depth + 1 <= max_depth_)) {
      // Dimensions nobody uses are not drawn (one light: no choice to make).
      float ul = scene_.lights().size() > 1 ? sampler.Get1D() : 0.5f;
      Vec2f u = sampler.Get2D();
      L += beta * SampleLightMIS(scene_, *si, bsdf, lambda, ul, u, counts, 1, 1, medium);
    }
    sampled_emitters = true;  // (a specular BSDF sets specular_bounce below instead)

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
    if (media) medium = si->shape->MediumToward(si->n, bs->wi, medium);

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
