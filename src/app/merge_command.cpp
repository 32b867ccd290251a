// `objektiv merge PART.exr... -o FINAL.exr`: puts the parts of a split render (sample ranges,
// crops: `render --spp-range`, `render --part --crop`) together into the image the unsplit
// render writes, bit for bit: the parts' exact sums add up to its sums (base/exact_sum.h),
// and the end of the render (the lens's layers, EXR and PNG) is the same code on the same
// film. The scene is loaded again, from the path the parts name (or --scene), and must be the
// one they were rendered from (the hash of its files' contents).
#include <chrono>
#include <filesystem>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "app/commands.h"
#include "app/render_finish.h"
#include "base/error.h"
#include "base/input_files.h"
#include "base/log.h"
#include "io/render_part.h"
#include "io/render_part_set.h"

namespace objektiv {
namespace {

struct MergeArgs {
  std::vector<std::string> parts;
  std::string output, scene;
  int threads = 0;
  double max_memory_gib = 16;
  bool quiet = false, verbose = false;
};

int RunMerge(const MergeArgs& a) {
  SetupLogging(a.quiet ? 0 : (a.verbose ? 2 : 1));
  namespace fs = std::filesystem;
  const auto start = std::chrono::steady_clock::now();
  fs::path exr = a.output;
  if (exr.extension() != ".exr") throw CLI::ValidationError("-o", "must name an .exr file (the PNG is written beside it)");
  const fs::path png = fs::path(exr).replace_extension(".png");
  const std::vector<Output> outputs = {{"the EXR", exr.string()}, {"the PNG written beside the EXR", png.string()}};
  CheckOutputsWritable(outputs);

  std::vector<RenderPartInfo> infos;
  for (const std::string& p : a.parts) infos.push_back(ReadRenderPartInfo(p));
  CheckPartsMakeOneRender(a.parts, infos);
  const RenderPartInfo& first = infos[0];
  const std::string scene = a.scene.empty() ? first.scene : a.scene;
  if (a.scene.empty() && !fs::exists(scene))
    throw InputError(fmt::format("{}: the scene of the parts (as {} names it) is not there; give its path with --scene",
                                 scene, a.parts[0]));
  const std::map<std::string, std::string> defines = DefinesFromJson(first.defines, a.parts[0]);
  RenderSetup setup = LoadScene(scene, defines, GlassCatalog::Default());
  setup.sampler.spp = first.spp;
  setup.sampler.seed = first.seed;
  const RenderPartInfo here = DescribeRender(scene, defines, setup);
  if (here.scene_hash != first.scene_hash)
    throw InputError(fmt::format("{}: its files are not those the parts were rendered from (contents hash {} against {} "
                                 "in {}); changed: {}", scene, here.scene_hash, first.scene_hash, a.parts[0],
                                 here.ChangedInputs(first)));
  if (const std::string m = here.Mismatch(first); !m.empty())
    throw InputError(fmt::format("{}: the scene loads otherwise than for the parts: {}", scene, m));
  for (const std::string& p : a.parts) RecordInputFile(p);  // (after the hash: the scene's files only)
  CheckOutputsAreNotInputs(outputs, "the merge");

  setup.film.crop = first.render_crop;
  Film film = MakeRenderFilm(setup, a.max_memory_gib, a.threads);
  for (const std::string& p : a.parts) AddRenderPart(p, film);
  const CropWindow& crop = setup.film.crop;
  const int pixels = crop.Width() * crop.Height();
  double seconds = 0;
  for (const RenderPartInfo& i : infos) seconds += i.seconds;
  const std::vector<ImageAttribute> header = {{"objektiv:partial", 0},
                                              {"objektiv:pixels", pixels},
                                              {"objektiv:pixels_completed", pixels},
                                              {"objektiv:render_end", std::string("complete")},
                                              {"objektiv:samples_per_pixel", film.samples_per_pixel()},
                                              {"objektiv:seconds", seconds},
                                              {"objektiv:merged_parts", int(a.parts.size())}};
  const LensLayers layers = WriteRenderImages(setup, film, a.threads, exr.string(), png.string(), header);
  if (!a.quiet)
    std::printf("%zu parts of %s: %dx%d, %.4g spp, rendered in %.2f s in all; merged in %.2f s%s -> %s, %s\n",
                a.parts.size(), scene.c_str(), crop.Width(), crop.Height(), film.samples_per_pixel(), seconds,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                LensPassTimes(layers).c_str(), exr.string().c_str(), png.string().c_str());
  return 0;
}

}  // namespace

std::function<int()> AddMergeCommand(CLI::App& app) {
  auto args = std::make_shared<MergeArgs>();
  CLI::App* cmd = app.add_subcommand("merge", "Put the parts of a split render together (render --spp-range, --part)");
  cmd->add_option("parts", args->parts, "The parts (EXR files written by render --spp-range or --part)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args->output, "The merged EXR (the PNG goes beside it)")->required();
  cmd->add_option("--scene", args->scene, "The scene, where it is not at the path the parts name")->check(CLI::ExistingFile);
  cmd->add_option("--threads", args->threads, "Worker threads for the lens's passes (default: all cores)")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--max-memory", args->max_memory_gib, "Memory budget for the film and the images written, GiB (default 16)")
      ->check(CLI::PositiveNumber);
  CLI::Option* quiet = cmd->add_flag("-q,--quiet", args->quiet, "No summary, warnings only");
  cmd->add_flag("-v,--verbose", args->verbose, "Debug logging")->excludes(quiet);
  return [args] { return RunMerge(*args); };
}

}  // namespace objektiv
