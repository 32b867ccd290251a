// `objektiv render SCENE.xml`: renders a scene to a linear EXR and a tone-mapped PNG.
#include <filesystem>
#include <limits>
#include <map>
#include <thread>

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "base/error.h"
#include "base/input_files.h"
#include "base/interrupt.h"
#include "base/log.h"
#include "base/output_file.h"
#include "io/image_io.h"
#include "io/scene_loader.h"
#include "render/aov.h"
#include "render/lens_layers.h"
#include "render/renderer.h"

namespace objektiv {
namespace {

struct RenderArgs {
  std::string scene, output, stats_json, crop;
  int spp = 0, threads = 0;
  int64_t seed = -1;
  double max_memory_gib = 16;
  std::vector<std::string> defines;
  bool quiet = false, verbose = false;
};

void WriteStatsJson(const std::string& path, const RenderStats& s, int threads, const LensLayers& layers) {
  nlohmann::ordered_json j = {{"seconds", s.seconds},
                              {"spp", s.spp},
                              {"width", s.width},
                              {"height", s.height},
                              {"threads", threads},
                              {"samples", s.samples},
                              {"rays", s.rays},
                              {"samples_per_second", s.SamplesPerSecond()},
                              {"mrays_per_second", s.MraysPerSecond()},
                              {"nan_count", s.nan_count},
                              {"inf_count", s.inf_count},
                              {"camera_rays_traced", s.camera_rays_traced},
                              {"camera_pass_rate", s.CameraPassRate() ? nlohmann::json(*s.CameraPassRate()) : nlohmann::json(nullptr)},
                              {"partial", s.Partial()},
                              {"pixels", s.pixels},
                              {"pixels_completed", s.pixels_completed}};
  if (!layers.ghosts.empty()) {
    j["ghost_seconds"] = layers.ghost_seconds;
    j["ghosts_traced"] = layers.ghosts_traced;
    j["ghosts_culled"] = layers.ghosts_culled;
    j["glare_seconds"] = layers.glare_seconds;
    j["glare_paths"] = layers.glare_paths;
    j["glare_paths_asked"] = layers.glare_paths_asked;
    j["glare_paths_landed"] = layers.glare_landed;
  }
  if (!layers.diffraction.empty()) j["diffraction_seconds"] = layers.diffraction_seconds;
  WriteTextFileAtomically(path, j.dump(2) + "\n");
}

// An output file and what it is, for messages.
struct Output {
  std::string what, path;
};

// Bad outputs are bad command-line values (exit status 2), found before the long work.
// Before the scene is loaded: every output can be written (its directory exists; it is not
// created, so that a mistyped path fails instead of growing directories) and no two are one file.
void CheckOutputsWritable(const std::vector<Output>& outputs) {
  namespace fs = std::filesystem;
  for (size_t i = 0; i < outputs.size(); ++i) {
    try {
      CheckOutputFile(outputs[i].path);
    } catch (const InputError& e) {
      throw CLI::ValidationError(fmt::format("{} cannot be written: {}", outputs[i].what, e.what()));
    }
    for (size_t j = 0; j < i; ++j)
      if (fs::weakly_canonical(outputs[i].path) == fs::weakly_canonical(outputs[j].path))
        throw CLI::ValidationError(fmt::format("{} {} is also {}", outputs[i].what, outputs[i].path, outputs[j].what));
  }
}

// After the scene is loaded: no output replaces a file the scene read.
void CheckOutputsAreNotInputs(const std::vector<Output>& outputs) {
  for (const Output& o : outputs)
    if (std::optional<std::string> input = InputFileAt(o.path))
      throw CLI::ValidationError(
          fmt::format("{} {} would overwrite {}, a file the scene reads; choose another name", o.what, o.path, *input));
}

CropWindow ParseCrop(const std::string& text, int width, int height) {
  int v[4];
  if (std::sscanf(text.c_str(), "%d,%d,%d,%d", &v[0], &v[1], &v[2], &v[3]) != 4)
    throw CLI::ValidationError("--crop", "expects x0,y0,x1,y1 (pixels, half-open)");
  if (v[0] < 0 || v[1] < 0 || v[2] > width || v[3] > height || v[0] >= v[2] || v[1] >= v[3])
    throw CLI::ValidationError("--crop", fmt::format("{} is not inside the {}x{} film with x0 < x1, y0 < y1", text, width, height));
  return {v[0], v[1], v[2], v[3]};
}

// The film, once the memory of the render is known to fit the budget: nearly all of it per
// pixel of the crop window, the film's accumulators, then the linear and the tone-mapped
// images and the 8-bit PNG made from them, and what the lens effects need (`extra_bytes`).
Film MakeFilm(const FilmSettings& f, double budget_gib, uint64_t extra_bytes) {
  const uint64_t bytes = Film::AccumulatorBytes(f.crop) + uint64_t(f.crop.Width()) * f.crop.Height() * (2 * 3 * sizeof(float) + 3) + extra_bytes;
  const double gib = double(bytes) / double(1 << 30);
  if (gib > budget_gib)
    throw ErrorAt(f.loc, "rendering {}x{} pixels needs {:.3g} GiB, more than the memory budget of {:g} GiB (see --max-memory)",
                  f.crop.Width(), f.crop.Height(), gib, budget_gib);
  try {
    return Film(f.width, f.height, f.crop, f.filter);
  } catch (const std::bad_alloc&) {
    throw ErrorAt(f.loc, "not enough memory for the {}x{} film ({:.3g} GiB)", f.crop.Width(), f.crop.Height(), gib);
  }
}

// The lens's layers (render/lens_layers.h) beside the picture's R, G, B: primary.R, .G, .B,
// ghosts.*, diffraction.* (EXR layers), where the effects are on; what their passes did in
// the header and the log.
void AddLensLayers(const LensLayers& layers, const ColorSpace& cs, float exposure, Image& image,
                   std::vector<ImageAttribute>& header) {
  if (layers.ghosts.empty() && layers.diffraction.empty()) return;
  std::vector<std::pair<std::string, const std::vector<float>*>> extra = {{"primary", &layers.primary}};
  if (!layers.ghosts.empty()) extra.push_back({"ghosts", &layers.ghosts});
  if (!layers.diffraction.empty()) extra.push_back({"diffraction", &layers.diffraction});
  const int base = image.NumChannels();
  Image out(image.width, image.height, image.channels);
  for (const auto& [name, xyz] : extra)
    for (const char* c : {"R", "G", "B"}) out.channels.push_back(name + "." + c);
  out.pixels.assign(size_t(out.width) * out.height * out.channels.size(), 0.f);
  const size_t stride = out.channels.size();
  for (size_t i = 0; i < size_t(out.width) * out.height; ++i)
    for (int c = 0; c < base; ++c) out.pixels[i * stride + c] = image.pixels[i * base + c];
  for (size_t l = 0; l < extra.size(); ++l) {
    const Image rgb = XyzToImage(*extra[l].second, layers.width, layers.height, cs, exposure);
    for (size_t i = 0; i < size_t(out.width) * out.height; ++i)
      for (int c = 0; c < 3; ++c) out.pixels[i * stride + base + 3 * l + c] = rgb.pixels[i * 3 + c];
  }
  image = std::move(out);
  header.push_back({"objektiv:flare_sources", layers.flare_sources});
  if (!layers.ghosts.empty() && layers.other_lights > 0 && layers.glare_paths == 0)
    spdlog::warn("ghosts: {} area or environment light{} of the scene make{} no ghosts with glare_samples 0 (only point, "
                 "spot and directional lights do, {} here)",
                 layers.other_lights, layers.other_lights == 1 ? "" : "s", layers.other_lights == 1 ? "s" : "",
                 layers.flare_sources);
  if (!layers.ghosts.empty()) {
    header.push_back({"objektiv:ghosts_traced", layers.ghosts_traced});
    header.push_back({"objektiv:ghosts_culled", layers.ghosts_culled});
    header.push_back({"objektiv:glare_paths", double(layers.glare_paths)});
    spdlog::info("ghosts: {} bright point{}, {} ghosts traced, {} culled as too dim, {} let no light through; {:.2f} s",
                 layers.flare_sources, layers.flare_sources == 1 ? "" : "s", layers.ghosts_traced, layers.ghosts_culled,
                 layers.ghosts_dark, layers.ghost_seconds);
  }
  if (layers.glare_paths < layers.glare_paths_asked)
    spdlog::warn("interrupted: ghosts and glare by light tracing from {} of the {} paths asked for (noisier)",
                 layers.glare_paths, layers.glare_paths_asked);
  if (layers.glare_paths > 0 && layers.glare_landed == 0)
    spdlog::info("ghosts and glare by light tracing: {} paths, none landed with two or more reflections (nothing "
                 "to add); {:.2f} s",
                 layers.glare_paths, layers.glare_seconds);
  else if (layers.glare_paths > 0)
    spdlog::info("ghosts and glare by light tracing (the part of the ghosts layer beside the bright points' bundles, "
                 "which have no noise): {} paths, {} landed; a pixel of it brighter than 1% of its bright pixels "
                 "(the 99th percentile) got {:g} of them (median: relative noise about {:.0f}%; raise glare_samples "
                 "for less); {:.2f} s",
                 layers.glare_paths, layers.glare_landed, layers.glare_median_landings,
                 layers.glare_median_landings > 0 ? 100 / std::sqrt(layers.glare_median_landings) : 100.0,
                 layers.glare_seconds);
  if (!layers.diffraction.empty()) {
    header.push_back({"objektiv:diffraction_fnumber", layers.fnumber});
    header.push_back({"objektiv:diffraction_radius", layers.diffraction_radius});
    spdlog::info("diffraction at working f/{:.3g}: kernel reaching {} pixels, {:.2f} s", layers.fnumber,
                 layers.diffraction_radius, layers.diffraction_seconds);
  }
}

// The AOVs (render/aov.h) as channels of their own names after the others; albedos from the
// film's XYZ into the colour space's RGB.
void AddAovChannels(const AovIntegrator& integrator, const Film& film, const ColorSpace& cs, Image& image) {
  std::vector<std::string> names;
  std::vector<size_t> albedos;  // first channel of each
  for (const Aov& a : integrator.aovs()) {
    if (a.type == AovType::kAlbedo) albedos.push_back(names.size());
    for (const std::string& n : a.ChannelNames()) names.push_back(n);
  }
  std::vector<float> values = film.Aovs();
  for (size_t i = 0; i + names.size() <= values.size(); i += names.size())
    for (size_t a : albedos) {
      const Vec3f rgb = cs.ToRGB(Vec3f(values[i + a], values[i + a + 1], values[i + a + 2]));
      values[i + a] = rgb.x, values[i + a + 1] = rgb.y, values[i + a + 2] = rgb.z;
    }
  const size_t base = image.channels.size(), n = names.size(), pixels = size_t(image.width) * image.height;
  Image out(image.width, image.height, image.channels);
  for (const std::string& name : names) out.channels.push_back(name);
  out.pixels.assign(pixels * out.channels.size(), 0.f);
  for (size_t i = 0; i < pixels; ++i) {
    for (size_t c = 0; c < base; ++c) out.pixels[i * (base + n) + c] = image.pixels[i * base + c];
    for (size_t c = 0; c < n; ++c) out.pixels[i * (base + n) + base + c] = values[i * n + c];
  }
  image = std::move(out);
}

// The lens passes' times after the render's, for the summary line: " + bright points and
// ghosts 3.40 s + diffraction 1.15 s".
std::string LensPassTimes(const LensLayers& layers) {
  std::string text;
  if (!layers.ghosts.empty() || !layers.diffraction.empty())
    text += fmt::format(" + bright points{} {:.2f} s", layers.ghosts.empty() ? "" : " and ghosts", layers.ghost_seconds);
  if (layers.glare_paths > 0) text += fmt::format(" + glare {:.2f} s", layers.glare_seconds);
  if (!layers.diffraction.empty()) text += fmt::format(" + diffraction {:.2f} s", layers.diffraction_seconds);
  return text;
}

int RunRender(const RenderArgs& a) {
  SetupLogging(a.quiet ? 0 : (a.verbose ? 2 : 1));
  std::map<std::string, std::string> defines;
  for (const std::string& d : a.defines) {
    size_t eq = d.find('=');
    if (eq == std::string::npos || eq == 0) {
      std::fprintf(stderr, "error: -D expects name=value, got '%s'\n", d.c_str());
      return 2;
    }
    if (!defines.emplace(d.substr(0, eq), d.substr(eq + 1)).second) {
      std::fprintf(stderr, "error: -D %s is given twice\n", d.substr(0, eq).c_str());
      return 2;
    }
  }
  namespace fs = std::filesystem;
  fs::path exr = a.output.empty() ? fs::path(fs::path(a.scene).stem().string() + ".exr") : fs::path(a.output);
  if (exr.extension().empty()) exr += ".exr";
  if (exr.extension() != ".exr") {
    std::fprintf(stderr, "error: -o must name an .exr file (the PNG is written beside it)\n");
    return 2;
  }
  fs::path png = fs::path(exr).replace_extension(".png");
  std::vector<Output> outputs = {{"the EXR", exr.string()}, {"the PNG written beside the EXR", png.string()}};
  if (!a.stats_json.empty()) outputs.push_back({"--stats-json", a.stats_json});
  CheckOutputsWritable(outputs);
  RenderSetup setup = LoadScene(a.scene, defines, GlassCatalog::Default());
  CheckOutputsAreNotInputs(outputs);
  FilmSettings& fs_ = setup.film;
  if (!a.crop.empty()) {
    try {
      fs_.crop = ParseCrop(a.crop, fs_.width, fs_.height);
    } catch (const CLI::ValidationError& e) {
      std::fprintf(stderr, "error: %s\n", e.what());
      return 2;
    }
  }
  if (a.spp > 0) setup.sampler.spp = a.spp;
  if (a.seed >= 0) setup.sampler.seed = uint64_t(a.seed);
  std::unique_ptr<Sampler> sampler = MakeSampler(setup.sampler);
  int threads = a.threads > 0 ? a.threads : int(std::thread::hardware_concurrency());
  const auto* aov_integrator = dynamic_cast<const AovIntegrator*>(setup.integrator.get());
  // The AOVs: double sums, then float channels in the image (twice: the image is copied).
  const uint64_t aov_bytes =
      aov_integrator ? uint64_t(fs_.crop.Width()) * fs_.crop.Height() * aov_integrator->AovChannels() * (8 + 2 * 4) : 0;
  Film film = MakeFilm(fs_, a.max_memory_gib, LensEffectsBytes(*setup.camera, fs_.crop, threads) + aov_bytes);
  PrepareFilmForLensEffects(*setup.camera, film);
  if (aov_integrator) film.KeepAovs(aov_integrator->AovChannels());
  RenderOptions opts;
  opts.spp_begin = 0;
  opts.spp_end = sampler->spp();
  opts.threads = a.threads;
  opts.progress = !a.quiet && InteractiveTerminal();

  // From here on Ctrl-C (or SIGTERM) stops the render and the pixels done so far are written.
  InstallInterruptHandlers();
  opts.stop = &InterruptRequested();
  spdlog::info("rendering {}x{} pixels at {} spp on {} threads", fs_.crop.Width(), fs_.crop.Height(), opts.spp_end,
               threads);
  RenderStats stats = Render(*setup.camera, *setup.integrator, *sampler, film, opts);

  // A partial image holds the pixels that got all their samples; the others are zero. EXR has
  // no 64-bit integers: counts beyond 32 bits are written as doubles.
  auto count = [](uint64_t n) -> ImageAttribute::Value {
    if (n <= uint64_t(std::numeric_limits<int>::max())) return int(n);
    return double(n);
  };
  std::vector<ImageAttribute> header = {{"objektiv:partial", int(stats.Partial())},
                                        {"objektiv:pixels", count(stats.pixels)},
                                        {"objektiv:pixels_completed", count(stats.pixels_completed)}};
  LensLayers layers;
  {
    std::unique_ptr<tbb::global_control> limit;  // the passes after the render keep to --threads too
    if (a.threads > 0) limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, a.threads);
    layers = ComposeLensLayers(*setup.scene, *setup.camera, film, setup.sampler.seed);
  }
  Image linear = XyzToImage(layers.Sum(), layers.width, layers.height, *fs_.color_space, fs_.exposure);
  AddLensLayers(layers, *fs_.color_space, fs_.exposure, linear, header);
  if (aov_integrator) AddAovChannels(*aov_integrator, film, *setup.film.color_space, linear);
  WriteExr(exr.string(), linear, header);
  WritePng(png.string(), ApplyToneMap(linear, fs_.tonemap));
  if (!a.stats_json.empty()) WriteStatsJson(a.stats_json, stats, threads, layers);
  if (!a.quiet)
    std::printf("%s: %dx%d, %d spp, %.2f s%s, %.3g samples/s, %.2f Mrays/s, %s, NaN %llu, Inf %llu -> %s, %s%s\n",
                a.scene.c_str(), stats.width, stats.height, stats.spp, stats.seconds, LensPassTimes(layers).c_str(),
                stats.SamplesPerSecond(),
                stats.MraysPerSecond(),
                stats.CameraPassRate() ? fmt::format("camera pass rate {:.1f}%", 100 * *stats.CameraPassRate()).c_str()
                                       : "no camera ray traced",
                (unsigned long long)stats.nan_count,
                (unsigned long long)stats.inf_count, exr.string().c_str(), png.string().c_str(),
                stats.Partial() ? " (partial)" : "");
  if (stats.Partial())
    spdlog::warn("interrupted: the image is partial, {} of {} pixels rendered (the others are black); {} is marked "
                 "objektiv:partial = 1",
                 stats.pixels_completed, stats.pixels, exr.string());
  if (stats.nan_count || stats.inf_count)
    spdlog::warn("{} NaN and {} Inf radiance samples were dropped", stats.nan_count, stats.inf_count);
  if (stats.skipped_rays)
    spdlog::warn("{} rays with non-finite or out-of-range origins or directions were skipped", stats.skipped_rays);
  return InterruptSignal() ? 128 + InterruptSignal() : 0;
}

}  // namespace

std::function<int()> AddRenderCommand(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene to a linear EXR and a tone-mapped PNG beside it");
  cmd->add_option("scene", args->scene, "Scene file (XML)")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args->output, "Output EXR path (default: SCENE-NAME.exr); the PNG goes beside it");
  cmd->add_option("--spp", args->spp, "Samples per pixel (overrides the scene's sampler)")->check(CLI::Range(1, 1 << 24));
  cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")->check(CLI::Range(1, 4096));
  cmd->add_option("--seed", args->seed, "Sampler seed (overrides the scene's)")->check(CLI::NonNegativeNumber);
  cmd->add_option("--crop", args->crop, "Render only pixels x0,y0,x1,y1 (half-open) of the film");
  cmd->add_option("-D,--define", args->defines, "Set a scene parameter: -D name=value (overrides <default>)");
  cmd->add_option("--stats-json", args->stats_json, "Write render statistics as JSON to this file");
  cmd->add_option("--max-memory", args->max_memory_gib, "Memory budget for the film and the images written, GiB (default 16)")
      ->check(CLI::PositiveNumber);
  CLI::Option* quiet = cmd->add_flag("-q,--quiet", args->quiet, "No progress bar, no summary, warnings only");
  cmd->add_flag("-v,--verbose", args->verbose, "Debug logging")->excludes(quiet);
  return [args] { return RunRender(*args); };
}

}  // namespace objektiv
