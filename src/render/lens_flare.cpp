#include "render/lens_flare.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include "base/cie.h"
#include "base/log.h"
#include "optics/compiled_sequence.h"

namespace objektiv {

namespace {

constexpr double kFlareLambdaMin = 380, kFlareLambdaMax = 780, kRegionLambda = 580;
// one_geometry's wavelength, near the middle of the eye's sensitivity.
constexpr double kOneGeometryLambda = 550;

// A path to trace for one source: a ghost or the direct image, with the region its light
// gets through (found once, at 580 nm, for all wavelengths).
struct FlarePath {
  std::optional<Ghost> ghost;  // none: the direct image
  BundleRegion region;
};

// Every ghost of `source` whose light gets through the lens, with its region and its levels:
// the flux of a coarse bundle (grid 8) that lands on the film rectangle [lo, hi], at each of
// kCullLambdas (a coating reflects least in the green, more toward blue and red: one
// wavelength would misjudge coated ghosts).
constexpr std::array<double, 3> kCullLambdas = {450, 550, 650};
struct LitGhost {
  FlarePath path;
  std::array<double, 3> level{};
};
// Without culling (`levels` false) the levels are left 0.
std::vector<LitGhost> LitGhosts(const LensSystem& lens, const std::vector<Ghost>& ghosts, const PointSource& source,
                                const BundleOptions& options, int region_grid, bool levels, Vec2d lo, Vec2d hi) {
  std::vector<std::optional<BundleRegion>> regions(ghosts.size());
  std::vector<std::array<double, 3>> level(ghosts.size());
  tbb::parallel_for(size_t(0), ghosts.size(), [&](size_t g) {
    regions[g] = GhostRegion(lens, ghosts[g], source, kRegionLambda, region_grid);
    if (!regions[g] || !levels) return;
    BundleOptions coarse = options;
    coarse.grid = 8, coarse.region = &*regions[g];
    for (size_t b = 0; b < kCullLambdas.size(); ++b)
      level[g][b] = FluxWithin(GhostBundle(lens, ghosts[g], source, kCullLambdas[b], coarse), lo, hi);
  });
  std::vector<LitGhost> lit;
  for (size_t g = 0; g < ghosts.size(); ++g)
    if (regions[g]) lit.push_back({{ghosts[g], *regions[g]}, level[g]});
  return lit;
}

// Which ghosts to cull: the dimmest (by their largest share of any wavelength's light on the
// film), as many as leave out together at most `share` of the ghosts' light on the film at
// every one of kCullLambdas. Ghosts without light on the film are culled.
std::vector<std::vector<bool>> Culled(const std::vector<std::vector<LitGhost>>& lit, double share) {
  std::array<double, 3> total{};
  for (const auto& ghosts : lit)
    for (const LitGhost& g : ghosts)
      for (size_t b = 0; b < total.size(); ++b) total[b] += g.level[b];
  struct Entry {
    size_t source, ghost;
    double key;
  };
  std::vector<Entry> order;
  std::vector<std::vector<bool>> culled(lit.size());
  for (size_t s = 0; s < lit.size(); ++s) culled[s].assign(lit[s].size(), false);
  if (!(share > 0)) return culled;  // every ghost traced
  for (size_t s = 0; s < lit.size(); ++s) {
    for (size_t g = 0; g < lit[s].size(); ++g) {
      double key = 0;
      for (size_t b = 0; b < total.size(); ++b)
        if (total[b] > 0) key = std::max(key, lit[s][g].level[b] / total[b]);
      order.push_back({s, g, key});
    }
  }
  std::sort(order.begin(), order.end(), [](const Entry& a, const Entry& b) { return a.key < b.key; });
  std::array<double, 3> dropped{};
  for (const Entry& e : order) {
    const LitGhost& g = lit[e.source][e.ghost];
    bool fits = true;
    for (size_t b = 0; b < total.size(); ++b) fits &= dropped[b] + g.level[b] <= share * total[b];
    if (!fits) break;
    for (size_t b = 0; b < total.size(); ++b) dropped[b] += g.level[b];
    culled[e.source][e.ghost] = true;
  }
  return culled;
}

}  // namespace

FlareSettings FlareSettings::Preview() {
  FlareSettings s;
  s.grid = 16;
  s.edge_levels = 1;
  s.region_grid = 8;
  s.wavelengths = 32;
  s.cull = 0;
  s.pixel_centres = true;
  s.half_resolution_from = 64;
  s.one_geometry = true;
  return s;
}

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
  if (lens.prescription().CrystalCount() > 0)
    spdlog::warn("ghosts: {} has birefringent crystals; the ghosts and the lights' images are traced for their ordinary "
                 "waves only (no second, extraordinary image)", lens.prescription().name);
  FilmRaster raster;
  raster.width = out.width, raster.height = out.height;
  const Vec2d pixel = camera.PixelSize(), origin = camera.FilmOrigin();
  raster.w = pixel.x, raster.h = pixel.y;
  raster.x0 = origin.x + crop.x0 * pixel.x, raster.y0 = origin.y + crop.y0 * pixel.y;

  // Film irradiance to pixel value, and the wavelength bins' colour weights.
  const double to_pixel = 4 / M_PI * camera.settings().exposure_scale;
  const int k_count = settings.one_geometry ? std::clamp(settings.wavelengths, 1, CompiledSequence::kMaxBands)
                                            : std::max(1, settings.wavelengths);
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
  options.edge_levels = settings.edge_levels;
  if (const ApertureMask* mask = camera.settings().aperture_mask.get())
    options.stop_transmittance = [mask](double u, double v) { return double(mask->Transmittance(float(u), float(v))); };
  BundleOptions direct_options = options;
  direct_options.lossless = !camera.settings().transmission;
  // Culling over all the lights at once: each ghost's light on the film
  // times its light's brightness; the dimmest, together at most `cull` of all the ghosts'
  // light there, are left out.
  std::vector<std::vector<LitGhost>> lit(sources.size());
  // The whole film, whatever the crop (a crop's ghosts are the full render's there).
  const Vec2d film_a = origin, film_b(origin.x + camera.width() * pixel.x, origin.y + camera.height() * pixel.y);
  const Vec2d film_lo(std::min(film_a.x, film_b.x), std::min(film_a.y, film_b.y)),
      film_hi(std::max(film_a.x, film_b.x), std::max(film_a.y, film_b.y));
  if (settings.ghosts)
    for (size_t s = 0; s < sources.size(); ++s) {
      lit[s] = LitGhosts(lens, all, sources[s].source, options, settings.region_grid, settings.cull > 0, film_lo, film_hi);
      out.ghosts_dark += int(all.size() - lit[s].size());
      for (LitGhost& g : lit[s])
        for (size_t b = 0; b < kCullLambdas.size(); ++b)
          g.level[b] *= sources[s].irradiance_scale * sources[s].visibility * sources[s].Emission(kCullLambdas[b]);
    }
  const std::vector<std::vector<bool>> culled = Culled(lit, settings.cull);
  for (size_t s = 0; s < sources.size(); ++s) {
    for (size_t g = 0; g < lit[s].size(); ++g) {
      if (!culled[s][g]) {
        paths[s].push_back(lit[s][g].path);
        ++out.ghosts_traced;
      } else {
        ++out.ghosts_culled;
      }
    }
    if (settings.light_images)
      if (std::optional<BundleRegion> r = DirectRegion(lens, sources[s].source, kRegionLambda, settings.region_grid))
        paths[s].push_back({std::nullopt, *r});
  }
  for (size_t s = 0; s < sources.size(); ++s)
    for (const FlarePath& p : paths[s])
      if (settings.one_geometry) {
        tasks.push_back({&sources[s], &p, kOneGeometryLambda});
      } else {
        for (double l : lambdas) tasks.push_back({&sources[s], &p, l});
      }
  // The wavelength's colour for a source: its emission times the matching functions
  // integrated over the wavelength's band (so that few bands keep white light white).
  auto band_weight = [&](const FlareSource& f, double lambda) {
    const Vec3d colour = CieXyzOverBand(lambda - 0.5 * step, lambda + 0.5 * step, [&f](double l) { return f.Emission(l); });
    return colour * (to_pixel * f.irradiance_scale * f.visibility / CieYIntegral());
  };
  // One geometry: each source's spectrum (the losses at every wavelength on a lattice of each
  // bundle's rays), the coatings' reflectances from tables kept from frame to frame.
  std::vector<BundleSpectrum> spectra(settings.one_geometry ? sources.size() : 0);
  for (size_t s = 0; s < spectra.size(); ++s) {
    spectra[s].wavelengths = lambdas;
    for (double l : lambdas) spectra[s].weights.push_back(band_weight(sources[s], l));
  }
  std::shared_ptr<const CoatingTables> coating_tables;
  if (settings.one_geometry) {
    coating_tables = CoatingTables::Shared(lens, lambdas);
    options.coating_tables = direct_options.coating_tables = coating_tables.get();
  }
  out.sources = int(sources.size());

  // Deterministic on any number of threads: the tasks go in chunks; a chunk's bundles are
  // traced in parallel, then splatted in parallel by bands of rows, each band taking the
  // chunk's bundles in task order (so every pixel's sum has one order).
  struct Traced {
    std::vector<FilmTriangle> bundle;
    Vec3d weight{0.0};  // but for one_geometry, whose triangles carry their colours
    bool ghost = false;
    bool half = false;  // splatted at half the resolution
  };
  constexpr double kHalfResolutionContrast = 4;
  // Whether a ghost's light spans settings.half_resolution_from pixels both ways on the crop,
  // with no focused core (tests/test_ghosts.cpp: within 12% at half the resolution up to a
  // contrast of 3; at 5.6 and above, its core blurred by 24% and more).
  auto large = [&](const std::vector<FilmTriangle>& bundle) {
    if (settings.half_resolution_from <= 0 || bundle.empty()) return false;
    Vec2d lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
    for (const FilmTriangle& t : bundle)
      for (const Vec2d& p : {t.a, t.b, t.c}) {
        lo = Vec2d(std::min(lo.x, p.x), std::min(lo.y, p.y));
        hi = Vec2d(std::max(hi.x, p.x), std::max(hi.y, p.y));
      }
    // In pixels, clamped to the crop.
    auto span = [](double a, double b, double origin, double size, int pixels) {
      const double u = (a - origin) / size, v = (b - origin) / size;
      return std::clamp(std::max(u, v), 0.0, double(pixels)) - std::clamp(std::min(u, v), 0.0, double(pixels));
    };
    return span(lo.x, hi.x, raster.x0, raster.w, raster.width) >= settings.half_resolution_from &&
           span(lo.y, hi.y, raster.y0, raster.h, raster.height) >= settings.half_resolution_from &&
           IrradianceContrast(bundle) <= kHalfResolutionContrast;
  };
  const FilmRaster half_raster = HalfResolution(raster);
  std::vector<float> half_ghosts(settings.half_resolution_from > 0 && settings.ghosts
                                     ? size_t(half_raster.width) * half_raster.height * 3
                                     : 0,
                                 0.f);
  std::atomic<bool> any_half = false;
  constexpr size_t kChunk = 64;
  constexpr int kBandRows = 32;
  const int bands = (out.height + kBandRows - 1) / kBandRows;
  std::vector<Traced> traced(kChunk);
  for (size_t first = 0; first < tasks.size(); first += kChunk) {
    if (settings.stop && settings.stop->load(std::memory_order_relaxed)) {
      out.stopped = true;
      break;
    }
    const size_t count = std::min(kChunk, tasks.size() - first);
    tbb::parallel_for(size_t(0), count, [&](size_t k) {
      const Task& t = tasks[first + k];
      const FlareSource& f = *t.source;
      const FlarePath& p = *t.path;
      BundleOptions o = p.ghost ? options : direct_options;
      o.region = &p.region;
      if (settings.one_geometry) o.spectrum = &spectra[size_t(t.source - sources.data())];
      Traced& r = traced[k];
      r.ghost = p.ghost.has_value();
      r.bundle = p.ghost ? GhostBundle(lens, *p.ghost, f.source, t.lambda, o) : DirectBundle(lens, f.source, t.lambda, o);
      r.half = r.ghost && large(r.bundle);
      if (r.half) any_half = true;
      // The band's colour, its geometry at the band's middle.
      if (!settings.one_geometry) r.weight = band_weight(f, t.lambda);
    });
    tbb::parallel_for(0, bands, [&](int band) {
      // The band's rows, and at half the resolution half as many (kBandRows is even).
      auto rows_of = [&](const FilmRaster& r, int first, int count) {
        FilmRaster rows = r;
        rows.height = std::max(0, std::min(count, r.height - first));
        rows.y0 = r.y0 + first * r.h;
        return rows;
      };
      const FilmRaster rows = rows_of(raster, band * kBandRows, kBandRows);
      const FilmRaster half_rows = rows_of(half_raster, band * kBandRows / 2, kBandRows / 2);
      for (size_t k = 0; k < count; ++k) {
        const Traced& tr = traced[k];
        const FilmRaster& into = tr.half ? half_rows : rows;
        if (into.height == 0) continue;
        float* image = tr.half    ? half_ghosts.data() + size_t(band) * kBandRows / 2 * half_raster.width * 3
                       : tr.ghost ? out.ghosts.data() + size_t(band) * kBandRows * out.width * 3
                                  : out.lights.data() + size_t(band) * kBandRows * out.width * 3;
        if (settings.one_geometry) {
          SplatTinted(tr.bundle, into, image, settings.pixel_centres);
        } else {
          SplatColour(tr.bundle, into, tr.weight, image, settings.pixel_centres);
        }
      }
    });
  }
  if (any_half)
    tbb::parallel_for(0, bands, [&](int band) {
      const int y0 = band * kBandRows;
      AddUpsampled(half_ghosts.data(), out.width, out.height, y0, std::min(y0 + kBandRows, out.height), out.ghosts.data());
    });
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace objektiv
