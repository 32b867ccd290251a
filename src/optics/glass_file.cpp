#include "optics/glass_file.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <optional>
#include <sstream>

#include "base/error.h"
#include "base/log.h"
#include "base/text_file.h"

namespace objektiv {
namespace {

// Schott-formula slots in the order a table of n rows takes them: A0, A2 (l^-2), A1 (l^2),
// A3 (l^-4).
constexpr int kSlots[] = {0, 2, 1, 3};

double Basis(int slot, double l) {
  double l2 = l * l;
  switch (slot) {
    case 0: return 1;
    case 1: return l2;
    case 2: return 1 / l2;
    default: return 1 / (l2 * l2);
  }
}

// Solves the k x k system a x = b (partial pivoting); false when singular.
bool Solve(std::vector<std::vector<double>> a, std::vector<double> b, std::vector<double>& x) {
  const size_t k = b.size();
  for (size_t c = 0; c < k; ++c) {
    size_t p = c;
    for (size_t r = c + 1; r < k; ++r)
      if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
    if (!(std::abs(a[p][c]) > 1e-300)) return false;
    std::swap(a[p], a[c]);
    std::swap(b[p], b[c]);
    for (size_t r = c + 1; r < k; ++r) {
      double f = a[r][c] / a[c][c];
      for (size_t j = c; j < k; ++j) a[r][j] -= f * a[c][j];
      b[r] -= f * b[c];
    }
  }
  x.assign(k, 0);
  for (size_t c = k; c-- > 0;) {
    double s = b[c];
    for (size_t j = c + 1; j < k; ++j) s -= a[c][j] * x[j];
    x[c] = s / a[c][c];
  }
  return true;
}

// Rows "wavelength_um value" with the line each came from.
struct Rows {
  std::vector<std::pair<double, double>> values;
  std::vector<int> lines;

  void Add(double l, double v, int line) {
    values.emplace_back(l, v);
    lines.push_back(line);
  }
  // Throws, naming the second line, where a wavelength is given twice (sorted copy: a table of
  // a million rows is checked in n log n).
  void CheckDistinct(const std::string& path, const std::string& glass, const char* what) const {
    std::vector<size_t> order(values.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return values[a].first < values[b].first; });
    for (size_t k = 1; k < order.size(); ++k)
      if (values[order[k]].first == values[order[k - 1]].first)
        throw MakeInputError(path, lines[order[k]], "glass {}: the {} gives wavelength {} um twice (first on line {})",
                             glass, what, values[order[k]].first, lines[order[k - 1]]);
  }
};

// The glass being read: a value glass (nd/vd, n) or an index table, and its transmittance rows.
struct Pending {
  std::string name;
  int line = 0;
  std::optional<Glass> value;  // empty: an index table
  Rows index;
  double transmittance_mm = 0;  // the thickness the transmittance rows are for; 0: none given
  int transmittance_line = 0;
  Rows transmittance;
};

// The row a typing error most likely sits in, and how much the formula fitted to the other
// rows misses it: the row without which the others fit best (tables of 5 to 200 rows; a
// least-squares fit spreads one bad row's error over its neighbours, so the plain residuals
// point at several rows).
std::pair<size_t, double> WorstRowLeftOut(const Rows& rows) {
  size_t best = 0;
  double best_rest = INFINITY, best_miss = 0;
  for (size_t i = 0; i < rows.values.size(); ++i) {
    std::vector<std::pair<double, double>> others;
    for (size_t j = 0; j < rows.values.size(); ++j)
      if (j != i) others.push_back(rows.values[j]);
    Glass fit("", "", DispersionFormula::kSchott, FitSchottFormula(others));
    double rest = 0;
    for (const auto& [l, n] : others) rest = std::max(rest, std::abs(fit.Index(l * 1e3) - n));
    if (rest < best_rest) best = i, best_rest = rest, best_miss = fit.Index(rows.values[i].first * 1e3) - rows.values[i].second;
  }
  return {best, best_miss};
}

Glass TableGlass(const Pending& g, const std::string& path, const std::string& catalog) {
  if (g.index.values.size() < 2)
    throw MakeInputError(path, g.line, "glass {} needs an index table of 2 or more rows (wavelength_um index) or a value "
                                       "(nd=N vd=V, n=N)", g.name);
  g.index.CheckDistinct(path, g.name, "index table");
  Glass glass(g.name, catalog, DispersionFormula::kSchott, FitSchottFormula(g.index.values));
  double lo = g.index.values.front().first, hi = lo;
  for (const auto& [l, n] : g.index.values) lo = std::min(lo, l), hi = std::max(hi, l);
  glass.lambda_min_um = lo;
  glass.lambda_max_um = hi;
  // The renderer uses the formula over the visible (0.36 to 0.83 um) whatever the table covers:
  // there it must give an index from 1 to 5 that falls with the wavelength (normal dispersion),
  // and over the table's own range an index from 1 to 5.
  double previous = INFINITY;
  for (int k = 0; k <= 94; ++k) {
    const double um = 0.36 + 0.005 * k, n = glass.Index(um * 1e3);
    if (!(n >= 1 && n <= 5 && n <= previous + 1e-12))
      throw MakeInputError(path, g.line,
                           "glass {}: the dispersion formula fitted to its index table gives n {:.5g} at {:.3f} um{}: the "
                           "table must describe an index from 1 to 5 that falls with the wavelength across the visible "
                           "(0.36 to 0.83 um; it covers {} to {} um)",
                           g.name, n, um,
                           std::isfinite(previous) && n > previous ? fmt::format(", above {:.5g} just before", previous) : "",
                           lo, hi);
    previous = n;
  }
  for (int k = 0; k <= 100; ++k) {
    const double um = lo + (hi - lo) * k / 100, n = glass.Index(um * 1e3);
    if (!(n >= 1 && n <= 5))
      throw MakeInputError(path, g.line, "glass {}: the dispersion formula fitted to its index table gives n {:.5g} at "
                                         "{:.3f} um, inside the table's range", g.name, n, um);
  }
  if (lo > 0.4861327 || hi < 0.6562725)  // less than the F to C lines
    spdlog::warn("{}:{}: glass {}: its index table covers {} to {} um; the renderer extrapolates its formula across the "
                 "visible (0.36 to 0.83 um)", path, g.line, g.name, lo, hi);
  if (const double vd = glass.ComputedVd(); !(vd >= 10 && vd <= 120))
    spdlog::warn("{}:{}: glass {}: the index table gives an Abbe number Vd of {:.3g}, far from any optical material's "
                 "(10 to 120)", path, g.line, g.name, vd);
  // A typing error: with 5 to 200 rows, the row the others' fit misses (an error at the table's
  // edge is absorbed by a fit through it); otherwise the row the whole fit misses most.
  const size_t rows = g.index.values.size();
  const bool left_out = rows >= 5 && rows <= 200;
  double largest = 0;
  size_t at = 0;
  if (left_out) {
    std::tie(at, largest) = WorstRowLeftOut(g.index);
  } else {
    for (size_t i = 0; i < rows; ++i) {
      double miss = glass.Index(g.index.values[i].first * 1e3) - g.index.values[i].second;
      if (!(std::abs(miss) <= std::abs(largest))) largest = miss, at = i;
    }
  }
  if (!(std::abs(largest) <= 2e-4))
    spdlog::warn("{}:{}: glass {}: the dispersion formula fitted to the {} misses this row by {:.1e} (a typing error?)",
                 path, g.index.lines[at], g.name, left_out ? "other rows" : "table", largest);
  glass.catalog_nd = glass.ComputedNd();
  glass.catalog_vd = glass.ComputedVd();
  return glass;
}

void AddPending(GlassCatalog& into, const Pending& g, const std::string& path, const std::string& catalog) {
  Glass glass = g.value ? *g.value : TableGlass(g, path, catalog);
  if (g.transmittance_mm > 0) {
    if (g.transmittance.values.empty())
      throw MakeInputError(path, g.transmittance_line, "glass {}: a transmittance line needs rows 'wavelength_um "
                                                       "transmittance' after it", g.name);
    g.transmittance.CheckDistinct(path, g.name, "transmittance");
    for (const auto& [l, tau] : g.transmittance.values) glass.AddTransmission(l, tau, g.transmittance_mm);
  }
  if (!into.Add(catalog, std::move(glass))) throw MakeInputError(path, g.line, "glass {} is given twice", g.name);
}

}  // namespace

std::array<double, 10> FitSchottFormula(const std::vector<std::pair<double, double>>& rows) {
  const size_t k = std::min<size_t>(rows.size(), 4);
  std::vector<std::vector<double>> ata(k, std::vector<double>(k, 0));
  std::vector<double> atb(k, 0);
  for (const auto& [l, n] : rows)
    for (size_t i = 0; i < k; ++i) {
      double bi = Basis(kSlots[i], l);
      atb[i] += bi * n * n;
      for (size_t j = 0; j < k; ++j) ata[i][j] += bi * Basis(kSlots[j], l);
    }
  std::vector<double> x;
  std::array<double, 10> c{};
  if (!Solve(ata, atb, x)) return c;  // distinct wavelengths make the system regular
  for (size_t i = 0; i < k; ++i) c[kSlots[i]] = x[i];
  return c;
}

void LoadGlassFile(GlassCatalog& into, const std::string& path, const std::string& catalog) {
  ParseGlassFile(into, ReadTextFile(path, "glass file"), path, catalog);
}

void ParseGlassFile(GlassCatalog& into, const std::string& text, const std::string& path, const std::string& catalog) {
  std::istringstream lines(DecodeToAscii(text));
  std::string line;
  int number = 0;
  std::optional<Pending> pending;  // the glass whose rows are being read
  std::map<std::string, int> first_lines;  // glass key -> the line that names it
  auto finish = [&] {
    if (pending) AddPending(into, *pending, path, catalog);
    pending.reset();
  };
  while (std::getline(lines, line)) {
    ++number;
    if (size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::vector<std::string> f = SplitFields(line);
    if (f.empty()) continue;
    if (f[0] == "transmittance") {
      if (!pending)
        throw MakeInputError(path, number, "a transmittance line belongs after a glass line");
      if (pending->transmittance_mm > 0)
        throw MakeInputError(path, number, "glass {}: a second transmittance line (the first is on line {})",
                             pending->name, pending->transmittance_line);
      if (f.size() != 2)
        throw MakeInputError(path, number, "a transmittance line is 'transmittance THICKNESS_MM' (the rows that follow "
                                           "give the internal transmittance through that thickness)");
      double mm = ParseFiniteNumber(f[1], path, number);
      if (!(mm > 0 && mm <= 1000)) throw MakeInputError(path, number, "thickness {} mm is not above 0 (at most 1000)", mm);
      pending->transmittance_mm = mm;
      pending->transmittance_line = number;
      continue;
    }
    if (f[0] != "glass") {
      const bool transmittance_rows = pending && pending->transmittance_mm > 0;
      if (!pending || f.size() != 2 || (pending->value && !transmittance_rows))
        throw MakeInputError(path, number, "expected 'glass NAME nd=N vd=V', 'glass NAME n=N' or 'glass NAME' and "
                                           "its table rows 'wavelength_um index', or 'transmittance THICKNESS_MM' and "
                                           "its rows 'wavelength_um transmittance', got '{}'", Printable(f[0]));
      double l = ParseFiniteNumber(f[0], path, number), v = ParseFiniteNumber(f[1], path, number);
      if (!(l >= 0.2 && l <= 25))
        throw MakeInputError(path, number, "wavelength {} is not in micrometres (0.2 to 25)", l);
      if (transmittance_rows) {
        if (!(v > 0 && v <= 1))
          throw MakeInputError(path, number, "transmittance {} is not above 0 and at most 1 (an opaque band: a small "
                                             "value such as 1e-6)", v);
        pending->transmittance.Add(l, v, number);
      } else {
        if (!(v >= 1 && v <= 5)) throw MakeInputError(path, number, "index {} is not between 1 and 5", v);
        pending->index.Add(l, v, number);
      }
      continue;
    }
    finish();
    if (f.size() < 2) throw MakeInputError(path, number, "a glass line needs a name");
    const std::string& name = f[1];
    if (name.find_first_of(":=,") != std::string::npos || GlassKey(name) == "AIR")
      throw MakeInputError(path, number, "'{}' cannot name a glass (a lens file would read it as {})", Printable(name),
                           GlassKey(name) == "AIR" ? "air" : "a catalog, an index or a model glass");
    if (auto [first, added] = first_lines.emplace(GlassKey(name), number); !added)
      throw MakeInputError(path, number, "glass {} is given twice (first on line {})", name, first->second);
    pending = Pending{name, number, std::nullopt, {}, 0, 0, {}};
    std::vector<std::string> values(f.begin() + 2, f.end());
    if (values.size() == 1 && values[0].find(",vd=") != std::string::npos) {  // nd=N,vd=V as in a lens file
      std::string v = values[0];
      values = {v.substr(0, v.find(',')), v.substr(v.find(',') + 1)};
    }
    auto value = [&](const std::string& field, const char* key) -> std::optional<double> {
      std::string k = std::string(key) + "=";
      if (field.rfind(k, 0) != 0) return std::nullopt;
      return ParseFiniteNumber(field.substr(k.size()), path, number);
    };
    if (values.empty()) continue;  // an index table follows
    if (values.size() == 1 && value(values[0], "n")) {
      double n = *value(values[0], "n");
      if (!(n >= 1 && n <= 5)) throw MakeInputError(path, number, "index {} is not between 1 and 5", n);
      pending->value = Glass::Constant(n).Named(name, catalog);
    } else if (values.size() == 2 && value(values[0], "nd") && value(values[1], "vd")) {
      double nd = *value(values[0], "nd"), vd = *value(values[1], "vd");
      if (!(nd >= 1 && nd <= 5) || !(vd > 0 && vd <= 200))
        throw MakeInputError(path, number, "glass {} needs nd from 1 to 5 and vd above 0 (at most 200), got nd {} vd {}",
                             name, nd, vd);
      pending->value = Glass::Model(nd, vd).Named(name, catalog);
    } else {
      throw MakeInputError(path, number, "glass {}: expected nd=N vd=V, n=N, or nothing (a table follows)", name);
    }
  }
  finish();
  if (first_lines.empty()) spdlog::warn("{}: no glass in this glass file", path);
}

}  // namespace objektiv
