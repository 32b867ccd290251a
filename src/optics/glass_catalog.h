// Glass catalogs in the Zemax AGF text format, and lookup of glasses by name.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "optics/glass.h"

namespace objektiv {

class GlassCatalog {
 public:
  // Reads an AGF file (ASCII or UTF-16) as catalog `name`. Lines of types this reader does
  // not use are skipped; malformed lines are an InputError naming the file and line.
  void LoadAgf(const std::string& path, const std::string& name);
  // The same from text (for tests).
  void LoadAgfText(const std::string& text, const std::string& path, const std::string& name);

  // The catalogs shipped in data/glass, in lookup order: SCHOTT, OHARA, HOYA, CDGM, SUMITA,
  // HIKARI, CRYSTALS (birefringent crystals' two indices, optics/uniaxial_crystal.h). The data folder is OBJEKTIV_DATA_DIR (environment) or the one built in.
  static const GlassCatalog& Default();

  // "N-BK7" (case-insensitive; catalogs searched in load order) or "OHARA:S-BSL7".
  const Glass* Find(std::string_view name) const;
  // `name` in catalog `catalog` only (both case-insensitive); null when either is absent.
  const Glass* FindIn(std::string_view catalog, std::string_view name) const;
  bool HasCatalog(std::string_view catalog) const;
  // Adds `glass` to `catalog` (created at the end of the lookup order when new); false, and
  // nothing added, when the catalog already holds a glass of that name.
  bool Add(const std::string& catalog, Glass glass);
  std::vector<const Glass*> All() const;
  const std::vector<std::string>& catalogs() const { return order_; }

 private:
  std::vector<std::string> order_;
  // catalog -> upper-case glass name -> glass
  std::map<std::string, std::map<std::string, std::unique_ptr<Glass>>> glasses_;
};

// How catalogs compare glass and catalog names: upper case.
std::string GlassKey(std::string_view name);

// Folder of the shipped data (glass catalogs, lenses).
std::string DataDirectory();

}  // namespace objektiv
