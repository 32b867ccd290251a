// `objektiv render SCENE.xml`: renders a scene to a linear EXR and a tone-mapped PNG.
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

#include "app/commands.h"
#include "base/error.h"
#include "base/log.h"
#include "io/image_io.h"
#include "io/scene_loader.h"
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

void WriteStatsJson(const std::string& path, const RenderStats& s, int threads) {
  std::ofstream out(path);
  if (!out) throw InputError(fmt::format("{}: cannot write the statistics file", path));
  out << fmt::format(
      "{{\n  \"seconds\": {:.6f},\n  \"spp\": {},\n  \"width\": {},\n  \"height\": {},\n  \"threads\": {},\n"
      "  \"samples\": {},\n  \"rays\": {},\n  \"samples_per_second\": {:.3f},\n  \"mrays_per_second\": {:.6f},\n"
      "  \"nan_count\": {},\n  \"inf_count\": {},\n  \"camera_rays_traced\": {},\n  \"camera_pass_rate\": {:.6f}\n}}\n",
      s.seconds, s.spp, s.width, s.height, threads, s.samples, s.rays, s.SamplesPerSecond(), s.MraysPerSecond(),
      s.nan_count, s.inf_count, s.camera_rays_traced, s.CameraPassRate());
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
// images and the 8-bit PNG made from them.
Film MakeFilm(const FilmSettings& f, double budget_gib) {
  const uint64_t bytes = Film::AccumulatorBytes(f.crop) + uint64_t(f.crop.Width()) * f.crop.Height() * (2 * 3 * sizeof(float) + 3);
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

int RunRender(const RenderArgs& a) {
  SetupLogging(a.quiet ? 0 : (a.verbose ? 2 : 1));
  std::map<std::string, std::string> defines;
  for (const std::string& d : a.defines) {
    size_t eq = d.find('=');
    if (eq == std::string::npos || eq == 0) {
      std::fprintf(stderr, "error: -D expects name=value, got '%s'\n", d.c_str());
      return 2;
    }
    defines[d.substr(0, eq)] = d.substr(eq + 1);
  }
  namespace fs = std::filesystem;
  fs::path exr = a.output.empty() ? fs::path(fs::path(a.scene).stem().string() + ".exr") : fs::path(a.output);
  if (exr.extension().empty()) exr += ".exr";
  if (exr.extension() != ".exr") {
    std::fprintf(stderr, "error: -o must name an .exr file (the PNG is written beside it)\n");
    return 2;
  }
  fs::path png = fs::path(exr).replace_extension(".png");

  RenderSetup setup = LoadScene(a.scene, defines);
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
  Film film = MakeFilm(fs_, a.max_memory_gib);
  RenderOptions opts;
  opts.spp_begin = 0;
  opts.spp_end = sampler->spp();
  opts.threads = a.threads;
  opts.progress = !a.quiet && InteractiveTerminal();
  int threads = a.threads > 0 ? a.threads : int(std::thread::hardware_concurrency());

  RenderStats stats = Render(*setup.camera, *setup.integrator, *sampler, film, opts);

  if (!exr.parent_path().empty()) fs::create_directories(exr.parent_path());
  Image linear = film.ToImage(*fs_.color_space, fs_.exposure);
  WriteExr(exr.string(), linear);
  WritePng(png.string(), ApplyToneMap(linear, fs_.tonemap));
  if (!a.stats_json.empty()) WriteStatsJson(a.stats_json, stats, threads);
  if (!a.quiet)
    std::printf("%s: %dx%d, %d spp, %.2f s, %.3g samples/s, %.2f Mrays/s, camera pass rate %.1f%%, NaN %llu, Inf %llu -> %s, %s\n",
                a.scene.c_str(), stats.width, stats.height, stats.spp, stats.seconds, stats.SamplesPerSecond(),
                stats.MraysPerSecond(), 100 * stats.CameraPassRate(), (unsigned long long)stats.nan_count,
                (unsigned long long)stats.inf_count, exr.string().c_str(), png.string().c_str());
  if (stats.nan_count || stats.inf_count)
    spdlog::warn("{} NaN and {} Inf radiance samples were dropped", stats.nan_count, stats.inf_count);
  if (stats.skipped_rays)
    spdlog::warn("{} rays with non-finite or out-of-range origins or directions were skipped", stats.skipped_rays);
  return 0;
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
  cmd->add_flag("-q,--quiet", args->quiet, "No progress bar, no summary, warnings only");
  cmd->add_flag("-v,--verbose", args->verbose, "Debug logging");
  return [args] { return RunRender(*args); };
}

}  // namespace objektiv
