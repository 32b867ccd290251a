// The <bsdf> plugins (materials).
#include <algorithm>
#include <cmath>

#include <spdlog/spdlog.h>

#include "base/cie.h"
#include "base/log.h"
#include "io/loader_context.h"
#include "optics/glass_catalog.h"
#include "base/conductor_data.h"
#include "scene/blend_material.h"
#include "scene/normal_mapping.h"

namespace objektiv {
namespace {

// Every <bsdf> is made here: Mitsuba's thin principled variant is named, and refused, before
// the registry would call it an unknown type.
std::shared_ptr<Material> BuildBsdfNode(const ObjectNode& node, LoaderContext& ctx) {
  if (node.type == "principledthin")
    throw ErrorAt(node.loc, "bsdf type 'principledthin' (Mitsuba's thin principled, with flatness and diff_trans) is "
                  "not supported; use 'principled' on a closed shape");
  return MaterialPlugins().Build(node, ctx);
}

// An index of refraction given as a number or one of Mitsuba's names.
double GetIor(const Properties& p, const std::string& name, double fallback) {
  if (!p.Has(name)) return fallback;
  if (p.TypeOf(name) == ValueType::kString) {
    std::string s = p.String(name);
    if (auto v = NamedIor(s)) return *v;
    throw ErrorAt(p.LocOf(name),
                  "unknown index of refraction '{}' (a number, or a name such as bk7, water, air, diamond)", s);
  }
  double v = p.Float(name);
  if (!(v > 0)) throw ErrorAt(p.LocOf(name), "index of refraction must be positive, got {}", v);
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
IorModel GetInteriorIor(const Properties& p, const GlassCatalog& glasses) {
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
  if (p.TypeOf("int_ior") == ValueType::kString) {
    std::string name = p.String("int_ior");
    if (!NamedIor(name)) {
      const Glass* glass = glasses.Find(name);
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

enum class Distribution { kGgx };
constexpr Named<Distribution> kDistributions[] = {{"ggx", Distribution::kGgx}};

// Roughness: alpha, or alpha_u and alpha_v (anisotropic); only GGX is implemented.
const std::vector<PropertyDecl> kRoughness = {{"distribution", kDistributions},
                                              {"alpha", PropType::kFloat},
                                              {"alpha_u", PropType::kFloat},
                                              {"alpha_v", PropType::kFloat}};
std::pair<float, float> GetAlpha(const Properties& p, float fallback) {
  p.Choice("distribution", Distribution::kGgx, kDistributions);
  float a = float(p.FloatIn("alpha", fallback, 0, 10));
  return {float(p.FloatIn("alpha_u", a, 0, 10)), float(p.FloatIn("alpha_v", a, 0, 10))};
}

std::shared_ptr<Material> MakeDielectric(const Properties& p, LoaderContext& ctx, bool rough) {
  auto [au, av] = rough ? GetAlpha(p, 0.1f) : std::pair<float, float>{0.f, 0.f};
  IorModel int_ior = GetInteriorIor(p, ctx.glasses);
  double ext_ior = GetIor(p, "ext_ior", *NamedIor("air"));
  auto m = std::make_shared<DielectricMaterial>(int_ior, ext_ior, au, av,
                                                GetTexture(p, "specular_reflectance", SpectrumUsage::kUnbounded, 1, ctx),
                                                GetTexture(p, "specular_transmittance", SpectrumUsage::kUnbounded, 1, ctx));
  if (auto sigma = p.SpectrumProp("absorption")) m->SetAbsorption(MakeSpectrum(*sigma, SpectrumUsage::kUnbounded));
  return m;
}

std::shared_ptr<Material> MakeThinDielectric(const Properties& p, LoaderContext& ctx) {
  return std::make_shared<ThinDielectricMaterial>(
      GetInteriorIor(p, ctx.glasses), GetIor(p, "ext_ior", *NamedIor("air")),
      GetTexture(p, "specular_reflectance", SpectrumUsage::kUnbounded, 1, ctx),
      GetTexture(p, "specular_transmittance", SpectrumUsage::kUnbounded, 1, ctx));
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

const std::vector<PropertyDecl> kDielectric = {{"int_ior", PropType::kFloatOrString},
                                               {"ext_ior", PropType::kFloatOrString},
                                               {"cauchy_a", PropType::kFloat},
                                               {"cauchy_b", PropType::kFloat},
                                               {"cauchy_c", PropType::kFloat},
                                               {"sellmeier_b1", PropType::kFloat},
                                               {"sellmeier_b2", PropType::kFloat},
                                               {"sellmeier_b3", PropType::kFloat},
                                               {"sellmeier_c1", PropType::kFloat},
                                               {"sellmeier_c2", PropType::kFloat},
                                               {"sellmeier_c3", PropType::kFloat},
                                               {"specular_reflectance", PropType::kSpectrumOrTexture},
                                               {"specular_transmittance", PropType::kSpectrumOrTexture},
                                               {"absorption", PropType::kSpectrum}};
// A thin sheet: the dielectric's index and colours, no volume to absorb in.
const std::vector<PropertyDecl> kThinDielectric = [] {
  std::vector<PropertyDecl> decls;
  for (const PropertyDecl& d : kDielectric)
    if (d.name != "absorption") decls.push_back(d);
  return decls;
}();
const std::vector<PropertyDecl> kConductor = {{"material", PropType::kString},
                                              {"eta", PropType::kSpectrum},
                                              {"k", PropType::kSpectrum},
                                              {"specular_reflectance", PropType::kSpectrumOrTexture}};

std::shared_ptr<Material> MakeDiffuse(const Properties& p, LoaderContext& ctx) {
  return std::make_shared<DiffuseMaterial>(GetTexture(p, "reflectance", SpectrumUsage::kAlbedo, 0.5f, ctx));
}

std::shared_ptr<Material> MakePlastic(const Properties& p, LoaderContext& ctx) {
  double int_ior = GetIor(p, "int_ior", 1.49), ext_ior = GetIor(p, "ext_ior", 1.000277);
  return std::make_shared<PlasticMaterial>(
      float(int_ior), float(ext_ior), GetTexture(p, "diffuse_reflectance", SpectrumUsage::kAlbedo, 0.5f, ctx),
      GetTexture(p, "specular_reflectance", SpectrumUsage::kUnbounded, 1, ctx), p.Bool("nonlinear", false));
}

// Mitsuba 3's roughplastic: plastic's parameters and the coat's GGX roughness alpha (isotropic).
std::shared_ptr<Material> MakeRoughPlastic(const Properties& p, LoaderContext& ctx) {
  p.Choice("distribution", Distribution::kGgx, kDistributions);
  if (p.Has("alpha")) {
    const double a = p.Float("alpha");
    if (!(a >= 1e-3 && a <= 1))
      throw ErrorAt(p.LocOf("alpha"), "roughplastic: alpha must lie in [0.001, 1], got {} (for a smooth coat use plastic)", a);
  }
  const double alpha = p.Float("alpha", 0.1);
  const double int_ior = GetIor(p, "int_ior", 1.49), ext_ior = GetIor(p, "ext_ior", 1.000277);
  return std::make_shared<RoughPlasticMaterial>(
      float(alpha), float(int_ior), float(ext_ior), GetTexture(p, "diffuse_reflectance", SpectrumUsage::kAlbedo, 0.5f, ctx),
      GetTexture(p, "specular_reflectance", SpectrumUsage::kUnbounded, 1, ctx), p.Bool("nonlinear", false));
}

// A weight or an opacity (blendbsdf, mask): a number or colour must lie in [0, 1]; a texture's
// values are clamped to it where they are read (TextureWeight).
std::shared_ptr<const SpectrumTexture> GetUnitParameter(const Properties& p, const std::string& name, float fallback,
                                                        LoaderContext& ctx) {
  if (const std::optional<SpectrumValue> v = p.Has(name) && !p.Object(name) ? p.SpectrumProp(name) : std::nullopt) {
    const bool in_range = v->kind == SpectrumValue::Kind::kConstant ? v->value >= 0 && v->value <= 1
                          : v->kind == SpectrumValue::Kind::kRgb    ? MinComponent(v->rgb) >= 0 && MaxComponent(v->rgb) <= 1
                                                                    : true;
    if (!in_range) throw ErrorAt(p.LocOf(name), "{}: '{}' must lie in [0, 1]", p.type(), name);
  }
  return GetTexture(p, name, SpectrumUsage::kData, fallback, ctx);
}

std::shared_ptr<const SpectrumTexture> GetWeight(const Properties& p, const std::string& name, LoaderContext& ctx) {
  return GetUnitParameter(p, name, 0.5f, ctx);
}

// Mitsuba 3's principled: eta or specular (not both; specular s gives eta = 2 / (1 -
// sqrt(0.08 s)) - 1, so eta in (1, 10] is s in (0, 8.37]), the other parameters numbers in
// [0, 1] or textures.
std::shared_ptr<Material> MakePrincipled(const Properties& p, LoaderContext& ctx) {
  PrincipledMaterial::Parameters m;
  for (const char* thin : {"flatness", "diff_trans"})
    if (p.Has(thin))
      throw ErrorAt(p.LocOf(thin), "principled: '{}' belongs to Mitsuba's principledthin, which is not supported", thin);
  if (p.Has("eta") && p.Has("specular"))
    throw ErrorAt(p.LocOf("specular"), "principled: give either eta or specular, not both");
  if (p.Has("eta")) {
    const double eta = p.Float("eta");
    if (!(eta > 1 && eta <= 10))
      throw ErrorAt(p.LocOf("eta"), "principled: eta must lie in (1, 10] (interior over exterior index), got {}", eta);
    m.eta = float(eta);
  } else {
    const double spec = p.Float("specular", 0.5);
    const double eta = spec > 0 && spec < 12.5 ? 2 / (1 - std::sqrt(0.08 * spec)) - 1 : 0;
    if (!(eta > 1 && eta <= 10))
      throw ErrorAt(p.LocOf("specular"),
                    "principled: specular must lie in (0, 8.37] (it gives eta = 2 / (1 - sqrt(0.08 specular)) - 1, at "
                    "most 10), got {}",
                    spec);
    m.eta = float(eta);
  }
  m.base_color = GetTexture(p, "base_color", SpectrumUsage::kAlbedo, 0.5f, ctx);
  m.roughness = GetUnitParameter(p, "roughness", 0.5f, ctx);
  m.anisotropic = GetUnitParameter(p, "anisotropic", 0, ctx);
  m.metallic = GetUnitParameter(p, "metallic", 0, ctx);
  m.spec_trans = GetUnitParameter(p, "spec_trans", 0, ctx);
  m.spec_tint = GetUnitParameter(p, "spec_tint", 0, ctx);
  m.sheen = GetUnitParameter(p, "sheen", 0, ctx);
  m.sheen_tint = GetUnitParameter(p, "sheen_tint", 0, ctx);
  m.clearcoat = GetUnitParameter(p, "clearcoat", 0, ctx);
  m.clearcoat_gloss = GetUnitParameter(p, "clearcoat_gloss", 0, ctx);
  m.diffuse_rate = float(p.FloatIn("diffuse_reflectance_sampling_rate", 1, 0, 1e3));
  m.specular_rate = float(p.FloatIn("main_specular_sampling_rate", 1, 0, 1e3));
  m.clearcoat_rate = float(p.FloatIn("clearcoat_sampling_rate", 1, 0, 1e3));
  if (!(m.specular_rate > 0))
    throw ErrorAt(p.LocOf("main_specular_sampling_rate"), "principled: main_specular_sampling_rate must be positive");
  m.sample_visible = p.Bool("sample_visible", true);
  return std::make_shared<PrincipledMaterial>(std::move(m));
}

// The nested <bsdf>s a blendbsdf or mask is made of, exactly `count` of them.
std::vector<std::shared_ptr<Material>> NestedMaterials(const Properties& p, LoaderContext& ctx, size_t count) {
  auto nodes = p.Children("bsdf");
  if (nodes.size() != count)
    throw ErrorAt(p.loc(), "{} needs exactly {} nested <bsdf>{}, got {}", p.type(), count, count == 1 ? "" : "s", nodes.size());
  std::vector<std::shared_ptr<Material>> out;
  for (const auto& n : nodes) {
    std::shared_ptr<Material> m = BuildBsdfNode(*n, ctx);
    if (m->Absorption())
      throw ErrorAt(n->loc, "{} cannot hold a dielectric with absorption (the medium behind a blend or mask has no one "
                    "interior)", p.type());
    // (A null part would be a surface that is not there on part of it: that is a mask's
    // opacity, and rays passing it would not enter the medium it bounds.)
    if (m->IsNull())
      throw ErrorAt(n->loc, "{} cannot hold a null BSDF (for a surface with holes, use a mask's opacity)", p.type());
    out.push_back(std::move(m));
  }
  return out;
}

std::shared_ptr<Material> MakeBlend(const Properties& p, LoaderContext& ctx) {
  std::shared_ptr<const SpectrumTexture> weight = GetWeight(p, "weight", ctx);
  std::vector<std::shared_ptr<Material>> parts = NestedMaterials(p, ctx, 2);
  auto blend = std::make_shared<BlendMaterial>(parts[0], parts[1], std::move(weight));
  if (blend->Leaves() > kMaxBlendLeaves)
    throw ErrorAt(p.loc(), "blendbsdf: blends nested in blends mix {} BSDFs, more than the {} supported", blend->Leaves(),
                  kMaxBlendLeaves);
  return blend;
}

std::shared_ptr<Material> MakeMask(const Properties& p, LoaderContext& ctx) {
  std::shared_ptr<const SpectrumTexture> opacity = GetWeight(p, "opacity", ctx);
  return std::make_shared<MaskMaterial>(NestedMaterials(p, ctx, 1)[0], std::move(opacity));
}

// The classic tracer's `phong` (Mitsuba 0.6's names): diffuse and specular colour, exponent.
std::shared_ptr<Material> MakePhong(const Properties& p, LoaderContext& ctx) {
  auto kd = GetTexture(p, "diffuse_reflectance", SpectrumUsage::kAlbedo, 0.5f, ctx);
  auto ks = GetTexture(p, "specular_reflectance", SpectrumUsage::kAlbedo, 0.2f, ctx);
  const float exponent = float(p.FloatIn("exponent", 30, 0, 1e5));
  // The colours as written (where both are numbers): their sum above 1 reflects more than
  // arrives. (An RGB colour's smooth spectrum can also exceed its RGB values near the ends of
  // the visible range; the material scales those wavelengths without a word.)
  auto largest = [&p](const char* name, const SpectrumTexture& texture, float fallback) -> std::optional<float> {
    if (!dynamic_cast<const ConstantTexture*>(&texture)) return std::nullopt;
    if (!p.Has(name)) return fallback;
    const std::optional<SpectrumValue> v = p.SpectrumProp(name);
    if (!v) return std::nullopt;
    if (v->kind == SpectrumValue::Kind::kRgb) return std::max({v->rgb.x, v->rgb.y, v->rgb.z});
    if (v->kind == SpectrumValue::Kind::kConstant) return v->value;
    if (v->kind == SpectrumValue::Kind::kSampled && !v->values.empty())
      return *std::max_element(v->values.begin(), v->values.end());
    return std::nullopt;
  };
  const std::optional<float> d = largest("diffuse_reflectance", *kd, 0.5f),
                             s = largest("specular_reflectance", *ks, 0.2f);
  if (d && s && *d + *s > 1.0001f)
    spdlog::warn("{}:{}: phong: diffuse_reflectance + specular_reflectance reach {:.3g}, above 1: both are scaled "
                 "down where they sum above 1, so that the surface reflects no more than arrives",
                 p.loc().file, p.loc().line, *d + *s);
  return std::make_shared<PhongMaterial>(std::move(kd), std::move(ks), exponent);
}

std::shared_ptr<Material> MakeTwoSided(const Properties& p, LoaderContext& ctx) {
  auto inner = p.Children("bsdf");
  if (inner.size() != 1) throw ErrorAt(p.loc(), "twosided needs exactly one nested <bsdf>, got {}", inner.size());
  const ObjectNode& in = *inner[0];
  if (in.type == "twosided") throw ErrorAt(in.loc, "twosided cannot wrap another twosided");
  // A private copy: the same inner BSDF may be used one-sided elsewhere.
  std::shared_ptr<Material> m = BuildBsdfNode(in, ctx);
  m->SetTwoSided(true);
  return m;
}

// The one nested <bsdf> a bumpmap or normalmap wraps, built for it alone (an enclosing
// twosided changes it).
std::shared_ptr<Material> WrappedMaterial(const Properties& p, LoaderContext& ctx) {
  auto inner = p.Children("bsdf");
  if (inner.size() != 1) throw ErrorAt(p.loc(), "{} needs exactly one nested <bsdf> to wrap, got {}", p.type(), inner.size());
  std::shared_ptr<Material> m = BuildBsdfNode(*inner[0], ctx);
  if (m->IsNull()) throw ErrorAt(inner[0]->loc, "{} cannot wrap a null BSDF (it has no surface to perturb)", p.type());
  return m;
}

// Mitsuba 3's bumpmap: heights from one texture (named 'arg', or unnamed), times 'scale'.
std::shared_ptr<Material> MakeBumpMap(const Properties& p, LoaderContext& ctx) {
  auto unnamed = p.Children("texture");
  const size_t given = unnamed.size() + (p.Has("arg") ? 1 : 0);
  if (given == 0)
    throw ErrorAt(p.loc(), "bumpmap needs a texture of heights: a nested <texture name=\"arg\" type=\"bitmap\"> (or one unnamed <texture>)");
  if (given > 1) throw ErrorAt(p.loc(), "bumpmap takes one texture of heights, got {}", given);
  std::shared_ptr<const SpectrumTexture> height = p.Has("arg") ? GetTexture(p, "arg", SpectrumUsage::kData, 0, ctx)
                                                               : BuildTexture(*unnamed[0], SpectrumUsage::kData, ctx);
  const double scale = p.Float("scale", 1);
  if (!std::isfinite(scale)) throw ErrorAt(p.LocOf("scale"), "bumpmap: scale must be finite, got {}", scale);
  std::shared_ptr<Material> inner = WrappedMaterial(p, ctx);
  if (height->IsPiecewiseConstant() || scale == 0) {
    const Location& at = p.Has("arg") ? p.LocOf("arg") : unnamed[0]->loc;
    spdlog::warn("{}:{}: bumpmap changes nothing: {}", at.file, at.line,
                 scale == 0 ? "its scale is 0"
                            : "its heights have no slope anywhere (a constant, a checkerboard of constants or a bitmap "
                              "with filter_type nearest; use a bilinear bitmap)");
  }
  return std::make_shared<BumpMapMaterial>(std::move(inner), std::move(height), float(scale));
}

// A normal map's colour c stores the tangent-space normal 2 c - 1, of length 1 and pointing out
// of the surface (z > 0). Where it decodes to hardly any direction (length below 1/2: mid-grey,
// a map saved with the wrong encoding or a colour image given by mistake) or into the surface,
// the surface is shaded with its own normal (scene/normal_mapping.h): warned, with how many texels.
void WarnOfTexelsWithoutNormal(const Properties& p, const SpectrumTexture& normals) {
  auto unusable = [](Vec3f c) {
    const Vec3f n = c * 2.f - Vec3f(1.f);
    return !(Length(n) >= 0.5f && n.z > 0);
  };
  size_t bad = 0, total = 1;
  if (const auto* bitmap = dynamic_cast<const BitmapTexture*>(&normals)) {
    const Image& image = bitmap->image();
    total = size_t(image.width) * image.height;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) bad += unusable(image.Rgb(x, y));
  } else if (const auto* constant = dynamic_cast<const ConstantTexture*>(&normals)) {
    bad = unusable(constant->MeanRgb());
  }
  if (bad > 0)
    spdlog::warn("{}:{}: normalmap: {} of {} texels decode to no outward normal (2 c - 1 shorter than 1/2, or "
                 "pointing into the surface): the surface keeps its own normal there (a tangent-space map is "
                 "bluish, (0.5, 0.5, 1) where flat)",
                 p.loc().file, p.loc().line, bad, total);
}

// Mitsuba 3's normalmap: tangent-space normals from the texture named 'normalmap'.
std::shared_ptr<Material> MakeNormalMap(const Properties& p, LoaderContext& ctx) {
  if (!p.Has("normalmap"))
    throw ErrorAt(p.loc(), "normalmap needs its texture of normals: a nested <texture name=\"normalmap\" type=\"bitmap\">");
  std::shared_ptr<const SpectrumTexture> normals = GetTexture(p, "normalmap", SpectrumUsage::kData, 0, ctx);
  WarnOfTexelsWithoutNormal(p, *normals);
  return std::make_shared<NormalMapMaterial>(WrappedMaterial(p, ctx), std::move(normals));
}

}  // namespace

const MaterialRegistry& MaterialPlugins() {
  using P = const Properties&;
  static const MaterialRegistry registry(
      "bsdf", {},
      {
          {"diffuse", {{"reflectance", PropType::kSpectrumOrTexture}}, MakeDiffuse},
          // Mitsuba 3's `null`: no surface, only a medium boundary (Material::IsNull).
          {"null", {}, [](P, LoaderContext&) -> std::shared_ptr<Material> { return std::make_shared<NullMaterial>(); }},
          {"dielectric", kDielectric, [](P p, LoaderContext& ctx) { return MakeDielectric(p, ctx, false); }},
          {"roughdielectric", Join(kDielectric, kRoughness),
           [](P p, LoaderContext& ctx) { return MakeDielectric(p, ctx, true); }},
          {"thindielectric", kThinDielectric, MakeThinDielectric},
          {"conductor", kConductor, [](P p, LoaderContext& ctx) { return MakeConductor(p, ctx, false); }},
          {"roughconductor", Join(kConductor, kRoughness),
           [](P p, LoaderContext& ctx) { return MakeConductor(p, ctx, true); }},
          {"plastic",
           {{"int_ior", PropType::kFloatOrString},
            {"ext_ior", PropType::kFloatOrString},
            {"diffuse_reflectance", PropType::kSpectrumOrTexture},
            {"specular_reflectance", PropType::kSpectrumOrTexture},
            {"nonlinear", PropType::kBoolean}},
           MakePlastic},
          {"roughplastic",
           {{"distribution", kDistributions},
            {"alpha", PropType::kFloat},
            {"int_ior", PropType::kFloatOrString},
            {"ext_ior", PropType::kFloatOrString},
            {"diffuse_reflectance", PropType::kSpectrumOrTexture},
            {"specular_reflectance", PropType::kSpectrumOrTexture},
            {"nonlinear", PropType::kBoolean}},
           MakeRoughPlastic},
          {"principled",
           {{"base_color", PropType::kSpectrumOrTexture},
            {"roughness", PropType::kSpectrumOrTexture},
            {"anisotropic", PropType::kSpectrumOrTexture},
            {"metallic", PropType::kSpectrumOrTexture},
            {"spec_trans", PropType::kSpectrumOrTexture},
            {"eta", PropType::kFloat},
            {"specular", PropType::kFloat},
            {"spec_tint", PropType::kSpectrumOrTexture},
            {"sheen", PropType::kSpectrumOrTexture},
            {"sheen_tint", PropType::kSpectrumOrTexture},
            {"clearcoat", PropType::kSpectrumOrTexture},
            {"clearcoat_gloss", PropType::kSpectrumOrTexture},
            {"diffuse_reflectance_sampling_rate", PropType::kFloat},
            {"main_specular_sampling_rate", PropType::kFloat},
            {"clearcoat_sampling_rate", PropType::kFloat},
            {"sample_visible", PropType::kBoolean},
            {"flatness", PropType::kSpectrumOrTexture},
            {"diff_trans", PropType::kSpectrumOrTexture}},
           MakePrincipled},
          {"blendbsdf", {{"bsdf", PropType::kObject}, {"weight", PropType::kSpectrumOrTexture}}, MakeBlend},
          {"mask", {{"bsdf", PropType::kObject}, {"opacity", PropType::kSpectrumOrTexture}}, MakeMask},
          {"phong",
           {{"diffuse_reflectance", PropType::kSpectrumOrTexture},
            {"specular_reflectance", PropType::kSpectrumOrTexture},
            {"exponent", PropType::kFloat}},
           MakePhong},
          {"twosided", {{"bsdf", PropType::kObject}}, MakeTwoSided},
          {"bumpmap",
           {{"bsdf", PropType::kObject},
            {"arg", PropType::kSpectrumOrTexture},
            {"texture", PropType::kObject},
            {"scale", PropType::kFloat}},
           MakeBumpMap},
          {"normalmap", {{"bsdf", PropType::kObject}, {"normalmap", PropType::kSpectrumOrTexture}}, MakeNormalMap},
      });
  return registry;
}

std::shared_ptr<const Material> BuildMaterial(const ObjectNode& node, LoaderContext& ctx) {
  if (auto it = ctx.materials.find(&node); it != ctx.materials.end()) return it->second;
  std::shared_ptr<const Material> material = BuildBsdfNode(node, ctx);
  ctx.materials[&node] = material;
  return material;
}

}  // namespace objektiv
