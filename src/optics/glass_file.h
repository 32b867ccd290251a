// A small glass file beside a lens: the glasses a prescription names that no shipped catalog
// holds (a vendor's B270 or D-ZK3M), given by the user rather than guessed.
//
//   # comment
//   glass B270 nd=1.5230 vd=58.5      a model glass through nd and Vd (Glass::Model)
//   glass SAPPHIRE n=1.768            a constant index
//   glass D-ZK3M                      an index table: rows "wavelength_um index" follow
//   0.4861327 1.5963
//   0.5875618 1.5891
//   0.6562725 1.5865
//
// A table becomes Schott's formula n^2 = A0 + A1 l^2 + A2 l^-2 + A3 l^-4 (l in micrometres)
// fitted by least squares: 2 rows take A0 and A2 (Cauchy's form), 3 rows add A1, 4 or more
// all four. A row the fit misses by more than 2e-4 (a typing error, or data no smooth formula
// follows) is warned about by line; the formula is valid between the table's first and last
// wavelength. Names compare without case and must be unique in the file.
#pragma once
#include <string>

#include "optics/glass_catalog.h"

namespace objektiv {

// The glasses of the glass file at `path` (or of `text`, for tests), as catalog `catalog`.
// Errors name the file and line.
void LoadGlassFile(GlassCatalog& into, const std::string& path, const std::string& catalog);
void ParseGlassFile(GlassCatalog& into, const std::string& text, const std::string& path, const std::string& catalog);

// The Schott-formula coefficients (10 slots, the unused ones 0) through index rows
// (wavelength in um, index): the fit described above. Rows must number 2 or more, at distinct
// wavelengths.
std::array<double, 10> FitSchottFormula(const std::vector<std::pair<double, double>>& rows);

}  // namespace objektiv
