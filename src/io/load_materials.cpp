// Builders for spectra, textures (<texture>) and materials (<bsdf>).
#include <cmath>
#include <functional>

#include "base/cie.h"
#include "io/image_io.h"
#include "io/loader_context.h"
#include "optics/glass_catalog.h"
#include "scene/conductor_data.h"

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
    if (usage == SpectrumUsage::kAlbedo && v->kind == SpectrumValue::Kind::kRgb &&
        (MinComponent(v->rgb) < 0 || MaxComponent(v->rgb) > 1))
      throw ErrorAt(props.LocOf(name), "reflectance '{}' must lie in [0, 1]", name);
    return std::make_shared<ConstantTexture>(MakeSpectrum(*v, usage));
  }
  SpectrumValue s;
  s.kind = SpectrumValue::Kind::kConstant;
  s.value = fallback;
  return std::make_shared<ConstantTexture>(MakeSpectrum(s, usage));
}

namespace {

Transform ToUv(const Properties& p) { return p.GetTransform("to_uv"); }

using TextureFactory = std::function<std::shared_ptr<const SpectrumTexture>(const Properties&, SpectrumUsage, LoaderContext&)>;

const std::map<std::string, TextureFactory>& TextureRegistry() {
  static const std::map<std::string, TextureFactory> registry = {
      {"bitmap",
       [](const Properties& p, SpectrumUsage usage, LoaderContext&) -> std::shared_ptr<const SpectrumTexture> {
         std::string file = ResolvePath(p.LocOf("filename"), p.String("filename"));
         bool raw = p.Bool("raw", false);
         std::string filter = p.Choice("filter_type", "bilinear", {"bilinear", "nearest"});
         std::string wrap = p.Choice("wrap_mode", "repeat", {"repeat", "mirror", "clamp"});
         Image img = ReadImageRgb(file, raw);
         WrapMode wm = wrap == "repeat" ? WrapMode::kRepeat : wrap == "mirror" ? WrapMode::kMirror : WrapMode::kClamp;
         return std::make_shared<BitmapTexture>(std::move(img), usage,
                                                filter == "nearest" ? FilterMode::kNearest : FilterMode::kBilinear, wm,
                                                ToUv(p));
       }},
      {"checkerboard",
       [](const Properties& p, SpectrumUsage usage, LoaderContext& ctx) -> std::shared_ptr<const SpectrumTexture> {
         return std::make_shared<CheckerboardTexture>(GetTexture(p, "color0", usage, 0.4f, ctx),
                                                      GetTexture(p, "color1", usage, 0.2f, ctx), ToUv(p));
       }},
  };
  return registry;
}

}  // namespace

std::shared_ptr<const SpectrumTexture> BuildTexture(const ObjectNode& node, SpectrumUsage usage, LoaderContext& ctx) {
  auto key = std::make_pair(&node, int(usage));
  if (auto it = ctx.textures.find(key); it != ctx.textures.end()) return it->second;
  const auto& registry = TextureRegistry();
  auto it = registry.find(node.type);
  if (it == registry.end()) UnknownType(node, registry);
  Properties props(node);
  auto tex = it->second(props, usage, ctx);
  props.WarnUnused();
  ctx.textures[key] = tex;
  return tex;
}

namespace {

const Property* FindProperty(const Properties& p, const std::string& name) {
  for (const Property& q : p.node().props)
    if (q.name == name) return &q;
  return nullptr;
}

// An index of refraction given as a number or one of Mitsuba's names.
double GetIor(const Properties& p, const std::string& name, double fallback) {
  if (!p.Has(name)) return fallback;
  const Property* prop = FindProperty(p, name);
  if (std::holds_alternative<std::string>(prop->data)) {
    std::string s = p.String(name);
    if (auto v = NamedIor(s)) return *v;
    throw ErrorAt(prop->loc, "unknown index of refraction '{}' (a number, or a name such as bk7, water, air, diamond)", s);
  }
  double v = p.Float(name);
  if (!(v > 0)) throw ErrorAt(prop->loc, "index of refraction must be positive, got {}", v);
  return v;
}

// Coefficients must give a real, positive index at every wavelength rendered (1 nm steps over
// [kLambdaMin, kLambdaMax]); a Sellmeier pole or a negative n^2 inside it is an error.
IorModel CheckedDispersion(IorModel ior, const Location& loc, const char* formula) {
  for (int l = int(kLambdaMin); l <= int(kLambdaMax); ++l) {
    double n = ior(l);
    if (!(n > 0) || !std::isfinite(n))
      throw ErrorAt(loc, "the {} coefficients give no real positive index of refraction at {} nm", formula, l);
  }
  return ior;
}

// The interior index of a dielectric: constant, Cauchy or Sellmeier coefficients.
IorModel GetInteriorIor(const Properties& p) {
  bool cauchy = p.Has("cauchy_a"), sellmeier = p.Has("sellmeier_b1");
  if (cauchy && sellmeier) throw ErrorAt(p.loc(), "give either Cauchy or Sellmeier coefficients, not both");
  if ((cauchy || sellmeier) && p.Has("int_ior"))
    throw ErrorAt(p.LocOf("int_ior"), "int_ior and dispersion coefficients exclude each other");
  if (cauchy)
    return CheckedDispersion(IorModel::Cauchy(p.Float("cauchy_a"), p.Float("cauchy_b", 0), p.Float("cauchy_c", 0)),
                             p.LocOf("cauchy_a"), "Cauchy");
  if (sellmeier) {
    std::array<double, 3> b{}, c{};
    for (int i = 0; i < 3; ++i) {
      b[i] = p.Float(fmt::format("sellmeier_b{}", i + 1), 0);
      c[i] = p.Float(fmt::format("sellmeier_c{}", i + 1), 0);
    }
    return CheckedDispersion(IorModel::Sellmeier(b, c), p.LocOf("sellmeier_b1"), "Sellmeier");
  }
  // A name that is not one of Mitsuba's constants is looked up in the glass catalogs.
  if (p.Has("int_ior") && std::holds_alternative<std::string>(FindProperty(p, "int_ior")->data)) {
    std::string name = p.String("int_ior");
    if (!NamedIor(name)) {
      const Glass* glass = GlassCatalog::Default().Find(name);
      if (!glass)
        throw ErrorAt(p.LocOf("int_ior"),
                      "unknown index of refraction '{}' (a number, a name such as bk7 or water, or a catalog glass "
                      "such as N-BK7 or OHARA:S-BSL7)",
                      name);
      return IorModel::FromGlass(glass);
    }
  }
  return IorModel(GetIor(p, "int_ior", *NamedIor("bk7")));
}

// Roughness: alpha, or alpha_u and alpha_v (anisotropic); only GGX is implemented.
std::pair<float, float> GetAlpha(const Properties& p, float fallback) {
  p.Choice("distribution", "ggx", {"ggx"});
  float a = float(p.FloatIn("alpha", fallback, 0, 10));
  return {float(p.FloatIn("alpha_u", a, 0, 10)), float(p.FloatIn("alpha_v", a, 0, 10))};
}

std::shared_ptr<Material> MakeDielectric(const Properties& p, LoaderContext& ctx, bool rough) {
  auto [au, av] = rough ? GetAlpha(p, 0.1f) : std::pair<float, float>{0.f, 0.f};
  IorModel int_ior = GetInteriorIor(p);
  double ext_ior = GetIor(p, "ext_ior", *NamedIor("air"));
  auto m = std::make_shared<DielectricMaterial>(int_ior, ext_ior, au, av,
                                                GetTexture(p, "specular_reflectance", SpectrumUsage::kUnbounded, 1, ctx),
                                                GetTexture(p, "specular_transmittance", SpectrumUsage::kUnbounded, 1, ctx));
  if (auto sigma = p.SpectrumProp("absorption")) m->SetAbsorption(MakeSpectrum(*sigma, SpectrumUsage::kUnbounded));
  return m;
}

std::shared_ptr<Material> MakeConductor(const Properties& p, LoaderContext& ctx, bool rough) {
  auto [au, av] = rough ? GetAlpha(p, 0.1f) : std::pair<float, float>{0.f, 0.f};
  Spectrum eta, k;
  if (p.Has("eta") || p.Has("k")) {
    if (p.Has("material")) throw ErrorAt(p.LocOf("material"), "give either 'material' or 'eta' and 'k', not both");
    eta = MakeSpectrum(p.SpectrumProp("eta").value_or(SpectrumValue{}), SpectrumUsage::kUnbounded);
    k = MakeSpectrum(p.SpectrumProp("k").value_or(SpectrumValue{}), SpectrumUsage::kUnbounded);
  } else {
    std::string name = p.String("material", "none");
    std::optional<ConductorIndex> data = NamedConductor(name);
    if (!data) throw ErrorAt(p.LocOf("material"), "unknown conductor '{}' (known: {})", name, NamedConductorList());
    eta = data->eta;
    k = data->k;
  }
  return std::make_shared<ConductorMaterial>(eta, k, au, av,
                                             GetTexture(p, "specular_reflectance", SpectrumUsage::kUnbounded, 1, ctx));
}

using MaterialFactory = std::function<std::shared_ptr<Material>(const Properties&, LoaderContext&)>;
std::shared_ptr<Material> MakeMaterial(const ObjectNode& node, LoaderContext& ctx);

const std::map<std::string, MaterialFactory>& MaterialRegistry() {
  static const std::map<std::string, MaterialFactory> registry = {
      {"diffuse",
       [](const Properties& p, LoaderContext& ctx) -> std::shared_ptr<Material> {
         return std::make_shared<DiffuseMaterial>(GetTexture(p, "reflectance", SpectrumUsage::kAlbedo, 0.5f, ctx));
       }},
      {"dielectric", [](const Properties& p, LoaderContext& ctx) { return MakeDielectric(p, ctx, false); }},
      {"roughdielectric", [](const Properties& p, LoaderContext& ctx) { return MakeDielectric(p, ctx, true); }},
      {"conductor", [](const Properties& p, LoaderContext& ctx) { return MakeConductor(p, ctx, false); }},
      {"roughconductor", [](const Properties& p, LoaderContext& ctx) { return MakeConductor(p, ctx, true); }},
      {"plastic",
       [](const Properties& p, LoaderContext& ctx) -> std::shared_ptr<Material> {
         double int_ior = GetIor(p, "int_ior", 1.49), ext_ior = GetIor(p, "ext_ior", 1.000277);
         return std::make_shared<PlasticMaterial>(float(int_ior), float(ext_ior),
                                                  GetTexture(p, "diffuse_reflectance", SpectrumUsage::kAlbedo, 0.5f, ctx),
                                                  GetTexture(p, "specular_reflectance", SpectrumUsage::kUnbounded, 1, ctx),
                                                  p.Bool("nonlinear", false));
       }},
      {"twosided",
       [](const Properties& p, LoaderContext& ctx) -> std::shared_ptr<Material> {
         auto inner = p.Children("bsdf");
         if (inner.size() != 1) throw ErrorAt(p.loc(), "twosided needs exactly one nested <bsdf>, got {}", inner.size());
         const ObjectNode& in = *inner[0];
         if (in.type == "twosided") throw ErrorAt(in.loc, "twosided cannot wrap another twosided");
         // A private copy: the same inner BSDF may be used one-sided elsewhere.
         std::shared_ptr<Material> m = MakeMaterial(in, ctx);
         m->SetTwoSided(true);
         return m;
       }},
  };
  return registry;
}

// A new material from a <bsdf> (its unused properties warned about).
std::shared_ptr<Material> MakeMaterial(const ObjectNode& node, LoaderContext& ctx) {
  const auto& registry = MaterialRegistry();
  auto it = registry.find(node.type);
  if (it == registry.end()) UnknownType(node, registry);
  Properties props(node);
  std::shared_ptr<Material> material = it->second(props, ctx);
  props.WarnUnused();
  return material;
}

}  // namespace

std::shared_ptr<const Material> BuildMaterial(const ObjectNode& node, LoaderContext& ctx) {
  if (auto it = ctx.materials.find(&node); it != ctx.materials.end()) return it->second;
  std::shared_ptr<const Material> material = MakeMaterial(node, ctx);
  ctx.materials[&node] = material;
  return material;
}

}  // namespace objektiv
