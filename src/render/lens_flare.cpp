#include "render/lens_flare.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "base/cie.h"

namespace objektiv {

namespace {

constexpr double kFlareLambdaMin = 380, kFlareLambdaMax = 780, kRegionLambda = 580;

// The flux a bundle carries to the film.
double BundleFlux(const std::vector<FilmTriangle>& bundle) {
  double flux = 0;
  for (const FilmTriangle& t : bundle) flux += t.flux;
  return flux;
}

// A path to trace for one source: a ghost or the direct image, with the region its light
// gets through (found once, at 580 nm, for all wavelengths).
struct FlarePath {
  std::optional<Ghost> ghost;  // none: the direct image
  BundleRegion region;
};

// Every ghost of `source` whose light reaches the film, with its region and its level: the
// flux of a coarse bundle at 580 nm (see lens_flare.h: culling).
struct LitGhost {
  FlarePath path;
  double level = 0;
};
std::vector<LitGhost> LitGhosts(const LensSystem& lens, const std::vector<Ghost>& ghosts, const PointSource& source,
                                const BundleOptions& options) {
  std::vector<std::optional<BundleRegion>> regions(ghosts.size());
  std::vector<double> level(ghosts.size(), 0);
  tbb::parallel_for(size_t(0), ghosts.size(), [&](size_t g) {
    regions[g] = GhostRegion(lens, ghosts[g], source, kRegionLambda);
    if (!regions[g]) return;
    BundleOptions coarse = options;
    coarse.grid = 8, coarse.region = &*regions[g];
    level[g] = BundleFlux(GhostBundle(lens, ghosts[g], source, kRegionLambda, coarse));
  });
  std::vector<LitGhost> lit;
  for (size_t g = 0; g < ghosts.size(); ++g)
    if (level[g] > 0) lit.push_back({{ghosts[g], *regions[g]}, level[g]});
  return lit;
}

// The level at and below which ghosts are culled: the largest such that the ghosts at or below
// it hold no more than `share` of the light of all (0 keeps every ghost with light; a ghost
// without light is never traced).
double CullLevel(const std::vector<std::vector<LitGhost>>& lit, double share) {
  std::vector<double> levels;
  double total = 0;
  for (const auto& ghosts : lit)
    for (const LitGhost& g : ghosts) levels.push_back(g.level), total += g.level;
  std::sort(levels.begin(), levels.end());
  double cut = 0, below = 0;
  for (double level : levels) {
    if (below + level > share * total) break;
    below += level, cut = level;
  }
  return cut;
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
  // The bundles' options: the aperture mask's grey levels at the stop; the camera's
  // transmission off leaves the lights' own images without losses (ghosts need reflections).
  BundleOptions options;
  options.grid = settings.grid;
  if (const ApertureMask* mask = camera.settings().aperture_mask.get())
    options.stop_transmittance = [mask](double u, double v) { return double(mask->Transmittance(float(u), float(v))); };
  BundleOptions direct_options = options;
  direct_options.lossless = !camera.settings().transmission;
  // Culling over all the lights at once: each ghost's flux times its light's brightness; the
  // dimmest ghosts, together less than `cull` of all the ghosts' light, are left out.
  std::vector<std::vector<LitGhost>> lit(sources.size());
  if (settings.ghosts)
    for (size_t s = 0; s < sources.size(); ++s) {
      lit[s] = LitGhosts(lens, all, sources[s].source, options);
      out.ghosts_dark += int(all.size() - lit[s].size());
      const double brightness = sources[s].irradiance_scale * sources[s].visibility * sources[s].Emission(kRegionLambda);
      for (LitGhost& g : lit[s]) g.level *= brightness;
    }
  const double kept_from = CullLevel(lit, settings.cull);
  for (size_t s = 0; s < sources.size(); ++s) {
    for (const LitGhost& g : lit[s]) {
      if (g.level > kept_from) {
        paths[s].push_back(g.path);
        ++out.ghosts_traced;
      } else {
        ++out.ghosts_culled;
      }
    }
    if (settings.light_images)
      if (std::optional<BundleRegion> r = DirectRegion(lens, sources[s].source, kRegionLambda))
        paths[s].push_back({std::nullopt, *r});
  }
  for (size_t s = 0; s < sources.size(); ++s)
    for (const FlarePath& p : paths[s])
      for (double l : lambdas) tasks.push_back({&sources[s], &p, l});
  out.sources = int(sources.size());

  // Deterministic on any number of threads: the tasks go in chunks; a chunk's bundles are
  // traced in parallel, then splatted in parallel by bands of rows, each band taking the
  // chunk's bundles in task order (so every pixel's sum has one order).
  struct Traced {
    std::vector<FilmTriangle> bundle;
    Vec3d weight{0.0};
    bool ghost = false;
  };
  constexpr size_t kChunk = 64;
  constexpr int kBandRows = 16;
  const int bands = (out.height + kBandRows - 1) / kBandRows;
  std::vector<Traced> traced(kChunk);
  for (size_t first = 0; first < tasks.size(); first += kChunk) {
    const size_t count = std::min(kChunk, tasks.size() - first);
    tbb::parallel_for(size_t(0), count, [&](size_t k) {
      const Task& t = tasks[first + k];
      const FlareSource& f = *t.source;
      const FlarePath& p = *t.path;
      BundleOptions o = p.ghost ? options : direct_options;
      o.region = &p.region;
      Traced& r = traced[k];
      r.ghost = p.ghost.has_value();
      r.bundle = p.ghost ? GhostBundle(lens, *p.ghost, f.source, t.lambda, o) : DirectBundle(lens, f.source, t.lambda, o);
      // The band's colour: the emission times the matching functions integrated over the band
      // (so that few bands keep white light white), its geometry at the band's middle.
      const Vec3d colour =
          CieXyzOverBand(t.lambda - 0.5 * step, t.lambda + 0.5 * step, [&f](double l) { return f.Emission(l); });
      r.weight = colour * (to_pixel * f.irradiance_scale * f.visibility / CieYIntegral());
    });
    tbb::parallel_for(0, bands, [&](int band) {
      FilmRaster rows = raster;
      const int y0 = band * kBandRows;
      rows.height = std::min(kBandRows, out.height - y0);
      rows.y0 = raster.y0 + y0 * raster.h;
      const size_t offset = size_t(y0) * out.width * 3;
      for (size_t k = 0; k < count; ++k)
        SplatColour(traced[k].bundle, rows, traced[k].weight,
                    (traced[k].ghost ? out.ghosts.data() : out.lights.data()) + offset);
    });
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace objektiv
