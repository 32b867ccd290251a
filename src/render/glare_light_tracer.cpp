#include "render/glare_light_tracer.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "base/interrupt.h"
#include "base/sampling.h"
#include "optics/front_element.h"
#include "optics/ghosts.h"
#include "optics/lens_walk.h"

namespace objektiv {

namespace {

// What one path leaves on the crop window: a pixel (or none) and its XYZ; and for the
// guide, the light and the front element's cell it came through.
struct Landing {
  uint32_t pixel = std::numeric_limits<uint32_t>::max();
  float xyz[3] = {0, 0, 0};
  int light = -1, cell = -1;
  float light_pmf = 0;  // the light's chance of being chosen
};

// Guiding: the front element's points are chosen through u in [0, 1)^2 (optics/front_element.h:
// equal areas for equal u); per light, a grid of kGuideCells^2 cells of u. The first eighth of
// the paths choose u uniformly and record which cells their landings came through (weighted
// by their luminance); the rest choose u from each light's record mixed half and half with the
// uniform density (so no cell is ever left out: unbiased; no weight above 2), which sends them
// where the light gets through the lens (at f/11 a few percent of the front element).
constexpr int kGuideCells = 16;
constexpr int64_t kMinGuideLandings = 256;  // a light's record guides its paths from this many landings on
constexpr double kUniformShare = 0.5;

class FrontGuide {
 public:
  FrontGuide() = default;
  explicit FrontGuide(const std::vector<double>& weights) {
    double total = 0;
    for (double w : weights) total += w;
    if (!(total > 0)) return;
    std::vector<float> f(weights.size());
    for (size_t i = 0; i < f.size(); ++i)
      f[i] = float(kUniformShare + (1 - kUniformShare) * weights[i] * double(weights.size()) / total);
    dist_ = Distribution2D(f, kGuideCells, kGuideCells);
    guided_ = true;
  }
  // u in [0, 1)^2 and its density (1: uniform).
  Vec2f Sample(Vec2f u, float* pdf) const {
    if (!guided_) {
      *pdf = 1;
      return u;
    }
    return dist_.Sample(u, pdf);
  }

 private:
  Distribution2D dist_;
  bool guided_ = false;
};

// The lights are guided the same way: the first half of the learning paths choose them by
// power and record how much of their light lands; the later paths choose them in proportion to a mixture of that record
// (kLearnedLightShare) and the power (the rest: every light keeps a chance, weights stay
// below 1 / (1 - kLearnedLightShare)). A light whose light cannot reach the film (behind the
// camera, behind a wall) then takes a quarter of its power share instead of all of it.
constexpr double kLearnedLightShare = 0.75;

class LightGuide {
 public:
  LightGuide() = default;
  LightGuide(const Scene& scene, const std::vector<double>& landed) {
    double total = 0;
    for (double w : landed) total += w;
    if (!(total > 0)) return;
    std::vector<float> f(landed.size());
    for (size_t i = 0; i < f.size(); ++i)
      f[i] = float((1 - kLearnedLightShare) * scene.LightPmf(scene.lights()[i].get()) +
                   kLearnedLightShare * landed[i] / total);
    dist_ = Distribution1D(f);
    guided_ = true;
  }
  const Light* Sample(const Scene& scene, float u, float* pmf) const {
    if (!guided_) return scene.SampleLight(u, pmf);
    return scene.lights()[size_t(dist_.SampleDiscrete(u, pmf))].get();
  }

 private:
  Distribution1D dist_;
  bool guided_ = false;
};

// What the learning paths teach the rest: per light, its front element's cells; the lights.
struct GlareGuide {
  std::vector<FrontGuide> fronts;
  LightGuide lights;
};

int GuideCell(Vec2f u) {
  const int i = std::min(int(u.x * kGuideCells), kGuideCells - 1), j = std::min(int(u.y * kGuideCells), kGuideCells - 1);
  return j * kGuideCells + i;
}

class GlarePaths {
 public:
  GlarePaths(const Scene& scene, const RealisticCamera& camera, const CropWindow& crop, const GlareSettings& settings)
      : scene_(scene), camera_(camera), lens_(camera.lens()), crop_(crop), settings_(settings) {
    walk_.min_reflect_probability = 1.0 / std::max(int(ReflectingSurfaces(lens_).size()), 2);
    walk_.max_reflections = settings.max_reflections;
    // Ghosts are the surfaces' reflections: the walk keeps them (and the losses) whatever the
    // camera's transmission says, as the bundles do.
    if (const ApertureMask* mask = camera.settings().aperture_mask.get())
      walk_.stop_transmittance = [mask](double u, double v) { return double(mask->Transmittance(float(u), float(v))); };
    // Flux over the pixel's area, as the film's value, per path: (4 / pi) exposure_scale x
    // (front element's projected area / pixel's area) / paths (scene units cancel).
    const Vec2d pixel = camera.PixelSize();
    scale_ = 4 / M_PI * camera.settings().exposure_scale * FrontElementArea(lens_) / (pixel.x * pixel.y) /
             double(settings.paths);
  }

  // `guide`: what the learning paths found so far (at first nothing: lights by power, the
  // front uniformly).
  Landing Trace(int64_t index, const GlareGuide& guide) const {
    Landing out;
    PCG32 rng(uint64_t(index), settings_.seed);
    float pmf = 0;
    const Light* light = guide.lights.Sample(scene_, rng.UniformFloat(), &pmf);
    if (!light || !(pmf > 0)) return out;
    float u_pdf = 1;
    Vec2f u_front(rng.UniformFloat(), rng.UniformFloat());
    u_front = guide.fronts[size_t(light->index())].Sample(u_front, &u_pdf);
    if (!(u_pdf > 0)) return out;
    const FrontPoint front = SampleFrontElement(lens_, Vec2d(u_front.x, u_front.y));
    const Vec3f at = camera_.WorldPoint(front.p);
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(rng.UniformFloat());
    lambda.TerminateSecondary();
    const Vec2f u(rng.UniformFloat(), rng.UniformFloat());
    const std::optional<LightSample> ls = light->SampleLi(at, u, lambda);
    if (!ls || !(ls->pdf > 0) || !(ls->L[0] > 0)) return out;
    const Vec3d d = camera_.LensSpaceDirection(-ls->wi);  // the way the light travels
    const double projected = front.ProjectedCosine(d);
    if (projected <= 0) return out;
    const LensWalk walk = WalkFromObject(lens_, {front.p - d, d}, lambda[0], rng, walk_);
    if (!walk.film || walk.reflections < 2) return out;
    if (walk.reflections == 2 && light->IsDelta() && !settings_.delta_light_ghosts) return out;
    const Vec2d p = camera_.PixelOf(Vec2d(walk.film->o.x, walk.film->o.y));
    const double px = std::floor(p.x), py = std::floor(p.y);
    if (!(px >= crop_.x0 && px < crop_.x1 && py >= crop_.y0 && py < crop_.y1)) return out;
    // The shadow ray last: most walks are left out before it.
    Ray shadow;
    shadow.o = at;
    shadow.d = ls->wi;
    if (!ls->infinite) shadow.tmax = Length(ls->p - at) * (1 - 1e-4f);
    if (scene_.Occluded(shadow)) return out;
    const double value = double(ls->L[0]) * projected * walk.weight / (double(ls->pdf) * pmf * u_pdf) * scale_;
    const Vec3f xyz = SampledToXYZ(SampledSpectrum(float(value)), lambda);
    out.pixel = uint32_t((int(py) - crop_.y0) * crop_.Width() + (int(px) - crop_.x0));
    out.xyz[0] = xyz.x, out.xyz[1] = xyz.y, out.xyz[2] = xyz.z;
    out.light = light->index();
    out.cell = GuideCell(u_front);
    out.light_pmf = pmf;
    return out;
  }

 private:
  const Scene& scene_;
  const RealisticCamera& camera_;
  const LensSystem& lens_;
  CropWindow crop_;
  GlareSettings settings_;
  LensWalkOptions walk_;
  double scale_ = 0;
};

}  // namespace

GlareImage TraceGlare(const Scene& scene, const RealisticCamera& camera, const CropWindow& crop,
                      const GlareSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  GlareImage out;
  out.width = crop.Width(), out.height = crop.Height();
  const size_t pixels = size_t(out.width) * out.height;
  std::vector<double> sum(3 * pixels, 0.0);
  std::vector<uint32_t> landings(pixels, 0);
  if (settings.paths > 0 && !scene.lights().empty()) {
    const GlarePaths paths(scene, camera, crop, settings);
    constexpr int64_t kChunk = 1 << 16;
    std::vector<Landing> landed(kChunk);
    const size_t lights = scene.lights().size();
    std::vector<std::vector<double>> record(lights, std::vector<double>(kGuideCells * kGuideCells, 0.0));
    std::vector<double> light_landed(lights, 0.0);
    std::vector<int64_t> light_landings(lights, 0);
    // Learning in two halves: the first chooses lights by power and learns which lights' light
    // lands; the second chooses lights by that and learns, per light, where on the front
    // element it lands (a small lamp beside a powerful light behind the camera gets few
    // landings by power alone, too few to learn its front from).
    GlareGuide guide;
    guide.fronts.assign(lights, FrontGuide());
    const int64_t learn = std::max<int64_t>(settings.paths / 8, 1), learn_lights = std::max<int64_t>(learn / 2, 1);
    int64_t first = 0;
    while (first < settings.paths) {
      // Ctrl-C: stop after the chunk in progress; the paths traced stand for all (below).
      if (InterruptRequested().load(std::memory_order_relaxed)) break;
      if (settings.stop && settings.stop->load(std::memory_order_relaxed)) break;
      // The learning paths, then the guided ones (chunks never straddle the phases).
      const bool learning = first < learn;
      const int64_t end = first < learn_lights ? learn_lights : learning ? learn : settings.paths;
      const int64_t count = std::min(kChunk, end - first);
      // The first guided chunk: the learning paths are left out of the image (below).
      if (first == learn) {
        std::fill(sum.begin(), sum.end(), 0.0);
        std::fill(landings.begin(), landings.end(), 0u);
      }
      tbb::parallel_for(int64_t(0), count, [&](int64_t k) { landed[k] = paths.Trace(first + k, guide); });
      for (int64_t k = 0; k < count; ++k) {
        const Landing& l = landed[k];
        if (l.pixel == std::numeric_limits<uint32_t>::max()) continue;
        ++out.landed;
        ++landings[l.pixel];
        for (int c = 0; c < 3; ++c) sum[3 * size_t(l.pixel) + c] += l.xyz[c];
        if (learning) {
          // Where on the front element a light's light lands, whatever its chance of being
          // chosen (that changes between the halves).
          record[size_t(l.light)][size_t(l.cell)] += std::abs(l.xyz[1]) * l.light_pmf;
          light_landed[size_t(l.light)] += std::abs(l.xyz[1]);
          ++light_landings[size_t(l.light)];
        }
      }
      first += count;
      if (first == learn_lights && learn_lights < learn) guide.lights = LightGuide(scene, light_landed);
      if (first == learn) {
        // A record of few landings is mostly chance: such a light's front stays uniform.
        for (size_t i = 0; i < lights; ++i)
          if (light_landings[i] >= kMinGuideLandings) guide.fronts[i] = FrontGuide(record[i]);
        guide.lights = LightGuide(scene, light_landed);
      }
    }
    // Each path's value was divided by the paths asked for: the paths kept are rescaled to
    // stand for all (each is an estimate of the whole on its own). Once guided paths were
    // traced, the learning paths are left out: chosen by power, a small lamp beside a sun
    // behind the camera got one path in 500, each 500 times the weight, and those fireflies
    // made the image 5-26 times noisier than without the sun. (Always, not only where
    // something landed while learning: kept only where nothing did, they would add zeros
    // chosen for being zeros, a bias.) Interrupted while learning, the learning paths are all
    // there is.
    out.paths = first;
    const int64_t kept = first > learn ? first - learn : first;
    if (kept > 0 && kept < settings.paths)
      for (double& v : sum) v *= double(settings.paths) / double(kept);
  }
  out.xyz.assign(sum.begin(), sum.end());
  // The pixels that matter: brighter than 1% of a bright pixel (the 99th percentile of those
  // with light, so that a few fireflies do not set it).
  std::vector<double> ys;
  for (size_t i = 0; i < pixels; ++i)
    if (sum[3 * i + 1] > 0) ys.push_back(sum[3 * i + 1]);
  if (!ys.empty()) {
    const size_t k = std::min(ys.size() - 1, ys.size() * 99 / 100);
    std::nth_element(ys.begin(), ys.begin() + k, ys.end());
    const double bright = ys[k];
    std::vector<uint32_t> lit;
    for (size_t i = 0; i < pixels; ++i)
      if (sum[3 * i + 1] >= 0.01 * bright) lit.push_back(landings[i]);
    if (!lit.empty()) {
      std::nth_element(lit.begin(), lit.begin() + lit.size() / 2, lit.end());
      out.median_landings = lit[lit.size() / 2];
    }
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace objektiv
