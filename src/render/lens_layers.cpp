#include "render/lens_layers.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <spdlog/spdlog.h>

#include "camera/realistic_camera.h"
#include "optics/real_fnumber.h"
#include "render/diffraction_glare.h"
#include "render/glare_light_tracer.h"
#include "render/lens_flare.h"

namespace objektiv {

namespace {

const RealisticCamera* WithEffects(const Camera& camera) {
  const auto* real = dynamic_cast<const RealisticCamera*>(&camera);
  return real && real->effects().Any() ? real : nullptr;
}

void Add(std::vector<float>& to, const std::vector<float>& from) {
  for (size_t i = 0; i < from.size(); ++i) to[i] += from[i];
}

// The stop's opening with the aperture mask over it, less a central obstruction's shadow, in
// stop radii.
PupilFunction StopPupil(const RealisticCamera& camera) {
  const StopShape& shape = camera.lens().stop_shape();
  const ApertureMask* mask = camera.settings().aperture_mask.get();
  const double hidden = ObstructionRatio(camera.lens());
  return [&shape, mask, hidden](double u, double v) {
    if (!shape.Contains(u, v) || u * u + v * v < hidden * hidden) return 0.0;
    return mask ? double(mask->Transmittance(float(u), float(v))) : 1.0;
  };
}

}  // namespace

std::vector<float> LensLayers::Sum() const {
  std::vector<float> sum = primary;
  Add(sum, ghosts);
  Add(sum, diffraction);
  return sum;
}

uint64_t LensEffectsBytes(const Camera& camera, const CropWindow& crop, int threads) {
  const RealisticCamera* real = WithEffects(camera);
  if (!real) return 0;
  const uint64_t pixels = uint64_t(crop.Width()) * crop.Height();
  // Layers and the sum (XYZ floats), the emitted light (doubles), each thread's two flare images.
  uint64_t bytes = pixels * 12 * 5 + pixels * 24 + uint64_t(std::max(threads, 1)) * pixels * 24;
  // The light-traced glare: its sums (doubles), counts and a chunk of paths' landings.
  if (real->effects().ghosts && real->effects().glare_samples > 0) bytes += pixels * 28 + (uint64_t(1) << 20);
  if (real->effects().diffraction != DiffractionScope::kOff) {
    // The fine pattern (at most 4096^2: input, transform, pattern) and the padded image's FFTs.
    const uint64_t fine = uint64_t(4096) * 4096;
    const int reach = 2 * 512;  // the kernel's radius is at most half the fine grid in pixels, in practice far less
    const uint64_t padded = uint64_t(crop.Width() + reach) * (crop.Height() + reach);
    bytes += fine * 24 + padded * (8 + 16 + 16);
  }
  return bytes;
}

void PrepareFilmForLensEffects(const Camera& camera, Film& film) {
  if (const RealisticCamera* real = WithEffects(camera))
    if (real->effects().diffraction == DiffractionScope::kEmitters) film.KeepEmitted();
}

LensLayers ComposeLensLayers(const Scene& scene, const Camera& camera, const Film& film, uint64_t seed,
                             const std::atomic<bool>* stop) {
  LensLayers out;
  const CropWindow& crop = film.crop();
  out.width = crop.Width(), out.height = crop.Height();
  out.primary = film.Xyz();
  const RealisticCamera* real = WithEffects(camera);
  if (!real) return out;
  const LensEffects& e = real->effects();

  FlareSettings flare;
  flare.ghosts = e.ghosts;
  flare.light_images = true;
  flare.grid = e.ghost_grid;
  flare.wavelengths = e.wavelengths;
  flare.cull = e.ghost_cull;
  flare.stop = stop;
  FlareImages f = RenderFlare(scene, *real, crop, flare);
  out.stopped = f.stopped;
  for (const std::unique_ptr<Light>& light : scene.lights()) out.other_lights += !light->IsDelta();
  out.flare_sources = f.sources, out.ghosts_traced = f.ghosts_traced, out.ghosts_culled = f.ghosts_culled;
  out.ghosts_dark = f.ghosts_dark;
  out.ghost_seconds = f.seconds;
  Add(out.primary, f.lights);
  if (e.ghosts) out.ghosts = std::move(f.ghosts);
  if (e.ghosts && e.glare_samples > 0) {
    // As many paths per pixel of the whole film whatever the crop: a crop's pixels get the
    // full render's noise.
    GlareSettings g;
    g.paths = int64_t(e.glare_samples) * real->width() * real->height();
    g.seed = seed;
    g.stop = stop;
    spdlog::debug("ghosts and glare by light tracing: {} paths", g.paths);
    const GlareImage glare = TraceGlare(scene, *real, crop, g);
    out.stopped = out.stopped || glare.paths < g.paths;
    Add(out.ghosts, glare.xyz);
    out.glare_paths = glare.paths, out.glare_landed = glare.landed, out.glare_paths_asked = g.paths;
    out.glare_median_landings = glare.median_landings;
    out.glare_seconds = glare.seconds;
  }

  if (e.diffraction == DiffractionScope::kOff || (stop && stop->load())) {
    out.stopped = out.stopped || (stop && stop->load());
    return out;
  }
  const auto start = std::chrono::steady_clock::now();
  // The light to spread: what came straight from emitters (the bright points' images with
  // it), or everything.
  std::vector<float> light;
  if (e.diffraction == DiffractionScope::kEmitters) {
    light = film.EmittedXyz();
    Add(light, f.lights);
  } else {
    light = out.primary;
    Add(light, out.ghosts);
  }
  out.fnumber = real->WorkingFNumber();
  const Vec2d pitch = real->PixelSize() * 1e3;  // um
  const int reach = int(std::ceil(std::hypot(crop.Width(), crop.Height())));
  const DiffractionKernel kernel = MakeDiffractionKernel(StopPupil(*real), out.fnumber, pitch.x, pitch.y, reach, e.wavelengths);
  out.diffraction_radius = kernel.radius;
  std::vector<float> spread = light;
  ApplyDiffraction(spread, out.width, out.height, kernel);
  out.diffraction.resize(spread.size());
  for (size_t i = 0; i < spread.size(); ++i) out.diffraction[i] = spread[i] - light[i];
  out.diffraction_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace objektiv
