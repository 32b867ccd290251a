// Stochastic progressive photon mapping: the iterations (render/sppm_integrator.h says why they
// are made so).
#include "render/sppm_integrator.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <limits>
#include <stdexcept>
#include <vector>

#include "base/bounds.h"
#include "base/lowdiscrepancy.h"
#include "base/progress.h"
#include "base/rng.h"
#include "render/adaptive_sampling.h"
#include "render/direct_lighting.h"
#include "render/light_paths.h"

namespace objektiv {

namespace {

// A pixel's visible point of the current iteration: where its camera path first met a surface
// that is not purely specular. `beta` is the camera path's throughput there (the camera's
// weight and the filter's included), at the wavelengths `lambda` (the iteration's, with the
// secondary ones dropped if the path crossed a dispersive surface or lens).
struct VisiblePoint {
  Vec3f p, wo;
  BSDF bsdf;
  SampledSpectrum beta{0.f};
  SampledWavelengths lambda;
  bool valid = false;
};

// What a pixel keeps over the iterations. Sums in double: a pixel's sums run over many
// iterations and photons.
struct SppmPixel {
  double direct[3] = {0, 0, 0};   // sum of w XYZ of the light the camera pass found
  double emitted[3] = {0, 0, 0};  // its part straight from emitters at the first hit (Film::KeepEmitted)
  double weight = 0;              // sum of the filter weights w
  double radius = 0, n = 0, tau[3] = {0, 0, 0};
  // This iteration's photons: their flux (XYZ) and count.
  double phi[3] = {0, 0, 0};
  int64_t m = 0;
  VisiblePoint vp;
};

// A photon's deposit at a visible point: the pixel (index into the crop window) and its XYZ.
struct Deposit {
  uint32_t pixel;
  Vec3f xyz;
};

// The visible points in a hash grid of cubes `cell` wide (at least each point's diameter): a
// point is listed in every cell its sphere overlaps, so that a photon looks in its own cell only.
class VisiblePointGrid {
 public:
  VisiblePointGrid(const std::vector<SppmPixel>& pixels) {
    float r_max = 0;
    size_t count = 0;
    for (const SppmPixel& px : pixels)
      if (px.vp.valid) {
        r_max = std::max(r_max, float(px.radius));
        lo_ = Min(lo_, px.vp.p), hi_ = Max(hi_, px.vp.p);
        ++count;
      }
    if (count == 0 || !(r_max > 0)) return;
    cell_ = 2.002f * r_max;  // a little over a diameter: rounding never spreads a sphere over 3 cells
    lo_ = lo_ - Vec3f(r_max), hi_ = hi_ + Vec3f(r_max);
    buckets_ = 2 * count;
    // Counting sort of (bucket, pixel) pairs: starts_[b] .. starts_[b + 1] index entries_.
    std::vector<uint32_t> counts(buckets_ + 1, 0);
    // The buckets of the (at most 2 x 2 x 2, room for 3 x 3 x 3) cells a point's sphere overlaps,
    // each once: two of its cells may hash to one bucket, and a point listed twice there would
    // take a photon twice (which once made a crop window's pixels differ from the full image's).
    auto for_each_bucket = [&](const SppmPixel& px, auto&& fn) {
      const float r = float(px.radius);
      const Vec3<int> c0 = Cell(px.vp.p - Vec3f(r)), c1 = Cell(px.vp.p + Vec3f(r));
      size_t buckets[27];
      int n = 0;
      for (int z = c0.z; z <= c1.z; ++z)
        for (int y = c0.y; y <= c1.y; ++y)
          for (int x = c0.x; x <= c1.x; ++x) buckets[n++] = Bucket(Vec3<int>(x, y, z));
      std::sort(buckets, buckets + n);
      for (int k = 0; k < n; ++k)
        if (k == 0 || buckets[k] != buckets[k - 1]) fn(buckets[k]);
    };
    for (const SppmPixel& px : pixels)
      if (px.vp.valid) for_each_bucket(px, [&](size_t b) { ++counts[b + 1]; });
    for (size_t b = 0; b < buckets_; ++b) counts[b + 1] += counts[b];
    starts_ = counts;
    entries_.resize(counts[buckets_]);
    for (size_t i = 0; i < pixels.size(); ++i)
      if (pixels[i].vp.valid) for_each_bucket(pixels[i], [&](size_t b) { entries_[counts[b]++] = uint32_t(i); });
  }
  // fn(pixel index) for the points listed in p's cell (a superset of those within reach).
  template <class Fn>
  void ForEachNear(const Vec3f& p, Fn&& fn) const {
    if (entries_.empty()) return;
    if (!(p.x >= lo_.x && p.y >= lo_.y && p.z >= lo_.z && p.x <= hi_.x && p.y <= hi_.y && p.z <= hi_.z)) return;
    const size_t b = Bucket(Cell(p));
    for (uint32_t k = starts_[b]; k < starts_[b + 1]; ++k) fn(entries_[k]);
  }

 private:
  Vec3<int> Cell(const Vec3f& p) const {
    const Vec3f c = (p - lo_) / cell_;
    return Vec3<int>(int(std::floor(c.x)), int(std::floor(c.y)), int(std::floor(c.z)));
  }
  size_t Bucket(const Vec3<int>& c) const {
    const uint64_t h = (uint64_t(uint32_t(c.x)) * 73856093u) ^ (uint64_t(uint32_t(c.y)) * 19349663u) ^
                       (uint64_t(uint32_t(c.z)) * 83492791u);
    return size_t(MixBits(h) % buckets_);
  }
  Vec3f lo_{std::numeric_limits<float>::infinity()}, hi_{-std::numeric_limits<float>::infinity()};
  float cell_ = 0;
  size_t buckets_ = 0;
  std::vector<uint32_t> starts_, entries_;
};

// The automatic initial radius: twice the median distance between the first surfaces seen
// through the centres of neighbouring pixels (the pixel to the right or below, the nearer), over
// a grid of 48 x 48 pixels spread across the whole film: about two pixels' footprint where most
// of the image is. From the whole film, so that a crop window renders its part of the full
// image, pixel for pixel.
float AutomaticRadius(const Scene& scene, const Camera& camera) {
  constexpr int kGrid = 48;
  SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
  auto first_hit = [&](float x, float y) -> std::optional<Vec3f> {
    SampledWavelengths l = lambda;
    const std::optional<CameraRay> cr = camera.GenerateRay({Vec2f(x, y), Vec2f(0.5f, 0.5f)}, l);
    if (!cr) return std::nullopt;
    const std::optional<SurfaceInteraction> si = scene.Intersect(cr->ray);
    if (!si) return std::nullopt;
    return si->p;
  };
  std::vector<float> d;
  Bounds3f seen;
  const int w = camera.width(), h = camera.height();
  for (int gy = 0; gy < kGrid; ++gy)
    for (int gx = 0; gx < kGrid; ++gx) {
      const float x = std::floor((gx + 0.5f) * w / kGrid) + 0.5f, y = std::floor((gy + 0.5f) * h / kGrid) + 0.5f;
      const std::optional<Vec3f> a = first_hit(x, y);
      if (!a) continue;
      seen.Extend(*a);
      float best = std::numeric_limits<float>::infinity();
      for (const Vec2f& n : {Vec2f(x + 1, y), Vec2f(x, y + 1)})
        if (const std::optional<Vec3f> b = first_hit(n.x, n.y)) best = std::min(best, Length(*b - *a));
      if (std::isfinite(best) && best > 0) d.push_back(best);
    }
  if (d.empty()) {
    // No two neighbouring points (a one-pixel film): a hundredth of what was seen, or of the scene.
    const float spread = 2 * (seen.Empty() ? scene.bounds().Radius() : seen.Radius());
    return spread > 0 && std::isfinite(spread) ? 0.01f * spread : 1e-3f;
  }
  std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
  return 2 * d[d.size() / 2];
}

constexpr int kPhotonChunk = 4096;  // photons per task of the photon pass (and per deposit list)

}  // namespace

uint64_t SppmIntegrator::BytesPerPixel() const { return sizeof(SppmPixel); }

RenderStats SppmIntegrator::RenderImage(const Camera& camera, const Sampler& sampler, Film& film,
                                        const RenderOptions& options) const {
  if (options.spp_begin != 0 || film.first_sample() != 0)
    throw std::invalid_argument("sppm renders its iterations in one go from the first: it takes no sample range");
  const CropWindow crop = film.crop();
  const int width = crop.Width(), height = crop.Height();
  const int iterations = options.spp_end;
  const bool lens_sample = camera.UsesLensSample();
  const bool keep_emitted = film.keeps_emitted();
  const int64_t photons = s_.photon_count;

  std::vector<SppmPixel> pixels(size_t(width) * height);
  tbb::enumerable_thread_specific<RenderCounters> counters;
  std::optional<Progress> own_progress;
  Progress* progress = options.progress_bar;
  if (!progress) progress = &own_progress.emplace("Rendering", int64_t(iterations) * width * height, options.progress);
  const auto start = std::chrono::steady_clock::now();
  const uint64_t skipped_before = scene_.SkippedRays();
  const int64_t n_chunks = (photons + kPhotonChunk - 1) / kPhotonChunk;
  std::vector<std::vector<Deposit>> deposits(static_cast<size_t>(n_chunks));

  // Whether a path may have `segments` segments.
  auto max_depth_allows = [&](int segments) { return s_.max_depth < 0 || segments <= s_.max_depth; };
  int done = 0;
  // The iterations' wavelengths, each iteration's shared by its camera paths and photons: the
  // whole image's colour rests on them, and four random ones an iteration left a cast over the
  // whole image that changed with the seed (blue 14% low at 16 iterations). Each iteration's
  // four lie one in each quarter of the range of the visible density's inverse, at u + j/4
  // with u uniform in [0, 1/4) (unbiased on its own); u is the base-2 radical inverse of the
  // iteration (Sobol's first dimension), turned by one random offset, scaled into [0, 1/4):
  // after 2^k iterations the 4 x 2^k wavelengths are stratified evenly over the range (sixteen
  // after four iterations: a smooth spectrum's X, Y, Z within 2%). The hero, which a path
  // through dispersive glass keeps alone, is the one in quarter (iteration mod 4): over every
  // four iterations it visits each quarter, stratified within it as u is (it was always the
  // first quarter's: light dispersed by a prism came out blue). A dispersive lens, where every
  // camera path keeps one wavelength, is refused (io/scene_loader.cpp: the iterations' unequal
  // weights leave a cast over the whole image).
  Sampler lambda_sampler(sampler);
  lambda_sampler.StartPixelSample(Vec2i(0, -2), 0);
  const float lambda_offset = lambda_sampler.Get1D();
  for (int it = 0; it < iterations; ++it) {
    if (options.stop && options.stop->load(std::memory_order_relaxed)) break;
    float u_lambda = std::min(float(Sobol0(uint32_t(it))) * 0x1p-32f, kOneMinusEpsilon) + lambda_offset;
    u_lambda = std::min((u_lambda - std::floor(u_lambda)) * 0.25f, 0.25f * kOneMinusEpsilon) + 0.25f * float(it % 4);
    const SampledWavelengths lambda_it = SampledWavelengths::SampleVisible(u_lambda);

    // 1. Camera pass, a row at a time.
    tbb::parallel_for(0, height, [&](int row) {
      RenderCounters& c = counters.local();
      const int y = crop.y0 + row;
      std::vector<Sampler> samplers(size_t(width), sampler);
      std::vector<CameraSample> cs(static_cast<size_t>(width));
      std::vector<SampledWavelengths> lambdas(size_t(width), lambda_it);
      std::vector<std::optional<CameraRay>> rays(static_cast<size_t>(width));
      std::vector<float> weights(static_cast<size_t>(width));
      for (int i = 0; i < width; ++i) {
        const Vec2i pixel(crop.x0 + i, y);
        Sampler& sp = samplers[i];
        sp.StartPixelSample(pixel, it);
        const PatternSample ps = sp.GetPixelSample();
        const FilterSample fs = film.filter().Sample(ps.u);
        weights[i] = fs.weight * ps.weight;
        const Vec2f lens = lens_sample ? sp.Get2D() : Vec2f(0.5f, 0.5f);
        cs[i] = {Vec2f(pixel.x + 0.5f + fs.offset.x, pixel.y + 0.5f + fs.offset.y), lens, pixel};
      }
      camera.GenerateRays(cs, lambdas, rays, c.camera);
      for (int i = 0; i < width; ++i) {
        SppmPixel& px = pixels[size_t(row) * width + i];
        px.vp.valid = false;
        const float w = weights[i];
        px.weight += w;
        if (!rays[i]) continue;
        Sampler& sp = samplers[i];
        SampledWavelengths& lambda = lambdas[i];
        SampledSpectrum L(0.f), beta = rays[i]->weight;
        Ray ray = rays[i]->ray;
        float eta_scale = 1;
        // After a glossy bounce (BSDF-sampled, with the light sampled there too) an emitter
        // the path meets counts by the power heuristic; at the camera or after a delta bounce
        // in full (nothing else could find it).
        bool full_emission = true;
        float bsdf_pdf = 0;
        Vec3f prev_p;
        for (int depth = 1;; ++depth) {
          ++c.rays.closest;
          const std::optional<SurfaceInteraction> si = scene_.Intersect(ray);
          if (!si) {
            L += beta * EscapedRadiance(scene_, ray, lambda, full_emission, bsdf_pdf);
            if (depth == 1 && keep_emitted) {
              const Vec3f xyz = SampledToXYZ(L, lambda);
              for (int k = 0; k < 3; ++k) px.emitted[k] += double(w) * xyz[k];
            }
            break;
          }
          beta *= SegmentTransmittance(ray, *si, lambda);
          const SampledSpectrum Le = HitEmission(scene_, *si, lambda, full_emission, bsdf_pdf, prev_p);
          L += beta * Le;
          if (depth == 1 && keep_emitted) {
            const Vec3f xyz = SampledToXYZ(beta * Le, lambda);
            for (int k = 0; k < 3; ++k) px.emitted[k] += double(w) * xyz[k];
          }
          const Material* material = si->shape->material.get();
          if (!material) break;
          const BSDF bsdf = material->GetBSDF(*si, lambda);
          const int flags = bsdf.Flags();
          // The visible point: the first surface with a diffuse lobe. Glossy surfaces are traced
          // through (a nearly smooth lobe would receive almost no photon in its narrow cone);
          // where max_depth ends the path at one, it keeps its direct light alone.
          const bool point_here = flags & kDiffuse;
          bool make_point = point_here;
          SampledSpectrum point_weight(1.f);
          if (point_here && (flags & kSpecular)) {
            // Delta and non-delta lobes: the visible point here, or on along a delta lobe.
            make_point = sp.Get1D() < 0.5f;
            point_weight = SampledSpectrum(2.f);
          }
          if (make_point) {
            // The direct light by light sampling alone (the path ends here; the photons leave
            // the direct light out), then the point.
            if (max_depth_allows(depth + 1)) {
              const float ul = scene_.lights().size() > 1 ? sp.Get1D() : 0.5f;
              const Vec2f u = sp.Get2D();
              L += beta * point_weight * SampleLightMIS(scene_, *si, bsdf, lambda, ul, u, c.rays, 1, 0);
              px.vp.p = si->p;
              px.vp.wo = si->wo;
              px.vp.bsdf = bsdf;
              px.vp.beta = beta * point_weight * w;
              px.vp.lambda = lambda;
              px.vp.valid = !px.vp.beta.IsBlack();
            }
            break;
          }
          if (!max_depth_allows(depth + 1)) break;
          Vec3f wi;
          if (point_here) {
            // Along one of the delta lobes, chosen uniformly (the other half: the point above).
            SpecularLobe lobes[kMaxSpecularLobes];
            const int n = bsdf.SpecularLobes(si->wo, lobes);
            if (n == 0) break;
            const int k = std::min(int(sp.Get1D() * n), n - 1);
            beta *= lobes[k].weight * (2.f * n);
            wi = lobes[k].wi;
            full_emission = true;
          } else {
            // A glossy (or delta) surface: the light sampled here by MIS against the BSDF's
            // sample, which the path then follows.
            const bool glossy = flags & kGlossy;
            if (glossy) {
              const float ul = scene_.lights().size() > 1 ? sp.Get1D() : 0.5f;
              const Vec2f u = sp.Get2D();
              L += beta * SampleLightMIS(scene_, *si, bsdf, lambda, ul, u, c.rays, 1, 1);
            }
            const float uc = bsdf.UsesLobeChoice() ? sp.Get1D() : 0.5f;
            const std::optional<BSDFSample> bs = bsdf.Sample(si->wo, uc, sp.Get2D());
            if (!bs || !(bs->pdf > 0)) break;
            beta *= bs->f * (AbsDot(bs->wi, bsdf.frame().n) / bs->pdf);
            if (bs->IsTransmission()) eta_scale *= Sqr(bs->eta);
            wi = bs->wi;
            full_emission = bs->IsSpecular() || !glossy;
            bsdf_pdf = bs->pdf;
          }
          prev_p = si->p;
          ray = si->SpawnRay(wi);
          if (beta.HasNaN() || beta.HasInf()) {
            ++c.nan;
            L = SampledSpectrum(0.f);
            break;
          }
          if (beta.IsBlack()) break;
          if (depth >= s_.rr_depth) {
            const float q = std::min((beta * eta_scale).Max(), 0.95f);
            if (sp.Get1D() >= q) break;
            beta = beta / q;
          }
        }
        if (L.HasNaN() || L.HasInf()) {
          ++(L.HasNaN() ? c.nan : c.inf);
          continue;
        }
        const Vec3f xyz = SampledToXYZ(L, lambda);
        for (int k = 0; k < 3; ++k) px.direct[k] += double(w) * xyz[k];
      }
    });

    if (it == 0) {
      const float r0 = s_.initial_radius > 0 ? s_.initial_radius : AutomaticRadius(scene_, camera);
      for (SppmPixel& px : pixels) px.radius = r0;
    }

    // 2. Photon pass: chunks of photons in parallel, each chunk's deposits listed in photon order.
    const VisiblePointGrid grid(pixels);
    tbb::parallel_for(int64_t(0), n_chunks, [&](int64_t chunk) {
      RenderCounters& c = counters.local();
      std::vector<Deposit>& out = deposits[size_t(chunk)];
      out.clear();
      Sampler sp(sampler);
      const int64_t j1 = std::min(photons, (chunk + 1) * kPhotonChunk);
      for (int64_t j = chunk * kPhotonChunk; j < j1; ++j) {
        sp.StartPixelSample(Vec2i(int(j), -1), it);
        float light_pmf = 0;
        const Light* light = scene_.SampleLight(sp.Get1D(), &light_pmf);
        if (!light || !(light_pmf > 0)) continue;
        SampledWavelengths lambda = lambda_it;
        const Vec2f u_pos = sp.Get2D();  // drawn before u_dir (arguments have no order)
        const std::optional<LightLeSample> les = light->SampleLe(u_pos, sp.Get2D(), lambda);
        if (!les || !(les->pdf_pos > 0) || !(les->pdf_dir > 0)) continue;
        SampledSpectrum beta = les->Flux() / light_pmf;
        if (beta.IsBlack()) continue;
        // Russian roulette on the throughput relative to the photon's start.
        SampledSpectrum throughput(1.f);
        Ray ray = les->ray;
        for (int depth = 1;; ++depth) {
          ++c.rays.closest;
          const std::optional<SurfaceInteraction> si = scene_.Intersect(ray);
          if (!si) break;
          throughput *= SegmentTransmittance(ray, *si, lambda);
          const Material* material = si->shape->material.get();
          if (!material) break;
          const BSDF bsdf = material->GetBSDF(*si, lambda);
          // Only where visible points can be (a diffuse lobe): a photon deposited on a glossy
          // surface (rough glass) would reach the points within the radius on the surfaces
          // beside it, and count again where it lands after (caustics 15-25% too bright).
          if (depth > 1 && (bsdf.Flags() & kDiffuse)) {
            const SampledSpectrum flux = beta * throughput;
            grid.ForEachNear(si->p, [&](uint32_t i) {
              const SppmPixel& px = pixels[i];
              if (LengthSquared(px.vp.p - si->p) > Sqr(float(px.radius))) return;
              const SampledSpectrum phi = px.vp.beta * px.vp.bsdf.f(px.vp.wo, si->wo) * flux;
              if (phi.IsBlack()) return;
              SampledWavelengths l = px.vp.lambda;
              if (lambda.SecondaryTerminated()) l.TerminateSecondary();
              out.push_back({i, SampledToXYZ(phi, l)});
            });
          }
          if (s_.max_depth >= 0 && depth >= s_.max_depth) break;
          const float uc = bsdf.UsesLobeChoice() ? sp.Get1D() : 0.5f;
          const std::optional<BSDFSample> bs = bsdf.Sample(si->wo, uc, sp.Get2D(), TransportMode::kImportance);
          if (!bs || !(bs->pdf > 0)) break;
          throughput *= bs->f * (ImportanceCosine(*si, bsdf, si->wo, bs->wi) / bs->pdf);
          ray = si->SpawnRay(bs->wi);
          if (throughput.HasNaN() || throughput.HasInf()) {
            ++c.nan;
            break;
          }
          if (throughput.IsBlack()) break;
          if (depth + 1 >= s_.rr_depth) {
            const float q = std::min(throughput.Max(), 0.95f);
            if (sp.Get1D() >= q) break;
            throughput = throughput / q;
          }
        }
      }
    });
    // The deposits into the pixels, in photon order (the same sums on any thread count).
    for (const std::vector<Deposit>& chunk : deposits)
      for (const Deposit& d : chunk) {
        const bool finite = std::isfinite(d.xyz.x) && std::isfinite(d.xyz.y) && std::isfinite(d.xyz.z);
        if (!finite) continue;
        SppmPixel& px = pixels[d.pixel];
        for (int k = 0; k < 3; ++k) px.phi[k] += d.xyz[k];
        ++px.m;
      }

    // 3. The progressive update.
    tbb::parallel_for(size_t(0), pixels.size(), [&](size_t i) {
      SppmPixel& px = pixels[i];
      if (px.m > 0) {
        const double n_new = px.n + s_.alpha * double(px.m);
        const double shrink = n_new / (px.n + double(px.m));  // r'^2 / r^2
        for (int k = 0; k < 3; ++k) px.tau[k] = (px.tau[k] + px.phi[k]) * shrink;
        px.n = n_new;
        px.radius *= std::sqrt(shrink);
      }
      px.m = 0;
      px.phi[0] = px.phi[1] = px.phi[2] = 0;
    });
    ++done;
    progress->Update(int64_t(width) * height);
  }
  if (own_progress) own_progress->Done();

  // The pixels: the direct part's mean plus the photons' density estimate, with the filter's
  // weights (1 for the usual filters: then weight = iterations).
  const double emitted_photons = double(photons) * done;
  RenderStats stats;
  for (int row = 0; row < height; ++row)
    for (int i = 0; i < width; ++i) {
      const SppmPixel& px = pixels[size_t(row) * width + i];
      const Vec2i pixel(crop.x0 + i, crop.y0 + row);
      if (done == 0) continue;
      Vec3f xyz(0.f), emitted(0.f);
      if (px.weight != 0) {
        const double area = std::numbers::pi * px.radius * px.radius;
        // tau / (N_emitted pi r^2) is the mean over the iterations of w L (w in the visible
        // point's beta): times the iterations, a sum of w L as the direct part's.
        const double photon_scale = area > 0 ? done / (emitted_photons * area) : 0;
        for (int k = 0; k < 3; ++k) {
          xyz[k] = float((px.direct[k] + px.tau[k] * photon_scale) / px.weight);
          emitted[k] = float(px.emitted[k] / px.weight);
        }
      }
      film.AddXyzSample(pixel, xyz, 1.f);
      if (keep_emitted) film.AddEmittedXyz(pixel, emitted, 1.f);
      film.AddSampleCount(pixel, done);
    }

  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats.spp = iterations;
  stats.width = width;
  stats.height = height;
  stats.pixels = uint64_t(width) * height;
  stats.skipped_rays = scene_.SkippedRays() - skipped_before;
  stats.pixels_completed = PixelsDone(film, sampler, options.spp_end);
  for (const RenderCounters& c : counters) {
    stats.rays += c.rays.closest + c.rays.shadow;
    stats.camera_rays_traced += c.camera.traced;
    stats.camera_rays_passed += c.camera.passed;
    stats.nan_count += c.nan;
    stats.inf_count += c.inf;
  }
  stats.samples = uint64_t(done) * width * height;
  return stats;
}

}  // namespace objektiv
