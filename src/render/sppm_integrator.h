// Stochastic progressive photon mapping (Hachisuka and Jensen 2009), `<integrator type="sppm">`:
// the integrator for light that neither camera paths nor light paths can carry, a caustic seen
// in a mirror or through glass (L S+ D S+ E in Heckbert's notation), above all from a point
// light and through a real lens, where a camera path cannot aim at the light and a light path
// cannot aim at the camera.
//
// An iteration (one per sample index: the film's spp are the iterations):
// 1. Camera pass. Each pixel of the crop window takes one camera ray (Camera::GenerateRays, a
//    row at a time: every camera works, the realistic lens too) and follows its specular and
//    glossy bounces to the first surface with a diffuse lobe: the pixel's visible point
//    (position, direction to the camera, its BSDF at the iteration's wavelengths, the path's
//    throughput). A glossy surface is traced through, as pbrt's SPPM does, by sampling its BSDF
//    (with the light sampled there and combined by the power heuristic, as the path tracer
//    does): a visible point on a nearly smooth lobe (glass or metal of roughness 0.01) would
//    gather almost no photon in its narrow cone, and stay dark for thousands of iterations.
//    Where max_depth ends the path at a glossy surface, it keeps its direct light. Emitters met
//    on the way count directly (by MIS after a glossy bounce), and the visible point estimates
//    its direct light by light sampling (one shadow ray). A BSDF with both delta and diffuse
//    lobes (a smooth plastic's coat) makes the visible point or continues along one of its
//    delta lobes, each with probability 1/2 and its weight doubled: the one visible point a
//    pixel has per iteration covers both parts without bias.
// 2. Photon pass. photon_count photons, each from a light chosen by power (Light::SampleLe, as
//    the light tracer starts its paths), carried through the scene with the adjoint BSDF
//    (render/light_paths.h). At every vertex after the first with a diffuse lobe (where visible
//    points can be: a photon left on rough glass would also reach the points on the surfaces
//    beside it, and count twice) the photon deposits its flux at the visible points within
//    their radius (a hash grid over the visible points, cells the largest diameter wide):
//    Phi += beta_vp f(wo_vp, wi_photon) flux.
//    The first vertex is left out: the camera pass's light sampling has the direct light.
// 3. Update, per pixel with M photons this iteration (alpha in (0, 1), 2/3 by default):
//    N' = N + alpha M, r'^2 = r^2 N' / (N + M), tau' = (tau + Phi) r'^2 / r^2.
// The pixel: the direct part averaged over the iterations plus tau / (N_emitted pi r^2),
// N_emitted = photon_count x iterations. Biased (the radius blurs and, at corners, darkens),
// consistent: the radius shrinks as the iterations go on, and the bias with it.
//
// Spectral: one set of wavelengths per iteration (hero-wavelength sampling from a sampler
// stream of its own, low-discrepancy over the iterations), shared by every camera path and
// photon of the iteration. A photon's flux and a visible point's BSDF and throughput are then
// values at the same wavelengths, and their product is the estimate at those wavelengths;
// where glass disperses (a photon or a camera path keeps the hero wavelength alone) the
// deposit keeps only the hero, which both bent by their own index at that wavelength: a prism
// still splits white light, one band per iteration. The alternative of photons with their own
// wavelengths would need each visible point's BSDF and throughput at every photon's
// wavelengths (and a dispersive camera path at all of them). The price: an iteration's colour
// error is the same over the whole image (a cast, not grain), so the iterations' wavelengths
// are stratified over the visible range (a radical-inverse sequence, randomly turned): after
// 2^k iterations 4 x 2^k wavelengths cover it evenly and the cast is gone (under 1% from 16).
//
// Schedule and determinism: whole iterations, each pass a TBB loop (rows of pixels, chunks of
// photons, pixels). Camera paths take their numbers from the sampler started at (pixel,
// iteration); photon j from (j, -1) at the iteration, the wavelengths' offset from (0, -2)
// (no camera pixel has a negative row). Deposits are gathered per chunk of photons and summed
// into the pixels in photon order after the pass: the image is bit for bit the same on any
// thread count. The iterations are one render: no sample ranges (parts, checkpoints), no
// adaptive sampling, time limit or noise target (app/render_command.cpp refuses them).
//
// max_depth bounds each half (the camera's specular chain, and a photon's segments) as pbrt's
// SPPM does; -1 leaves both to Russian roulette from rr_depth on. Participating media and null
// surfaces are not followed (RendersMedia: the loader refuses such scenes).
#pragma once
#include "render/renderer.h"

namespace objektiv {

struct SppmSettings {
  int max_depth = -1, rr_depth = 5;
  int64_t photon_count = 100000;  // photons per iteration
  // World units; 0: automatic, twice the median distance between the first surfaces seen through
  // neighbouring pixels, over a grid across the whole film (about two pixels' footprint; the
  // same for a crop window as for the whole film).
  float initial_radius = 0;
  float alpha = 2.f / 3;  // the share of the new photons kept as the radius shrinks
  static constexpr int64_t kMaxPhotonCount = int64_t(1) << 30;
};

class SppmIntegrator final : public WholeImageIntegrator {
 public:
  SppmIntegrator(const Scene& scene, SppmSettings settings) : WholeImageIntegrator(scene), s_(settings) {}
  RenderStats RenderImage(const Camera& camera, const Sampler& sampler, Film& film,
                          const RenderOptions& options) const override;
  const SppmSettings& settings() const { return s_; }
  // Each pixel's statistics and visible point (its BSDF kept whole): some 430 bytes.
  uint64_t BytesPerPixel() const override;

 private:
  SppmSettings s_;
};

}  // namespace objektiv
