#include "optics/glass_catalog.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "base/error.h"
#include "base/log.h"
#include "base/text_file.h"

namespace objektiv {
std::string GlassKey(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = char(std::toupper(static_cast<unsigned char>(c)));
  return r;
}

void GlassCatalog::LoadAgf(const std::string& path, const std::string& name) {
  LoadAgfText(ReadTextFile(path, "glass catalog"), path, name);
}

void GlassCatalog::LoadAgfText(const std::string& raw, const std::string& path, const std::string& catalog) {
  std::string text = DecodeToAscii(raw);
  const std::string key = GlassKey(catalog);
  auto& table = glasses_[key];
  if (std::find(order_.begin(), order_.end(), key) == order_.end()) order_.push_back(key);
  Glass* current = nullptr;
  int current_line = 0;
  size_t count = 0;
  // A glass whose formula disagrees with its own NM line's nd (a CD line of zeros, none at all,
  // a wrong formula number) would be a silently wrong lens: checked where its lines end. Glasses
  // whose formula is not valid at the d line (infrared materials) or whose nd is not given are
  // left alone.
  auto check_current = [&] {
    if (!current || current->catalog_nd <= 0) return;
    if (current->lambda_max_um > 0 && !(current->lambda_min_um <= 0.5875618 && current->lambda_max_um >= 0.5875618))
      return;
    const double nd = current->ComputedNd();
    if (!(std::abs(nd - current->catalog_nd) <= 1e-3))
      throw MakeInputError(path, current_line,
                           "glass {}: its dispersion formula gives nd {:.6g}, its NM line says {} (the CD coefficients "
                           "or the formula number are wrong)", current->name(), nd, current->catalog_nd);
    // Nor a pole or a negative square inside the visible part of its range.
    const double lo = std::max(0.36, current->lambda_max_um > 0 ? current->lambda_min_um : 0.0);
    const double hi = std::min(0.83, current->lambda_max_um > 0 ? current->lambda_max_um : 1.0);
    for (int k = 0; k <= 47 && lo < hi; ++k) {
      const double um = lo + (hi - lo) * k / 47, n = current->Index(um * 1e3);
      if (!(n >= 1 && n <= 5))
        throw MakeInputError(path, current_line, "glass {}: its dispersion formula gives n {:.6g} at {:.3f} um",
                             current->name(), n, um);
    }
  };
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    std::vector<std::string> f = SplitFields(line);
    if (f.empty()) continue;
    const std::string type = f.front();
    f.erase(f.begin());
    if (type == "NM") {
      // NM name formula MIL nd vd [exclude status melt]
      if (f.size() < 5) throw MakeInputError(path, number, "NM line needs name, formula, MIL, nd and vd");
      std::optional<int> formula_number = ParseIntegerIn(f[1], 0, 1000);
      auto formula = formula_number ? DispersionFormulaFromNumber(*formula_number) : std::nullopt;
      if (!formula)
        throw MakeInputError(path, number, "glass {}: unknown dispersion formula {}", f[0], f[1]);
      auto glass = std::make_unique<Glass>(f[0], catalog, *formula, std::array<double, 10>{});
      glass->catalog_nd = ParseFiniteNumber(f[3], path, number);
      glass->catalog_vd = ParseFiniteNumber(f[4], path, number);
      std::string glass_key = GlassKey(f[0]);
      if (table.count(glass_key)) throw MakeInputError(path, number, "glass {} is listed twice", f[0]);
      check_current();
      current = glass.get();
      current_line = number;
      ++count;
      table[glass_key] = std::move(glass);
    } else if (type == "CD" || type == "LD" || type == "IT") {
      if (!current) throw MakeInputError(path, number, "{} line before any NM line", type);
      if (type == "CD") {
        if (f.empty() || f.size() > 10) throw MakeInputError(path, number, "CD line needs 1 to 10 coefficients");
        std::array<double, 10> c{};
        for (size_t i = 0; i < f.size(); ++i) c[i] = ParseFiniteNumber(f[i], path, number);
        current->SetCoefficients(c);
      } else if (type == "LD") {
        if (f.size() < 2) throw MakeInputError(path, number, "LD line needs a minimum and a maximum wavelength");
        current->lambda_min_um = ParseFiniteNumber(f[0], path, number);
        current->lambda_max_um = ParseFiniteNumber(f[1], path, number);
        if (!(current->lambda_min_um < current->lambda_max_um))
          throw MakeInputError(path, number, "LD range is empty");
      } else {
        if (f.size() < 3) throw MakeInputError(path, number, "IT line needs wavelength, transmittance and thickness");
        double l = ParseFiniteNumber(f[0], path, number), tau = ParseFiniteNumber(f[1], path, number);
        double d = ParseFiniteNumber(f[2], path, number);
        // Implausible rows occur in real catalogs (HIKARI lists transmittances of 12 and
        // 1.959): one bad optional row should not make a catalog unusable. Skip it and say so
        // in the debug log (the shipped catalogs would otherwise warn on every run).
        if (!(l > 0) || tau < 0 || tau > 1.0001 || !(d > 0)) {
          spdlog::debug("{}:{}: glass {}: ignoring transmission row (wavelength {} um, transmittance {}, thickness {} mm)",
                       path, number, current->name(), l, tau, d);
          continue;
        }
        current->AddTransmission(l, std::min(tau, 1.0), d);
      }
    }
    // Other line types (CC, GC, ED, TD, OD, BD, ...) carry nothing the renderer uses.
  }
  check_current();
  if (count == 0) throw MakeInputError(path, 0, "no glass in this catalog (no NM line): not an AGF file?");
}

std::string DataDirectory() {
  if (const char* env = std::getenv("OBJEKTIV_DATA_DIR"); env && *env) return env;
  return OBJEKTIV_BUILTIN_DATA_DIR;
}

const GlassCatalog& GlassCatalog::Default() {
  static const GlassCatalog catalog = [] {
    GlassCatalog c;
    for (const char* name : {"SCHOTT", "OHARA", "HOYA", "CDGM", "SUMITA", "HIKARI", "CRYSTALS"})
      c.LoadAgf(DataDirectory() + "/glass/" + name + ".AGF", name);
    return c;
  }();
  return catalog;
}

const Glass* GlassCatalog::Find(std::string_view name) const {
  size_t colon = name.find(':');
  if (colon != std::string_view::npos) return FindIn(name.substr(0, colon), name.substr(colon + 1));
  for (const std::string& cat : order_)
    if (const Glass* g = FindIn(cat, name)) return g;
  return nullptr;
}

const Glass* GlassCatalog::FindIn(std::string_view catalog, std::string_view name) const {
  auto it = glasses_.find(GlassKey(catalog));
  if (it == glasses_.end()) return nullptr;
  auto g = it->second.find(GlassKey(name));
  return g == it->second.end() ? nullptr : g->second.get();
}

bool GlassCatalog::HasCatalog(std::string_view catalog) const { return glasses_.count(GlassKey(catalog)) > 0; }

bool GlassCatalog::Add(const std::string& catalog, Glass glass) {
  std::string key = GlassKey(catalog);
  auto& table = glasses_[key];
  if (std::find(order_.begin(), order_.end(), key) == order_.end()) order_.push_back(key);
  std::string glass_key = GlassKey(glass.name());
  return table.emplace(std::move(glass_key), std::make_unique<Glass>(std::move(glass))).second;
}

std::vector<const Glass*> GlassCatalog::All() const {
  std::vector<const Glass*> all;
  for (const std::string& cat : order_)
    for (const auto& [key, g] : glasses_.at(cat)) all.push_back(g.get());
  return all;
}

}  // namespace objektiv
