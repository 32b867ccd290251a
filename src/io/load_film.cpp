// The <film> plugin (hdrfilm) and the <rfilter> plugins (reconstruction filters).
#include "base/log.h"
#include "io/loader_context.h"

namespace objektiv {
namespace {

std::shared_ptr<const Filter> BuildFilter(const ObjectNode* node) {
  if (!node) return std::make_shared<GaussianFilter>(0.5f);  // Mitsuba's default
  return FilterPlugins().Build(*node);
}

constexpr Named<ToneMap> kToneMaps[] = {{"clamp", ToneMap::kClamp}, {"filmic", ToneMap::kFilmic}};
constexpr Named<const ColorSpace& (*)()> kColorSpaces[] = {{"rec709", &ColorSpace::Rec709},
                                                           {"acescg", &ColorSpace::ACEScg}};
// Mitsuba's output formats: the EXR is always RGB float32 (value: whether that is what is asked).
constexpr Named<bool> kPixelFormats[] = {{"rgb", true}, {"rgba", false}};
constexpr Named<bool> kComponentFormats[] = {{"float16", false}, {"float32", true}};
constexpr Named<bool> kFileFormats[] = {{"openexr", true}, {"exr", true}};

FilmSettings BuildHdrFilm(const Properties& p) {
  FilmSettings f;
  f.width = int(p.IntIn("width", 768, 1, 1 << 16));
  f.height = int(p.IntIn("height", 576, 1, 1 << 16));
  int cx = int(p.IntIn("crop_offset_x", 0, 0, f.width - 1)), cy = int(p.IntIn("crop_offset_y", 0, 0, f.height - 1));
  int cw = int(p.IntIn("crop_width", f.width - cx, 1, f.width - cx));
  int ch = int(p.IntIn("crop_height", f.height - cy, 1, f.height - cy));
  f.crop = {cx, cy, cx + cw, cy + ch};
  f.exposure = float(p.FloatIn("exposure", 0, -64, 64));
  f.tonemap = p.Choice("tonemap", ToneMap::kClamp, kToneMaps);
  f.color_space = &p.Choice("color_space", &ColorSpace::Rec709, kColorSpaces)();
  const bool rgb = p.Choice("pixel_format", true, kPixelFormats);
  const bool float32 = p.Choice("component_format", true, kComponentFormats);
  p.Choice("file_format", true, kFileFormats);
  if (!rgb || !float32) {
    const Location& at = p.LocOf(!rgb ? "pixel_format" : "component_format");
    spdlog::warn("{}:{}: film: the EXR is written as rgb float32, not {} {}", at.file, at.line,
                 p.String("pixel_format", "rgb"), p.String("component_format", "float32"));
  }
  f.filter = BuildFilter(OneChild(p, "rfilter"));
  return f;
}

// A filter plugin: its one size property (with its default and range) and the filter it makes.
template <typename F>
FilterRegistry::PluginType SizedFilter(const char* type, const char* size, double fallback, double max) {
  return {type, {{size, PropType::kFloat}}, [=](const Properties& p) -> std::shared_ptr<const Filter> {
            return std::make_shared<F>(float(p.FloatIn(size, fallback, 1e-3, max)));
          }};
}

}  // namespace

const FilterRegistry& FilterPlugins() {
  static const FilterRegistry registry("rfilter", {},
                                       {
                                           SizedFilter<BoxFilter>("box", "radius", 0.5, 16),
                                           SizedFilter<TentFilter>("tent", "radius", 1.0, 16),
                                           SizedFilter<GaussianFilter>("gaussian", "stddev", 0.5, 4),
                                           SizedFilter<BlackmanHarrisFilter>("blackman-harris", "radius", 1.5, 16),
                                       });
  return registry;
}

const FilmRegistry& FilmPlugins() {
  static const FilmRegistry registry("film", {},
                                     {{"hdrfilm",
                                       {{"width", PropType::kInteger},
                                        {"height", PropType::kInteger},
                                        {"crop_offset_x", PropType::kInteger},
                                        {"crop_offset_y", PropType::kInteger},
                                        {"crop_width", PropType::kInteger},
                                        {"crop_height", PropType::kInteger},
                                        {"exposure", PropType::kFloat},
                                        {"tonemap", kToneMaps},
                                        {"color_space", kColorSpaces},
                                        {"pixel_format", kPixelFormats},
                                        {"component_format", kComponentFormats},
                                        {"file_format", kFileFormats},
                                        {"rfilter", PropType::kObject}},
                                       BuildHdrFilm}});
  return registry;
}

FilmSettings BuildFilm(const ObjectNode* node) {
  if (node) return FilmPlugins().Build(*node);
  FilmSettings f;
  f.filter = BuildFilter(nullptr);
  f.crop = {0, 0, f.width, f.height};
  return f;
}

}  // namespace objektiv
