#include "optics/coating_library.h"

#include <algorithm>
#include <cctype>

#include "base/error.h"
#include "base/text_file.h"

namespace objektiv {

namespace {

}  // namespace

bool SameCoatingName(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

namespace {
bool SameName(std::string_view a, std::string_view b) { return SameCoatingName(a, b); }

struct Material {
  const char* name;
  std::shared_ptr<const Glass> glass;
};

const std::vector<Material>& Materials() {
  static const std::vector<Material> materials = [] {
    auto named = [](const char* name, const Glass& g) {
      return Material{name, std::make_shared<const Glass>(g.Named(name, "COATING"))};
    };
    auto square = [](double x) { return x * x; };
    return std::vector<Material>{
        named("MgF2", Glass::Sellmeier({0.48755108, 0.39875031, 2.3120353},
                                       {square(0.04338408), square(0.09461442), square(23.793604)})),
        named("SiO2", Glass::Sellmeier({0.6961663, 0.4079426, 0.8974794},
                                       {square(0.0684043), square(0.1162414), square(9.896161)})),
        named("Al2O3", Glass::Constant(1.62)), named("ZrO2", Glass::Constant(2.05)),
        named("Ta2O5", Glass::Constant(2.10)), named("TiO2", Glass::Constant(2.35))};
  }();
  return materials;
}

// "NAME" or "NAME@NM" (a design wavelength from 200 to 2000 nm): the wavelength, 550 without
// one. Throws InputError for NAME@ and something else.
std::optional<double> DesignSuffix(std::string_view name, std::string_view base) {
  if (name.size() < base.size() || !SameName(name.substr(0, base.size()), base)) return std::nullopt;
  if (name.size() == base.size()) return 550.0;
  if (name[base.size()] != '@') return std::nullopt;
  std::optional<double> nm = ParseFiniteNumber(std::string(name.substr(base.size() + 1)));
  if (!nm || *nm < 200 || *nm > 2000)
    throw InputError(fmt::format("coating '{}': the design wavelength after @ is a number of nm from 200 to 2000", name));
  return nm;
}

}  // namespace

std::shared_ptr<const Glass> FindCoatingMaterial(std::string_view name) {
  for (const Material& m : Materials())
    if (SameName(name, m.name)) return m.glass;
  return nullptr;
}

std::string CoatingMaterialNames() {
  std::string names;
  for (const Material& m : Materials()) {
    if (!names.empty()) names += ", ";
    names += m.name;
  }
  return names;
}

std::optional<std::shared_ptr<const Coating>> FindBuiltInCoating(std::string_view name) {
  if (SameName(name, "none") || SameName(name, "uncoated")) return std::shared_ptr<const Coating>();
  const std::string text(name);
  if (std::optional<double> nm = DesignSuffix(name, "MgF2"))
    return std::make_shared<const Coating>(text, *nm, std::vector<Coating::Layer>{{FindCoatingMaterial("MgF2"), 0, 0.25}});
  if (std::optional<double> nm = DesignSuffix(name, "multi"))
    return std::make_shared<const Coating>(
        text, *nm,
        std::vector<Coating::Layer>{
            {FindCoatingMaterial("MgF2"), 0, 0.25}, {FindCoatingMaterial("ZrO2"), 0, 0.5}, {nullptr, 0, 0.25}});
  // Zemax's I.xx: the digits after the point are the transmittance's.
  if (name.size() > 2 && (name[0] == 'I' || name[0] == 'i') && name[1] == '.' &&
      std::all_of(name.begin() + 2, name.end(), ::isdigit) && name.size() <= 12) {
    double t = std::stod("0" + text.substr(1));
    if (!(t > 0)) throw InputError(fmt::format("coating '{}': an ideal coating's transmittance must be above 0 (I.95)", name));
    return std::make_shared<const Coating>(Coating::Ideal(text, t));
  }
  return std::nullopt;
}

std::shared_ptr<const Coating> CoatingForLens(std::string_view name, const LensPrescription& lens) {
  if (auto c = FindBuiltInCoating(name)) return *c;
  for (const std::shared_ptr<const Coating>& c : lens.defined_coatings)
    if (SameName(c->name(), name)) return c;
  for (const LensSurface& s : lens.surfaces)
    if (s.coating && SameName(s.coating->name(), name)) return s.coating;
  throw InputError(fmt::format("unknown coating '{}' (built in: {}, NM a design wavelength in 200..2000 nm and xx a "
                               "transmittance above 0; or one the lens file defines)",
                               name, BuiltInCoatingNames()));
}

void Recoat(LensPrescription& lens, const std::shared_ptr<const Coating>& coating) {
  if (coating) {
    CoatAirGlassSurfaces(lens, coating, false);
    if (auto mismatch = FirstCoatingMismatch(lens))
      throw InputError(fmt::format("lens surface {}: {}", mismatch->first + 1, mismatch->second));
  } else {
    for (LensSurface& s : lens.surfaces) s.coating = nullptr;
  }
}

std::string BuiltInCoatingNames() { return "none, MgF2[@NM], multi[@NM], I.xx"; }

std::shared_ptr<const Coating> ParseCoatingDefinition(const std::string& name, std::span<const std::string> fields,
                                                      const GlassCatalog& glasses, const std::string& path, int line) {
  double design = 550;
  bool design_given = false;
  std::vector<Coating::Layer> layers;
  for (const std::string& f : fields) {
    if (f.rfind("design=", 0) == 0) {
      if (!layers.empty()) throw MakeInputError(path, line, "design= comes before the layers");
      if (design_given) throw MakeInputError(path, line, "design= is given twice");
      design_given = true;
      design = ParseFiniteNumber(f.substr(7), path, line);
      if (design < 200 || design > 2000) throw MakeInputError(path, line, "design wavelength {} nm is outside 200..2000 nm", design);
      continue;
    }
    const size_t colon = f.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == f.size())
      throw MakeInputError(path, line, "a layer is MATERIAL:THICKNESS (MgF2:0.25, SiO2:98nm), got '{}'", f);
    const std::string material = f.substr(0, colon), thickness = f.substr(colon + 1);
    Coating::Layer layer;
    if (SameName(material, "matched")) {
      layer.material = nullptr;
    } else if (material.rfind("n=", 0) == 0) {
      double n = ParseFiniteNumber(material.substr(2), path, line);
      if (n < 1 || n > 10) throw MakeInputError(path, line, "layer index {} is outside 1..10", n);
      layer.material = std::make_shared<const Glass>(Glass::Constant(n));
    } else if (auto coating_material = FindCoatingMaterial(material)) {
      layer.material = coating_material;
    } else if (const Glass* g = glasses.Find(material)) {
      layer.material = std::shared_ptr<const Glass>(std::shared_ptr<const Glass>(), g);  // catalogs outlive lenses
    } else {
      throw MakeInputError(path, line, "unknown layer material '{}' ({}, matched, a catalog glass or n=INDEX)", material,
                           CoatingMaterialNames());
    }
    const bool physical = thickness.size() > 2 && thickness.substr(thickness.size() - 2) == "nm";
    const double value = ParseFiniteNumber(physical ? thickness.substr(0, thickness.size() - 2) : thickness, path, line);
    if (!(value > 0) || value > (physical ? 1e5 : 100))
      throw MakeInputError(path, line, "layer thickness '{}' must be positive and at most {}", thickness,
                           physical ? "100000nm" : "100 waves");
    (physical ? layer.thickness_nm : layer.waves) = value;
    layers.push_back(std::move(layer));
  }
  if (layers.empty()) throw MakeInputError(path, line, "coating '{}' has no layers", name);
  try {
    return std::make_shared<const Coating>(name, design, std::move(layers));
  } catch (const std::invalid_argument& e) {
    throw MakeInputError(path, line, "coating '{}': {}", name, e.what());
  }
}

}  // namespace objektiv
