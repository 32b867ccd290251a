// Other names of catalog glasses: withdrawn names and their successors, as lens designers read
// old prescriptions, and the generic names of crystalline and fused materials.
//
// Glass makers replaced their lead- and arsenic-bearing glasses in the 1990s by "eco" glasses
// of (nearly) the same nd and Vd under a prefixed name: Schott's BK7 became N-BK7, Ohara's
// BSL7 S-BSL7, Hoya's FD7 E-FD7, CDGM's ZF52 H-ZF52. Schott's older "N" infix names (LaKN22,
// LaSFN9, SSKN8) became N-LAK22, N-LASF9, N-SSK8, and SF56A became N-SF56. Patents and old
// Zemax files still write the withdrawn names; the shipped catalogs list only what the makers
// sell (and a few obsolete glasses still in their data).
//
// SuccessorCandidates gives the names a withdrawn `name` may have now in `catalog`, most
// likely first; a caller takes the first that the catalog lists and says so in the log
// (the successor's nd and Vd differ from the old glass's in the third or fourth decimal).
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace objektiv {

// `catalog` and `name` in upper case ("SCHOTT", "LAKN22"); empty where the catalog's maker
// has no renaming rule here (SUMITA, HIKARI) or the name is already a successor's.
std::vector<std::string> SuccessorCandidates(std::string_view catalog, std::string_view name);

// Zemax's MISC names for materials that the shipped catalogs hold under a maker's name:
// SILICA (Malitson's fused silica; SCHOTT LITHOSIL-Q agrees to 2e-5 in nd) and CAF2 (SCHOTT
// LITHOTEC-CAF2). The catalog and glass, upper case; empty for other names.
struct CatalogGlassName {
  std::string catalog, glass;
};
std::optional<CatalogGlassName> SameMaterial(std::string_view name);

}  // namespace objektiv
