// The glasses one lens file can name (glass_lookup.h), gathered from beside the file: its glass
// file (LENS.glass beside LENS.zmx or LENS.lens, glass_file.h) and an AGF catalog for each
// catalog it names (Zemax's GCAT line) that is not shipped, or that the user wants to replace
// (NAME.AGF, any case, beside the lens). A named catalog found in neither place is warned about.
#pragma once
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "optics/glass_lookup.h"

namespace objektiv {

struct NamedCatalog {
  std::string name;
  int line = 0;  // where the lens file names it
};

class LensGlasses {
 public:
  LensGlasses(const std::string& lens_path, const GlassCatalog& shipped, const std::vector<NamedCatalog>& named = {});
  const GlassLookup& lookup() const { return lookup_; }
  // lookup().Find, with a glass other than the name written (glass_lookup.h: SubstitutionNote)
  // warned about once per name, at its first `line` in the lens file.
  std::optional<GlassMatch> Find(std::string_view name, int line, std::optional<StatedGlass> stated = std::nullopt) const;
  // Warns, naming the glass file, about its glasses that no surface used.
  void WarnUnused() const;

 private:
  GlassLookup lookup_;
  std::string lens_path_;
  std::string glass_file_;  // empty when the lens has none
  mutable std::set<std::string> noted_;
};

}  // namespace objektiv
