// `objektiv render SCENE.xml`: renders a scene to a linear EXR and a tone-mapped PNG, or a part
// of a render (a sample range, a crop) to merge later; checkpoints, resuming, time and noise
// budgets (render/progressive_render.h).
#include <filesystem>
#include <limits>
#include <map>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/cli_values.h"
#include "app/commands.h"
#include "app/render_finish.h"
#include "base/error.h"
#include "base/interrupt.h"
#include "base/log.h"
#include "base/output_file.h"
#include "camera/stereo_camera.h"
#include "io/render_part.h"
#include "render/adaptive_sampling.h"
#include "render/progressive_render.h"

namespace objektiv {
namespace {

struct RenderArgs {
  std::string scene, output, stats_json, crop, spp_range, seed;
  bool crop_given = false, spp_range_given = false;
  int spp = 0, threads = 0;
  double max_memory_gib = 16;
  std::vector<std::string> defines;
  bool quiet = false, verbose = false;
  bool part = false, resume = false;
  double checkpoint = 0, time_limit = 0, noise_target = 0;
  std::string sampler, adaptive;
  double adaptive_threshold = 0;
  int adaptive_min = 0;
  bool sample_count_layer = false;
};

// --sampler, --adaptive, --adaptive-threshold, --adaptive-min-samples over the scene's sampler.
void ApplySamplingOptions(const RenderArgs& a, SamplerSettings& s) {
  static const std::map<std::string, std::pair<SamplerKind, PixelPattern>> kTypes = {
      {"independent", {SamplerKind::kIndependent, PixelPattern::kSampler}},
      {"stratified", {SamplerKind::kStratified, PixelPattern::kSampler}},
      {"sobol", {SamplerKind::kSobol, PixelPattern::kSampler}},
      {"grid", {SamplerKind::kSobol, PixelPattern::kGrid}},
      {"rgss", {SamplerKind::kSobol, PixelPattern::kRgss}},
      {"quincunx", {SamplerKind::kSobol, PixelPattern::kQuincunx}}};
  if (!a.sampler.empty()) {
    const auto& t = kTypes.at(a.sampler);  // (checked by its option)
    s.kind = t.first, s.pattern = t.second;
  }
  const AdaptiveMode scene_mode = s.adaptive.mode;
  if (a.adaptive == "none") s.adaptive.mode = AdaptiveMode::kNone;
  if (a.adaptive == "statistical") s.adaptive.mode = AdaptiveMode::kStatistical;
  if (a.adaptive == "whitted") s.adaptive.mode = AdaptiveMode::kWhitted;
  // A mode other than the scene's takes its own default (a contrast and a relative error are
  // not the same measure).
  if (s.adaptive.mode != scene_mode) s.adaptive.threshold = AdaptiveSettings::DefaultThreshold(s.adaptive.mode);
  if (a.adaptive_threshold > 0) s.adaptive.threshold = a.adaptive_threshold;
  if (a.adaptive_min > 0) s.adaptive.min_samples = a.adaptive_min;
  if (a.adaptive_min > 0 && s.adaptive.mode != AdaptiveMode::kStatistical)
    throw CLI::ValidationError("--adaptive-min-samples", "applies to statistical adaptive sampling only (--adaptive statistical)");
  if (a.adaptive_threshold > 0 && s.adaptive.mode == AdaptiveMode::kNone)
    throw CLI::ValidationError("--adaptive-threshold", "applies to adaptive sampling only (--adaptive statistical or whitted)");
  if (s.adaptive.mode == AdaptiveMode::kWhitted && s.pattern != PixelPattern::kSampler)
    throw CLI::ValidationError("--adaptive", fmt::format("whitted places its own samples; it cannot take the {} pattern "
                                                         "(use a sobol, stratified or independent sampler)",
                                                         PixelPatternName(s.pattern)));
}

// The camera samples each pixel of the crop took: fewest, most, all (adaptive sampling's
// spread), and the most a pixel may take (the cap).
struct PixelSampleCounts {
  uint32_t lo = UINT32_MAX, hi = 0;
  uint64_t total = 0;
  int cap = 0;
};
PixelSampleCounts CountPixelSamples(const Film& film, const CropWindow& crop, const SamplerSettings& sampler) {
  PixelSampleCounts c;
  c.cap = sampler.adaptive.mode == AdaptiveMode::kWhitted ? WhittedMaxSamples(sampler.adaptive.max_depth) : sampler.spp;
  for (int y = crop.y0; y < crop.y1; ++y)
    for (int x = crop.x0; x < crop.x1; ++x) {
      const uint32_t n = film.SampleCount(Vec2i(x, y));
      c.lo = std::min(c.lo, n), c.hi = std::max(c.hi, n), c.total += n;
    }
  return c;
}

// `counts`: with adaptive sampling, the pixels' sample counts ("spp" is then the cap).
void WriteStatsJson(const std::string& path, const RenderStats& s, int threads, const LensLayers& layers,
                    const ProgressiveResult& r, const std::optional<PixelSampleCounts>& counts) {
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
                              {"pixels_completed", s.pixels_completed},
                              {"render_end", RenderEndName(r.end)},
                              {"rendering_seconds_in_all", r.elapsed}};
  if (r.noise >= 0) j["noise"] = r.noise;
  if (counts) {
    j["spp"] = counts->cap;
    j["samples_per_pixel_min"] = counts->lo;
    j["samples_per_pixel_max"] = counts->hi;
    j["samples_per_pixel_mean"] = s.pixels ? double(counts->total) / double(s.pixels) : 0.0;
  }
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

CropWindow ParseCrop(const std::string& text, int width, int height) {
  const std::optional<std::vector<int>> v = ParseCounts(text, ',', 4);
  if (!v) throw CLI::ValidationError("--crop", fmt::format("expects x0,y0,x1,y1 (pixels, half-open), got '{}'", text));
  const int x0 = (*v)[0], y0 = (*v)[1], x1 = (*v)[2], y1 = (*v)[3];
  if (x1 > width || y1 > height || x0 >= x1 || y0 >= y1)
    throw CLI::ValidationError("--crop", fmt::format("{} is not inside the {}x{} film with x0 < x1, y0 < y1", text, width, height));
  return {x0, y0, x1, y1};
}

// "A:B" with 0 <= A < B <= spp.
std::pair<int, int> ParseSppRange(const std::string& text, int spp) {
  const std::optional<std::vector<int>> v = ParseCounts(text, ':', 2);
  if (!v) throw CLI::ValidationError("--spp-range", fmt::format("expects A:B (sample indices A to B-1), got '{}'", text));
  const int a = (*v)[0], b = (*v)[1];
  if (a >= b || b > spp)
    throw CLI::ValidationError("--spp-range", fmt::format("{} is not a range within the render's {} samples per pixel "
                                                          "(0 <= A < B <= {})", text, spp, spp));
  return {a, b};
}

// EXR counts beyond 32 bits are written as doubles (EXR has no 64-bit integers).
ImageAttribute::Value Count(uint64_t n) {
  if (n <= uint64_t(std::numeric_limits<int>::max())) return int(n);
  return double(n);
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
  const bool part = a.part || a.spp_range_given;
  if (part && (a.time_limit > 0 || a.noise_target > 0))
    throw CLI::ValidationError("--time-limit and --noise-target end whole renders; a part (--part, --spp-range) takes "
                               "all the samples of its range, so that the parts add up");
  fs::path exr = a.output.empty() ? fs::path(fs::path(a.scene).stem().string() + ".exr") : fs::path(a.output);
  if (exr.extension().empty()) exr += ".exr";
  if (exr.extension() != ".exr") {
    std::fprintf(stderr, "error: -o must name an .exr file (the PNG is written beside it)\n");
    return 2;
  }
  const fs::path png = fs::path(exr).replace_extension(".png");
  const fs::path checkpoint = fs::path(exr).replace_extension(".checkpoint.exr");
  std::vector<Output> outputs = {{part ? "the render part" : "the EXR", exr.string()}};
  if (!part) outputs.push_back({"the PNG written beside the EXR", png.string()});
  if (a.checkpoint > 0 || a.resume) outputs.push_back({"the checkpoint", checkpoint.string()});
  if (!a.stats_json.empty()) outputs.push_back({"--stats-json", a.stats_json});
  CheckOutputsWritable(outputs);
  RenderSetup setup = LoadScene(a.scene, defines, GlassCatalog::Default());
  // (The scene's sample_count under its own adaptive whitted is warned about by the loader.)
  const bool scene_count_given = setup.sampler.spp_given && setup.sampler.adaptive.mode != AdaptiveMode::kWhitted;
  if (a.spp > 0) setup.sampler.spp = a.spp;
  ApplySamplingOptions(a, setup.sampler);
  const AdaptiveMode adaptive = setup.sampler.adaptive.mode;
  // sppm's iterations (its samples per pixel) are one render: each starts from the photon
  // radii and sums the ones before it left, so they cannot be split, paused or cut short.
  if (dynamic_cast<const WholeImageIntegrator*>(setup.integrator.get())) {
    const char* what = part                              ? "a part (--part, --spp-range)"
                       : adaptive != AdaptiveMode::kNone ? "adaptive sampling (--adaptive)"
                       : a.time_limit > 0                ? "--time-limit"
                       : a.noise_target > 0              ? "--noise-target"
                       : a.checkpoint > 0                ? "--checkpoint"
                       : a.resume                        ? "--resume"
                                                         : nullptr;
    if (what)
      throw InputError(fmt::format("{}: sppm renders its iterations (the samples per pixel) in one go, each shrinking "
                                   "the photon radii the one before left: {} cannot apply",
                                   a.scene, what));
  }
  // (After sppm's refusals: its adaptive sampling is refused, not checked for its settings.)
  if (!a.sampler.empty() || !a.adaptive.empty() || a.adaptive_min > 0 || a.spp > 0)
    CheckSamplerSettings(setup.sampler, "the command line");
  // A pixel's adaptive sample count is decided from all of its samples: a sample range alone
  // cannot decide it, and the parts would not add up to one render.
  if (adaptive != AdaptiveMode::kNone && part)
    throw InputError(fmt::format("{}: adaptive sampling ({}) decides each pixel's samples from the samples before them; "
                                 "a part (--part, --spp-range) cannot: render it whole (--checkpoint and --resume work)",
                                 a.scene, AdaptiveModeName(adaptive)));
  if (adaptive == AdaptiveMode::kWhitted && (a.time_limit > 0 || a.noise_target > 0))
    throw InputError(fmt::format("{}: adaptive whitted takes each pixel whole in one go, so it has no passes to stop "
                                 "after: --time-limit and --noise-target cannot apply (--adaptive statistical can)",
                                 a.scene));
  if (adaptive == AdaptiveMode::kWhitted && (a.spp > 0 || scene_count_given))
    spdlog::warn("{} does not apply to adaptive whitted: a pixel takes 5 to {} samples as its contrast asks",
                 a.spp > 0 ? std::string("--spp") : fmt::format("the scene's sample_count ({})", setup.sampler.spp),
                 WhittedMaxSamples(setup.sampler.adaptive.max_depth));
  if (adaptive == AdaptiveMode::kWhitted && !setup.integrator->NearlyNoiseFree())
    spdlog::warn("{}: adaptive whitted subdivides where a pixel's samples differ; this integrator's noise makes them "
                 "differ everywhere (--adaptive statistical is meant for it)", a.scene);
  if (adaptive != AdaptiveMode::kNone && setup.integrator->TracesLightToCamera())
    spdlog::warn("{}: adaptive sampling sees the camera samples only; the light paths (one per camera sample) follow "
                 "them, their noise on the film does not steer them", a.scene);
  // The noise estimate reads the camera samples' spread; light paths add theirs as splats,
  // which it cannot see (it would call a light-traced image clean after its first pass).
  if (a.noise_target > 0 && setup.integrator->TracesLightToCamera())
    throw InputError(fmt::format("{}: --noise-target measures the noise of camera samples, and this integrator's light "
                                 "paths add light it cannot measure; use --time-limit or samples per pixel",
                                 a.scene));
  if (!a.seed.empty()) setup.sampler.seed = *ParseUint64(a.seed);  // (checked by its option)
  RenderPartInfo info = DescribeRender(a.scene, defines, setup);
  CheckOutputsAreNotInputs(outputs);
  FilmSettings& fs_ = setup.film;
  if (a.crop_given) {
    fs_.crop = ParseCrop(a.crop, fs_.width, fs_.height);
    if (setup.integrator->TracesLightToCamera())
      spdlog::warn("{}: light paths land anywhere on the film and only those inside --crop count: renders split by "
                   "crop are noisier than one render (split light-traced renders by --spp-range)", a.scene);
    const auto* stereo = dynamic_cast<const StereoCamera*>(setup.camera.get());
    if (!part && stereo && stereo->layout() == StereoLayout::kAnaglyph)
      throw CLI::ValidationError("--crop", "an anaglyph is made of both eyes' whole images: crop a part to merge "
                                           "(--part) or render layout side-by-side");
    if (part && !info.render_crop.Contains(fs_.crop))
      throw CLI::ValidationError("--crop", fmt::format("a part's pixels must lie inside the scene's crop window {},{},{},{}",
                                                       info.render_crop.x0, info.render_crop.y0, info.render_crop.x1,
                                                       info.render_crop.y1));
  }
  // Whitted's adaptive pixels are taken whole: one "sample index" per pixel stands for them all.
  const int spp = adaptive == AdaptiveMode::kWhitted ? 1 : setup.sampler.spp;
  const std::pair<int, int> range =
      a.spp_range_given ? ParseSppRange(a.spp_range, spp) : std::pair<int, int>(0, spp);
  const int spp_begin = range.first, spp_end = range.second;  // (lambdas below capture them: no structured binding)
  info.crop = fs_.crop;
  info.spp_begin = spp_begin, info.spp_end = spp_end;
  std::unique_ptr<Sampler> sampler = MakeSampler(setup.sampler);
  const int threads = a.threads > 0 ? a.threads : int(std::thread::hardware_concurrency());
  Film film = MakeRenderFilm(setup, a.max_memory_gib, threads);
  film.StartSamplesAt(spp_begin);

  double elapsed_before = 0;
  if (a.checkpoint > 0 || a.resume) RemoveStaleTemporaries(checkpoint.string());
  if (a.resume && fs::exists(checkpoint)) {
    const RenderPartInfo saved = ReadRenderPartInfo(checkpoint.string());
    std::string m = info.Mismatch(saved);
    if (m.empty() && !(saved.crop == info.crop))
      m = fmt::format("its pixels are {},{},{},{}", saved.crop.x0, saved.crop.y0, saved.crop.x1, saved.crop.y1);
    if (m.empty() && (saved.spp_begin != spp_begin || saved.spp_end != spp_end))
      m = fmt::format("its samples are {}:{}", saved.spp_begin, saved.spp_end);
    if (!m.empty())
      throw InputError(fmt::format("{}: a checkpoint of another render ({}{}); remove it to start afresh",
                                   checkpoint.string(), m,
                                   saved.scene_hash != info.scene_hash ? "; changed: " + info.ChangedInputs(saved) : ""));
    AddRenderPart(checkpoint.string(), film);
    elapsed_before = saved.seconds;
    spdlog::info("resuming from {}: {} of {} pixels had all their samples, {:.1f} s rendered before", checkpoint.string(),
                 saved.pixels_completed, uint64_t(fs_.crop.Width()) * fs_.crop.Height(), elapsed_before);
  } else if (a.resume) {
    spdlog::info("no checkpoint {} yet: starting from the first sample", checkpoint.string());
  }
  // The film as a part or a checkpoint: its own image and its sums.
  auto write_part = [&](const std::string& path, bool is_checkpoint, double seconds) {
    RenderPartInfo i = info;
    i.checkpoint = is_checkpoint;
    i.seconds = seconds;
    i.pixels_completed = PixelsDone(film, *sampler, spp_end);
    WriteRenderPart(path, film.ToImage(*fs_.color_space, fs_.exposure), film, i);
  };

  ProgressiveOptions po;
  po.render.spp_begin = spp_begin;
  po.render.spp_end = spp_end;
  po.render.threads = a.threads;
  po.render.progress = !a.quiet && InteractiveTerminal();
  po.elapsed_before = elapsed_before;
  po.time_limit_seconds = a.time_limit;
  po.noise_target = a.noise_target;
  if (a.checkpoint > 0) {
    po.checkpoint_seconds = a.checkpoint;
    po.checkpoint = [&](double seconds) {
      write_part(checkpoint.string(), true, seconds);
      spdlog::debug("checkpoint written: {}", checkpoint.string());
    };
  }
  // From here on Ctrl-C (or SIGTERM) stops the render and the pixels done so far are written.
  InstallInterruptHandlers();
  po.interrupt = &InterruptRequested();
  spdlog::info("rendering {}x{} pixels, samples {}:{} of {}, on {} threads{}", fs_.crop.Width(), fs_.crop.Height(),
               spp_begin, spp_end, setup.sampler.spp, threads, part ? " (a part)" : "");
  const ProgressiveResult result = RenderProgressive(*setup.camera, *setup.integrator, *sampler, film, po);
  const RenderStats& stats = result.stats;
  const bool interrupted = result.end == RenderEnd::kInterrupted;

  LensLayers layers;
  if (part) {
    write_part(exr.string(), false, result.elapsed);
    if (LensEffectsBytes(*setup.camera, fs_.crop, 1) > 0)
      spdlog::info("the lens's ghosts, glare and diffraction are passes over the whole image: `objektiv merge` adds them");
  } else {
    // The lens's passes may take long: the samples are saved first, so that Ctrl-C there loses none.
    if (!interrupted && a.checkpoint > 0 && LensEffectsBytes(*setup.camera, fs_.crop, 1) > 0)
      write_part(checkpoint.string(), true, result.elapsed);
    std::vector<ImageAttribute> header = {{"objektiv:partial", int(interrupted)},
                                          {"objektiv:pixels", Count(stats.pixels)},
                                          {"objektiv:pixels_completed", Count(stats.pixels_completed)},
                                          {"objektiv:render_end", std::string(RenderEndName(result.end))},
                                          {"objektiv:samples_per_pixel", film.samples_per_pixel()},
                                          {"objektiv:seconds", result.elapsed}};
    if (const std::string sampling = DescribeSampling(setup.sampler); !sampling.empty())
      header.push_back({"objektiv:sampling", sampling});
    if (a.time_limit > 0) header.push_back({"objektiv:time_limit", a.time_limit});
    if (a.noise_target > 0) header.push_back({"objektiv:noise_target", a.noise_target});
    if (result.noise >= 0) header.push_back({"objektiv:noise", result.noise});
    layers = WriteRenderImages(setup, film, a.threads, exr.string(), png.string(), header, a.sample_count_layer);
  }
  // Ctrl-C during the lens's passes leaves the samples whole but the image not: partial too.
  const bool stopped = interrupted || InterruptSignal() != 0;
  if (!stopped && fs::exists(checkpoint)) fs::remove(checkpoint);
  const std::optional<PixelSampleCounts> counts =
      adaptive != AdaptiveMode::kNone ? std::optional(CountPixelSamples(film, fs_.crop, setup.sampler)) : std::nullopt;
  if (!a.stats_json.empty()) WriteStatsJson(a.stats_json, stats, threads, layers, result, counts);
  // An anaglyph's film holds both eyes side by side; its image is one eye wide.
  const auto* rig = dynamic_cast<const StereoCamera*>(setup.camera.get());
  const bool anaglyph = rig && rig->layout() == StereoLayout::kAnaglyph;
  const std::string eyes = anaglyph && !part
                               ? fmt::format(" (both eyes; the anaglyph {}x{})", stats.width / 2, stats.height)
                               : "";
  if (!a.quiet)
    std::printf("%s: %dx%d%s, %.4g spp, %.2f s%s, %.3g samples/s, %.2f Mrays/s, %s, NaN %llu, Inf %llu -> %s%s%s\n",
                a.scene.c_str(), stats.width, stats.height, eyes.c_str(), film.samples_per_pixel(), stats.seconds,
                LensPassTimes(layers).c_str(), stats.SamplesPerSecond(), stats.MraysPerSecond(),
                stats.CameraPassRate() ? fmt::format("camera pass rate {:.1f}%", 100 * *stats.CameraPassRate()).c_str()
                                       : "no camera ray traced",
                (unsigned long long)stats.nan_count, (unsigned long long)stats.inf_count, exr.string().c_str(),
                part ? "" : (", " + png.string()).c_str(), stopped ? " (partial)" : "");
  if (!a.quiet && counts) {
    std::printf("%s: %llu camera samples, %u to %u per pixel (mean %.4g)%s\n", DescribeSampling(setup.sampler).c_str(),
                (unsigned long long)counts->total, counts->lo, counts->hi, film.samples_per_pixel(),
                a.sample_count_layer && !anaglyph ? ", channel sample_count" : "");
  } else if (!a.quiet && a.sample_count_layer && !anaglyph) {
    std::printf("%llu camera samples in all, channel sample_count\n", (unsigned long long)stats.samples);
  }
  if (result.end == RenderEnd::kTimeLimit || result.end == RenderEnd::kNoiseTarget)
    spdlog::info("stopped at the {} after {:.1f} s: {:.4g} samples per pixel of {}{}", RenderEndName(result.end),
                 result.elapsed, film.samples_per_pixel(), spp_end - spp_begin,
                 result.noise >= 0 ? fmt::format(", noise {:.3g} (95% of the pixels' relative error below)", result.noise)
                                   : std::string());
  const std::string resume = a.checkpoint > 0 ? fmt::format("; --resume goes on from {}", checkpoint.string()) : "";
  if (interrupted && part)
    spdlog::warn("interrupted: the part is unfinished, {} of {} pixels have all their samples (objektiv:partial = 1 in "
                 "{}; merge refuses it){}", stats.pixels_completed, stats.pixels, exr.string(), resume);
  else if (interrupted)
    spdlog::warn("interrupted: the image is partial, {} of {} pixels have all their samples; {} is marked "
                 "objektiv:partial = 1{}", stats.pixels_completed, stats.pixels, exr.string(), resume);
  else if (stopped && !part)
    spdlog::warn("interrupted in the lens's passes: every sample is in, the lens's layers are not whole; {} is marked "
                 "objektiv:partial = 1{}", exr.string(), resume);
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
  cmd->add_option("--seed", args->seed, "Sampler seed, 0 to 2^64-1 (overrides the scene's)")
      ->check(CLI::Validator(
          [](std::string& t) { return ParseUint64(t) ? std::string() : "'" + t + "' is not a whole number 0 to 2^64-1"; },
          "0..2^64-1"));
  CLI::Option* crop = cmd->add_option("--crop", args->crop, "Render only pixels x0,y0,x1,y1 (half-open) of the film");
  cmd->add_option("-D,--define", args->defines, "Set a scene parameter: -D name=value (overrides <default>)");
  cmd->add_option("--stats-json", args->stats_json, "Write render statistics as JSON to this file");
  cmd->add_option("--max-memory", args->max_memory_gib, "Memory budget for the film and the images written, GiB (default 16)")
      ->check(FinitePositive());
  CLI::Option* range = cmd->add_option("--spp-range", args->spp_range,
                                       "Render sample indices A to B-1 of every pixel (A:B) as a part to merge (`objektiv merge`)");
  cmd->add_flag("--part", args->part, "Write a part to merge (`objektiv merge`) instead of the image: with --crop, a region");
  cmd->add_option("--checkpoint", args->checkpoint,
                  "Every so many seconds (and on Ctrl-C), save the render so far to OUTPUT.checkpoint.exr")
      ->check(FinitePositive());
  cmd->add_flag("--resume", args->resume, "Go on from OUTPUT.checkpoint.exr if it exists (else start afresh)");
  cmd->add_option("--time-limit", args->time_limit,
                  "Stop rendering after so many seconds (in all, across resumes; every pixel gets at least one sample)")
      ->check(FinitePositive());
  cmd->add_option("--noise-target", args->noise_target,
                  "Stop once 95% of the pixels have a relative error below this (e.g. 0.02), or at the spp")
      ->check(FinitePositive(1.0));
  cmd->add_option("--sampler", args->sampler,
                  "Sampler type over the scene's: independent, stratified, sobol, or a pixel pattern grid, rgss, "
                  "quincunx (Sobol' numbers for the rest)")
      ->check(CLI::IsMember({"independent", "stratified", "sobol", "grid", "rgss", "quincunx"}));
  cmd->add_option("--adaptive", args->adaptive,
                  "Adaptive sampling over the scene's: none, statistical (samples until a pixel's relative standard "
                  "error is below the threshold, the spp the cap), whitted (classic subdivision)")
      ->check(CLI::IsMember({"none", "statistical", "whitted"}));
  cmd->add_option("--adaptive-threshold", args->adaptive_threshold,
                  "statistical: a pixel's relative standard error to reach (0.05); whitted: the contrast that subdivides (0.1)")
      ->check(FinitePositive());
  cmd->add_option("--adaptive-min-samples", args->adaptive_min, "statistical: samples every pixel takes first (16)")
      ->check(CLI::Range(2, 1 << 24));
  cmd->add_flag("--sample-count-layer", args->sample_count_layer,
                "Add a channel sample_count to the EXR: each pixel's camera samples");
  CLI::Option* quiet = cmd->add_flag("-q,--quiet", args->quiet, "No progress bar, no summary, warnings only");
  cmd->add_flag("-v,--verbose", args->verbose, "Debug logging")->excludes(quiet);
  return [args, crop, range] {
    args->crop_given = crop->count() > 0;
    args->spp_range_given = range->count() > 0;
    return RunRender(*args);
  };
}

}  // namespace objektiv
