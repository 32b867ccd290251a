#include "render/lens_flare.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>
#include <optional>

#include "base/cie.h"

namespace objektiv {

namespace {

constexpr double kFlareLambdaMin = 380, kFlareLambdaMax = 780, kRegionLambda = 580;

// The flux of a bundle over the film area it covers: its mean irradiance.
double MeanIrradiance(const std::vector<FilmTriangle>& bundle) {
  double flux = 0, area = 0;
  for (const FilmTriangle& t : bundle) flux += t.flux, area += t.Area();
  return area > 0 ? flux / area : 0;
}

// A path to trace for one source: a ghost or the direct image, with the region its light
// gets through (found once, at 580 nm, for all wavelengths).
struct FlarePath {
  std::optional<Ghost> ghost;  // none: the direct image
  BundleRegion region;
};

// The ghosts of `source` worth tracing (see lens_flare.h: culling), with their regions.
std::vector<FlarePath> BrightGhosts(const LensSystem& lens, const std::vector<Ghost>& ghosts, const PointSource& source,
                                    double cull) {
  std::vector<std::optional<BundleRegion>> regions(ghosts.size());
  std::vector<double> level(ghosts.size(), 0);
  tbb::parallel_for(size_t(0), ghosts.size(), [&](size_t g) {
    regions[g] = GhostRegion(lens, ghosts[g], source, kRegionLambda);
    if (regions[g]) level[g] = MeanIrradiance(GhostBundle(lens, ghosts[g], source, kRegionLambda, 8, &*regions[g]));
  });
  double brightest = 0;
  for (double l : level) brightest = std::max(brightest, l);
  std::vector<FlarePath> kept;
  for (size_t g = 0; g < ghosts.size(); ++g)
    if (level[g] > 0 && level[g] >= cull * brightest) kept.push_back({ghosts[g], *regions[g]});
  return kept;
}

}  // namespace

FlareImages RenderFlare(const Scene& scene, const RealisticCamera& camera, const CropWindow& crop,
                        const FlareSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  FlareImages out;
  out.width = crop.Width(), out.height = crop.Height();
  const size_t values = size_t(out.width) * out.height * 3;
  out.ghosts.assign(settings.ghosts ? values : 0, 0.f);
  out.lights.assign(settings.light_images ? values : 0, 0.f);
  if (!settings.ghosts && !settings.light_images) return out;

  const LensSystem& lens = camera.lens();
  FilmRaster raster;
  raster.width = out.width, raster.height = out.height;
  const Vec2d pixel = camera.PixelSize(), origin = camera.FilmOrigin();
  raster.w = pixel.x, raster.h = pixel.y;
  raster.x0 = origin.x + crop.x0 * pixel.x, raster.y0 = origin.y + crop.y0 * pixel.y;

  // Film irradiance to pixel value, and the wavelength bins' colour weights.
  const double to_pixel = 4 / M_PI * camera.settings().exposure_scale;
  const int k_count = std::max(1, settings.wavelengths);
  const double step = (kFlareLambdaMax - kFlareLambdaMin) / k_count;
  std::vector<double> lambdas;
  for (int k = 0; k < k_count; ++k) lambdas.push_back(kFlareLambdaMin + (k + 0.5) * step);

  // Every (source, path, wavelength) is a task.
  struct Task {
    const FlareSource* source;
    const FlarePath* path;
    double lambda;
  };
  const std::vector<FlareSource> sources = FindFlareSources(scene, camera);
  const std::vector<Ghost> all = TwoReflectionGhosts(lens);
  std::vector<std::vector<FlarePath>> paths(sources.size());
  std::vector<Task> tasks;
  for (size_t s = 0; s < sources.size(); ++s) {
    if (settings.ghosts) {
      paths[s] = BrightGhosts(lens, all, sources[s].source, settings.cull);
      out.ghosts_traced += int(paths[s].size());
      out.ghosts_culled += int(all.size() - paths[s].size());
    }
    if (settings.light_images)
      if (std::optional<BundleRegion> r = DirectRegion(lens, sources[s].source, kRegionLambda))
        paths[s].push_back({std::nullopt, *r});
  }
  for (size_t s = 0; s < sources.size(); ++s)
    for (const FlarePath& p : paths[s])
      for (double l : lambdas) tasks.push_back({&sources[s], &p, l});
  out.sources = int(sources.size());

  struct Images {
    std::vector<float> ghosts, lights;
  };
  tbb::enumerable_thread_specific<Images> local([&] { return Images{std::vector<float>(out.ghosts.size(), 0.f), std::vector<float>(out.lights.size(), 0.f)}; });
  tbb::parallel_for(size_t(0), tasks.size(), [&](size_t i) {
    const Task& t = tasks[i];
    const FlareSource& f = *t.source;
    const FlarePath& p = *t.path;
    std::vector<FilmTriangle> bundle = p.ghost ? GhostBundle(lens, *p.ghost, f.source, t.lambda, settings.grid, &p.region)
                                               : DirectBundle(lens, f.source, t.lambda, settings.grid, &p.region);
    if (bundle.empty()) return;
    const double w = to_pixel * f.irradiance_scale * f.visibility * f.Emission(t.lambda) * step / CieYIntegral();
    const Vec3f cie = CieXyz(float(t.lambda));
    Images& images = local.local();
    SplatColour(bundle, raster, Vec3d(w * cie.x, w * cie.y, w * cie.z), p.ghost ? images.ghosts.data() : images.lights.data());
  });
  for (const Images& images : local) {
    for (size_t i = 0; i < out.ghosts.size(); ++i) out.ghosts[i] += images.ghosts[i];
    for (size_t i = 0; i < out.lights.size(); ++i) out.lights[i] += images.lights[i];
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace objektiv
