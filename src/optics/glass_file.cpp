#include "optics/glass_file.h"

#include <cmath>
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

struct Table {
  std::string name;
  int line = 0;
  std::vector<std::pair<double, double>> rows;  // (um, index)
  std::vector<int> row_lines;
};

void AddTable(GlassCatalog& into, const Table& t, const std::string& path, const std::string& catalog) {
  if (t.rows.size() < 2)
    throw MakeInputError(path, t.line, "glass {} needs an index table of 2 or more rows (wavelength_um index) or a value "
                                       "(nd=N vd=V, n=N)", t.name);
  for (size_t i = 0; i < t.rows.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (t.rows[i].first == t.rows[j].first)
        throw MakeInputError(path, t.row_lines[i], "glass {}: wavelength {} um is given twice (first on line {})", t.name,
                             t.rows[i].first, t.row_lines[j]);
  std::array<double, 10> c = FitSchottFormula(t.rows);
  Glass g(t.name, catalog, DispersionFormula::kSchott, c);
  double lo = t.rows.front().first, hi = lo;
  for (const auto& [l, n] : t.rows) lo = std::min(lo, l), hi = std::max(hi, l);
  g.lambda_min_um = lo;
  g.lambda_max_um = hi;
  for (size_t i = 0; i < t.rows.size(); ++i) {
    double miss = g.Index(t.rows[i].first * 1e3) - t.rows[i].second;
    if (!(std::abs(miss) <= 2e-4))
      spdlog::warn("{}:{}: glass {}: the dispersion formula fitted to the table misses this row by {:.1e} (a typing "
                   "error?)", path, t.row_lines[i], t.name, miss);
  }
  g.catalog_nd = g.ComputedNd();
  g.catalog_vd = g.ComputedVd();
  if (!into.Add(catalog, std::move(g))) throw MakeInputError(path, t.line, "glass {} is given twice", t.name);
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
  std::optional<Table> table;  // the glass whose rows are being read
  auto finish = [&] {
    if (table) AddTable(into, *table, path, catalog);
    table.reset();
  };
  while (std::getline(lines, line)) {
    ++number;
    if (size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::vector<std::string> f = SplitFields(line);
    if (f.empty()) continue;
    if (f[0] != "glass") {
      if (!table || f.size() != 2)
        throw MakeInputError(path, number, "expected 'glass NAME nd=N vd=V', 'glass NAME n=N' or 'glass NAME' and "
                                           "its table rows 'wavelength_um index', got '{}'", f[0]);
      double l = ParseFiniteNumber(f[0], path, number), n = ParseFiniteNumber(f[1], path, number);
      if (!(l >= 0.2 && l <= 25))
        throw MakeInputError(path, number, "wavelength {} is not in micrometres (0.2 to 25)", l);
      if (!(n >= 1 && n <= 5)) throw MakeInputError(path, number, "index {} is not between 1 and 5", n);
      table->rows.emplace_back(l, n);
      table->row_lines.push_back(number);
      continue;
    }
    finish();
    if (f.size() < 2) throw MakeInputError(path, number, "a glass line needs a name");
    const std::string& name = f[1];
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
    std::optional<Glass> g;
    if (values.empty()) {
      table = Table{name, number, {}, {}};
      continue;
    } else if (values.size() == 1 && value(values[0], "n")) {
      double n = *value(values[0], "n");
      if (!(n >= 1 && n <= 5)) throw MakeInputError(path, number, "index {} is not between 1 and 5", n);
      g = Glass::Constant(n).Named(name, catalog);
    } else if (values.size() == 2 && value(values[0], "nd") && value(values[1], "vd")) {
      double nd = *value(values[0], "nd"), vd = *value(values[1], "vd");
      if (!(nd >= 1 && nd <= 5) || !(vd > 0 && vd <= 200))
        throw MakeInputError(path, number, "glass {} needs nd from 1 to 5 and vd above 0 (at most 200), got nd {} vd {}",
                             name, nd, vd);
      g = Glass::Model(nd, vd).Named(name, catalog);
    } else {
      throw MakeInputError(path, number, "glass {}: expected nd=N vd=V, n=N, or nothing (a table follows)", name);
    }
    if (!into.Add(catalog, std::move(*g))) throw MakeInputError(path, number, "glass {} is given twice", name);
  }
  finish();
}

}  // namespace objektiv
