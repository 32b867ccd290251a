// Spectra as written in the scene, and the <texture> plugins (bitmap, checkerboard).
#include <algorithm>

#include "base/cie.h"
#include "io/image_io.h"
#include "io/loader_context.h"

namespace objektiv {

Spectrum MakeSpectrum(const SpectrumValue& v, SpectrumUsage usage) {
  switch (v.kind) {
    case SpectrumValue::Kind::kConstant:
      // A constant emission is an equal-energy spectrum in Mitsuba; a constant reflectance is flat.
      return usage == SpectrumUsage::kIlluminant ? Spectrum::RgbIlluminant(Vec3f(v.value)) : Spectrum(v.value);
    case SpectrumValue::Kind::kRgb:
      switch (usage) {
        case SpectrumUsage::kAlbedo:
          return Spectrum::RgbAlbedo(v.rgb);
        case SpectrumUsage::kUnbounded:
        case SpectrumUsage::kData:
          return Spectrum::RgbUnbounded(v.rgb);
        case SpectrumUsage::kIlluminant:
          return Spectrum::RgbIlluminant(v.rgb);
      }
      break;
    case SpectrumValue::Kind::kSampled:
      return Spectrum::Tabulated(v.lambdas, v.values);
    case SpectrumValue::Kind::kBlackbody:
      return Spectrum::Blackbody(v.temperature, v.value);
    case SpectrumValue::Kind::kD65:
      return Spectrum::D65(v.value);
    case SpectrumValue::Kind::kIlluminantA: {
      // CIE illuminant A is Planck's law at 2856 K, normalised to luminance 1.
      Spectrum a = Spectrum::Blackbody(2856);
      return a.Scaled(v.value / SpectrumToY(a));
    }
  }
  return Spectrum(0.f);
}

std::shared_ptr<const SpectrumTexture> GetTexture(const Properties& props, const std::string& name, SpectrumUsage usage,
                                                  float fallback, LoaderContext& ctx) {
  if (auto obj = props.Object(name)) {
    if (obj->tag != "texture") throw ErrorAt(obj->loc, "'{}' must be a texture, not a {}", name, obj->tag);
    return BuildTexture(*obj, usage, ctx);
  }
  if (auto v = props.SpectrumProp(name)) {
    if (usage == SpectrumUsage::kData) {
      // Data (heights, normals) is numbers: a texture, a number or an <rgb>, never a spectrum.
      if (v->kind == SpectrumValue::Kind::kRgb) return std::make_shared<ConstantTexture>(MakeSpectrum(*v, usage), v->rgb);
      if (v->kind == SpectrumValue::Kind::kConstant)
        return std::make_shared<ConstantTexture>(MakeSpectrum(*v, usage), Vec3f(v->value));
      throw ErrorAt(props.LocOf(name),
                    "'{}' holds numbers, not light (heights, normals, weights, roughness): give a texture, a number "
                    "or an <rgb>, not a spectrum",
                    name);
    }
    Spectrum spectrum = MakeSpectrum(*v, usage);
    // A reflectance above 1 (or below 0) anywhere would create light: checked as written for an
    // <rgb> or a number, as the spectrum it makes otherwise.
    auto non_negative = [](const std::vector<float>& values) {
      return std::all_of(values.begin(), values.end(), [](float x) { return x >= 0; });
    };
    const bool in_unit_range = v->kind == SpectrumValue::Kind::kRgb
                                   ? MinComponent(v->rgb) >= 0 && MaxComponent(v->rgb) <= 1
                               : v->kind == SpectrumValue::Kind::kConstant ? v->value >= 0 && v->value <= 1
                               : v->kind == SpectrumValue::Kind::kSampled  ? non_negative(v->values) && spectrum.MaxValue() <= 1
                                                                           : spectrum.MaxValue() <= 1;
    if (usage == SpectrumUsage::kAlbedo && !in_unit_range)
      throw ErrorAt(props.LocOf(name), "reflectance '{}' must lie in [0, 1]", name);
    return std::make_shared<ConstantTexture>(std::move(spectrum));
  }
  SpectrumValue s;
  s.kind = SpectrumValue::Kind::kConstant;
  s.value = fallback;
  return std::make_shared<ConstantTexture>(MakeSpectrum(s, usage));
}

namespace {

constexpr Named<FilterMode> kFilterModes[] = {{"bilinear", FilterMode::kBilinear}, {"nearest", FilterMode::kNearest}};
constexpr Named<WrapMode> kWrapModes[] = {
    {"repeat", WrapMode::kRepeat}, {"mirror", WrapMode::kMirror}, {"clamp", WrapMode::kClamp}};

std::shared_ptr<const SpectrumTexture> BuildBitmap(const Properties& p, SpectrumUsage usage, LoaderContext&) {
  std::string file = ResolvePath(p.LocOf("filename"), p.String("filename"));
  // Data (a bump map's heights, a normal map's normals) is read as stored, unless the scene
  // asks for sRGB decoding with raw = false; colours are decoded unless raw = true.
  bool raw = p.Bool("raw", usage == SpectrumUsage::kData);
  FilterMode filter = p.Choice("filter_type", FilterMode::kBilinear, kFilterModes);
  WrapMode wrap = p.Choice("wrap_mode", WrapMode::kRepeat, kWrapModes);
  Image img = ReadImageRgb(file, raw);
  return std::make_shared<BitmapTexture>(std::move(img), usage, filter, wrap, p.GetTransform("to_uv"));
}

std::shared_ptr<const SpectrumTexture> BuildCheckerboard(const Properties& p, SpectrumUsage usage, LoaderContext& ctx) {
  return std::make_shared<CheckerboardTexture>(GetTexture(p, "color0", usage, 0.4f, ctx),
                                               GetTexture(p, "color1", usage, 0.2f, ctx), p.GetTransform("to_uv"));
}

}  // namespace

const TextureRegistry& TexturePlugins() {
  static const TextureRegistry registry(
      "texture", {{"to_uv", PropType::kTransform}},
      {
          {"bitmap",
           {{"filename", PropType::kString},
            {"raw", PropType::kBoolean},
            {"filter_type", kFilterModes},
            {"wrap_mode", kWrapModes}},
           BuildBitmap},
          {"checkerboard",
           {{"color0", PropType::kSpectrumOrTexture}, {"color1", PropType::kSpectrumOrTexture}},
           BuildCheckerboard},
      });
  return registry;
}

std::shared_ptr<const SpectrumTexture> BuildTexture(const ObjectNode& node, SpectrumUsage usage, LoaderContext& ctx) {
  auto key = std::make_pair(&node, int(usage));
  if (auto it = ctx.textures.find(key); it != ctx.textures.end()) return it->second;
  auto tex = TexturePlugins().Build(node, usage, ctx);
  ctx.textures[key] = tex;
  return tex;
}

}  // namespace objektiv
