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
//   transmittance 2                   optional, after any glass: rows "wavelength_um
//   0.40 0.95                         transmittance" through 2 mm (a filter's curve)
//
// A table becomes Schott's formula n^2 = A0 + A1 l^2 + A2 l^-2 + A3 l^-4 (l in micrometres)
// fitted by least squares: 2 rows take A0 and A2 (Cauchy's form), 3 rows add A1, 4 or more
// all four. The formula must give an index from 1 to 5 falling with the wavelength across the
// visible (0.36-0.83 um, where the renderer evaluates it): an error otherwise. A row the fit
// misses by more than 2e-4 (a typing error) is warned about by line (with 5 to 200 rows, the
// row the other rows' fit misses); a table narrower than F to C, and a Vd outside 10-120, are
// warned about. Names compare without case, must be unique in the file, and cannot be ones a
// lens file reads otherwise (air, or with ':', '=' or ',').
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
