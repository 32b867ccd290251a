#include "app/render_finish.h"

#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>

#include "base/error.h"
#include "base/input_files.h"
#include "base/interrupt.h"
#include "base/output_file.h"
#include "camera/stereo_camera.h"
#include "io/anaglyph.h"
#include "io/tonemap.h"
#include "render/aov.h"

namespace objektiv {

namespace {

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
    if (layers.flare_sources > 0)
      spdlog::info("ghosts: {} bright point{}, {} ghosts traced, {} culled as too dim, {} let no light through; {:.2f} s",
                   layers.flare_sources, layers.flare_sources == 1 ? "" : "s", layers.ghosts_traced,
                   layers.ghosts_culled, layers.ghosts_dark, layers.ghost_seconds);
    else
      spdlog::info("ghosts: no point, spot or directional light in front of the lens to trace ghost bundles from{}",
                   layers.glare_paths > 0 ? " (the other lights' ghosts come from light tracing, below)" : "");
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
  AppendChannels(names, values, image);
}

}  // namespace

void AppendChannels(const std::vector<std::string>& names, const std::vector<float>& values, Image& image) {
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

void CheckOutputsAreNotInputs(const std::vector<Output>& outputs, const char* read_by) {
  for (const Output& o : outputs)
    if (std::optional<std::string> input = InputFileAt(o.path))
      throw CLI::ValidationError(
          fmt::format("{} ({}) would overwrite {}, a file {} reads; choose another name", o.what, o.path, *input, read_by));
}

Film MakeRenderFilm(const RenderSetup& setup, double budget_gib, int threads) {
  const FilmSettings& f = setup.film;
  const auto* aov_integrator = dynamic_cast<const AovIntegrator*>(setup.integrator.get());
  // What the integrator keeps per pixel beside the film (the AOVs, sppm's photon statistics).
  const uint64_t integrator_bytes = uint64_t(f.crop.Width()) * f.crop.Height() * setup.integrator->BytesPerPixel();
  Film film = MakeFilm(f, budget_gib, LensEffectsBytes(*setup.camera, f.crop, threads) + integrator_bytes);
  PrepareFilmForLensEffects(*setup.camera, film);
  if (aov_integrator) film.KeepAovs(aov_integrator->AovChannels());
  return film;
}

LensLayers WriteRenderImages(const RenderSetup& setup, const Film& film, int threads, const std::string& exr,
                             const std::string& png, std::vector<ImageAttribute> header, bool sample_count_layer) {
  const FilmSettings& fs = setup.film;
  LensLayers layers;
  {
    std::unique_ptr<tbb::global_control> limit;  // the passes after the render keep to --threads too
    if (threads > 0) limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
    layers = ComposeLensLayers(*setup.scene, *setup.camera, film, setup.sampler.seed);
  }
  if (InterruptRequested()) {  // Ctrl-C in the lens's passes: their layers are not whole
    for (ImageAttribute& h : header) {
      if (h.name == "objektiv:partial") h.value = 1;
      if (h.name == "objektiv:render_end") h.value = std::string("interrupted");
    }
  }
  Image linear = XyzToImage(layers.Sum(), layers.width, layers.height, *fs.color_space, fs.exposure);
  AddLensLayers(layers, *fs.color_space, fs.exposure, linear, header);
  if (const auto* aov = dynamic_cast<const AovIntegrator*>(setup.integrator.get()))
    AddAovChannels(*aov, film, *fs.color_space, linear);
  const auto* rig = dynamic_cast<const StereoCamera*>(setup.camera.get());
  if (sample_count_layer && rig && rig->layout() == StereoLayout::kAnaglyph)
    spdlog::warn("--sample-count-layer: an anaglyph's pixels mix both eyes' film, which holds the counts: not written");
  else if (sample_count_layer) {
    std::vector<float> counts;
    counts.reserve(size_t(fs.crop.Width()) * fs.crop.Height());
    for (int y = fs.crop.y0; y < fs.crop.y1; ++y)
      for (int x = fs.crop.x0; x < fs.crop.x1; ++x) counts.push_back(float(film.SampleCount(Vec2i(x, y))));
    AppendChannels({"sample_count"}, counts, linear);
  }
  if (const auto* stereo = dynamic_cast<const StereoCamera*>(setup.camera.get())) {
    if (stereo->layout() == StereoLayout::kAnaglyph) {
      // Both eyes whole (render_command refuses --crop for an anaglyph's image).
      if (!(fs.crop == CropWindow{0, 0, fs.width, fs.height}))
        throw InputError(fmt::format("{}: an anaglyph needs the whole film, not a crop of it", exr));
      linear = AnaglyphImage(linear, *fs.color_space, fs.tonemap);
      header.push_back({"objektiv:stereo", std::string("anaglyph: R, G, B red-cyan by Dubois' least squares, linear "
                                                       "Rec.709 in [0, 1], the tone curve applied; left.*, right.*: "
                                                       "the eyes' linear images")});
      WriteExr(exr, linear, header);
      WritePng(png, ApplyToneMap(linear, ToneMap::kClamp));  // the tone curve is in the anaglyph already
      return layers;
    }
    header.push_back({"objektiv:stereo", std::string(stereo->layout() == StereoLayout::kOverUnder
                                                         ? "over-under: the left eye's image on top"
                                                         : "side-by-side: the left eye's image on the left")});
  }
  WriteExr(exr, linear, header);
  WritePng(png, ApplyToneMap(linear, fs.tonemap));
  return layers;
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

RenderPartInfo DescribeRender(const std::string& scene, const std::map<std::string, std::string>& defines,
                              const RenderSetup& setup) {
  RenderPartInfo i;
  i.version = OBJEKTIV_VERSION;
  std::error_code ec;
  i.scene = std::filesystem::absolute(scene, ec).lexically_normal().string();
  const auto files = InputFilesContentHashes();
  i.scene_hash = fmt::format("{:016x}", CombinedContentHash(files));
  const std::filesystem::path folder = std::filesystem::path(i.scene).parent_path();
  for (const auto& [path, hash] : files) {
    const std::filesystem::path relative = std::filesystem::path(path).lexically_relative(folder);
    const bool inside = !relative.empty() && *relative.begin() != "..";
    i.inputs += fmt::format("{:016x} {}\n", hash, inside ? relative.string() : path);
  }
  i.defines = nlohmann::json(defines).dump();
  i.spp = setup.sampler.spp;
  i.seed = setup.sampler.seed;
  i.sampling = DescribeSampling(setup.sampler);
  i.width = setup.film.width, i.height = setup.film.height;
  i.render_crop = setup.film.crop;
  return i;
}

std::map<std::string, std::string> DefinesFromJson(const std::string& json, const std::string& part) {
  try {
    return nlohmann::json::parse(json).get<std::map<std::string, std::string>>();
  } catch (const nlohmann::json::exception&) {
    throw MakeInputError(part, 0, "objektiv:defines is not a JSON object of strings: {}", json);
  }
}

}  // namespace objektiv
