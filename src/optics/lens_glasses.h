// The glasses one lens file can name (glass_lookup.h), gathered from beside the file: its glass
// file (LENS.glass beside LENS.zmx or LENS.lens, glass_file.h) and an AGF catalog for each
// catalog it names (Zemax's GCAT line) that is not shipped, or that the user wants to replace
// (NAME.AGF, any case, beside the lens). A named catalog found in neither place is warned about
// (a dated name, SUMITA_AUG2011, is read as the shipped SUMITA); a file of those names that is
// not a regular file, or two files naming one catalog, is an error.
//
// Resolve turns a name into the lens's glass, with the lens readers' common diagnostics.
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

  // The glass `name` written on `line` means, whose nd and Vd the file may state. A glass other
  // than the name written (glass_lookup.h: SubstitutionNote) is warned about once per name; a
  // found glass that disagrees with the stated values is warned about, or is an error where it
  // is clearly another material (nd off by more than 0.01 or Vd by more than 5); a name found
  // nowhere is an error saying how to supply the glass (with the nearest shipped glasses to the
  // stated values).
  std::shared_ptr<const Glass> Resolve(const std::string& name, int line,
                                       std::optional<StatedGlass> stated = std::nullopt) const;
  // Warns, naming the glass file, about its glasses that no surface used.
  void WarnUnused() const;

 private:
  GlassLookup lookup_;
  std::string lens_path_;
  std::string glass_file_;  // empty when the lens has none
  mutable std::set<std::string> noted_;
};

}  // namespace objektiv
