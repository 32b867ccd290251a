#include "render/light_paths.h"

#include <algorithm>

#include "render/direct_lighting.h"

namespace objektiv {

float ImportanceCosine(const SurfaceInteraction& si, const BSDF& bsdf, const Vec3f& wo, const Vec3f& wi) {
  const float wo_ng = AbsDot(wo, si.n);
  if (wo_ng == 0) return 0;
  return AbsDot(wo, bsdf.frame().n) * AbsDot(wi, si.n) / wo_ng;
}

namespace {

// Splats the light of the vertex si (flux beta, arriving from si.wo) that reaches the camera.
void JoinCamera(const Scene& scene, const SurfaceInteraction& si, const BSDF& bsdf, const SampledSpectrum& beta,
                const SampledWavelengths& lambda, Vec2f u, BlockContext& ctx) {
  SampledWavelengths lambda_camera = lambda;  // a lens may keep the hero wavelength alone
  const std::optional<CameraImportance> imp = ctx.camera().SampleImportance(si.p, u, lambda_camera);
  if (!imp || imp->weight.IsBlack()) return;
  const Vec3f to_lens = imp->p_lens - si.p;
  if (!(LengthSquared(to_lens) > 0)) return;
  const Vec3f wi = Normalize(to_lens);
  const SampledSpectrum f = bsdf.f(si.wo, wi, TransportMode::kImportance);
  if (f.IsBlack()) return;
  const SampledSpectrum J = beta * f * ImportanceCosine(si, bsdf, si.wo, wi);
  if (J.IsBlack()) return;
  ++ctx.rays().shadow;
  if (scene.Occluded(si.SpawnRayTo(imp->p_lens, Vec3f(0.f), Vec3f(0.f)))) return;
  ctx.AddSplat(imp->p_film, J * imp->weight, lambda_camera);
}
}  // namespace

void TraceLightPath(const Scene& scene, const LightPathSettings& settings, Sampler& sampler, BlockContext& ctx) {
  const int max_depth = settings.max_depth;
  // A path that cannot reach the camera through a scattering vertex is not started.
  if (max_depth >= 0 && max_depth < (settings.join == LightPathVertices::kCaustics ? 3 : 2)) return;
  float light_pmf = 0;
  const Light* light = scene.SampleLight(sampler.Get1D(), &light_pmf);
  if (!light || !(light_pmf > 0)) return;
  SampledWavelengths lambda = SampledWavelengths::SampleVisible(sampler.Get1D());
  const Vec2f u_pos = sampler.Get2D();  // drawn before u_dir (arguments have no order)
  const std::optional<LightLeSample> les = light->SampleLe(u_pos, sampler.Get2D(), lambda);
  if (!les || !(les->pdf_pos > 0) || !(les->pdf_dir > 0)) return;
  const SampledSpectrum flux = les->Flux() * (ctx.LightPathScale() / light_pmf);
  if (flux.IsBlack()) return;
  const bool caustics = settings.join == LightPathVertices::kCaustics;
  // The path's flux is flux x throughput; the roulette looks at the throughput alone.
  SampledSpectrum throughput(1.f);
  Ray ray = les->ray;
  RayCounts& counts = ctx.rays();
  // `depth`: the path's segments from the light so far, the current ray included.
  for (int depth = 1;; ++depth) {
    ++counts.closest;
    const std::optional<SurfaceInteraction> si = scene.Intersect(ray);
    if (!si) return;
    throughput *= SegmentTransmittance(ray, *si, lambda);
    const Material* material = si->shape->material.get();
    if (!material) return;
    const BSDF bsdf = material->GetBSDF(*si, lambda);
    const bool scatters = bsdf.Flags() & (kDiffuse | kGlossy);
    // Caustics: the first vertex after one or more specular bounces (every bounce so far was
    // specular, or the path would have ended).
    const bool join = scatters && (max_depth < 0 || depth + 1 <= max_depth) && (!caustics || depth >= 2);
    if (join) JoinCamera(scene, *si, bsdf, flux * throughput, lambda, sampler.Get2D(), ctx);
    // A longer path could not join the camera within max_depth any more.
    if (max_depth >= 0 && depth + 2 > max_depth) return;

    const float uc = bsdf.UsesLobeChoice() ? sampler.Get1D() : 0.5f;
    const std::optional<BSDFSample> bs = bsdf.Sample(si->wo, uc, sampler.Get2D(), TransportMode::kImportance);
    if (!bs || !(bs->pdf > 0)) return;
    if (caustics && !bs->IsSpecular()) return;  // beyond the caustics' paths
    throughput *= bs->f * (ImportanceCosine(*si, bsdf, si->wo, bs->wi) / bs->pdf);
    ray = si->SpawnRay(bs->wi);
    if (throughput.HasNaN() || throughput.HasInf()) {
      ctx.CountNaN();
      return;
    }
    if (throughput.IsBlack()) return;
    if (depth + 1 >= settings.rr_depth) {
      const float q = std::min(throughput.Max(), 0.95f);
      if (sampler.Get1D() >= q) return;
      throughput = throughput / q;
    }
  }
}

}  // namespace objektiv
