// Which glass a name in a lens file means, as lens designers expect.
//
// The names are searched in groups, in this order:
//   1. the glasses the user gives in a glass file beside the lens (glass_file.h: LENS.glass
//      for LENS.zmx or LENS.lens);
//   2. the catalogs the lens file names (Zemax's GCAT line), in its order: a shipped catalog,
//      or an AGF file of that name beside the lens (Zemax's glasscat folder);
//   3. every other shipped catalog, in the shipped order (SCHOTT, OHARA, HOYA, CDGM, SUMITA,
//      HIKARI, CRYSTALS).
// In each group the exact name first; where several catalogs of the group list it (CDGM's F2
// is not Schott's F2) and the file gives the glass's nd and Vd, the first that agrees with
// them (nd within 0.001, Vd within 0.5), else one of that name in a later group that agrees,
// else the first. Then a withdrawn name's successor
// (glass_aliases.h: BK7 -> SCHOTT N-BK7), which the caller notes in the log. A name in no
// group is the caller's error: never a guess. "CATALOG:NAME" searches that catalog only.
#pragma once
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "optics/glass_catalog.h"

namespace objektiv {

// A glass's nd and Vd as a lens file states them (Zemax's GLAS line).
struct StatedGlass {
  double nd = 0, vd = 0;
};
// Whether `g`'s nd and Vd are within 0.001 and 0.5 of the stated ones.
bool AgreesWith(const Glass& g, const StatedGlass& stated);

struct GlassMatch {
  // Shares ownership of the catalog a lens file brought (shipped glasses live as long as the
  // program and are not owned).
  std::shared_ptr<const Glass> glass;
  // kAgreesWithStated: the search order's glass of that name disagrees with the nd and Vd the
  // file states, and this one, of that name in a later group, agrees.
  enum class How { kExactName, kSuccessor, kSameMaterial, kAgreesWithStated } how = How::kExactName;
};
// What a lens reader logs where the glass found is not the name written: "glass BK7 is
// withdrawn; its successor SCHOTT:N-BK7 is used"; empty for an exact name.
std::string SubstitutionNote(std::string_view written, const GlassMatch& match);

class GlassLookup {
 public:
  explicit GlassLookup(const GlassCatalog& shipped) : shipped_(shipped) {}

  // Glasses from the user's glass file (group 1), named `label` (the file's name) in messages.
  void SetUserGlasses(std::shared_ptr<const GlassCatalog> user, std::string label);
  // The catalogs a lens file names (group 2): shipped ones by name, or catalogs of `beside`
  // (AGF files beside the lens). Names neither holds are skipped (the caller warns).
  void Prefer(const std::vector<std::string>& catalogs, std::shared_ptr<const GlassCatalog> beside);

  std::optional<GlassMatch> Find(std::string_view name, std::optional<StatedGlass> stated = std::nullopt) const;

  // The glasses of the user's glass file that no Find returned (to warn about).
  std::vector<std::string> UnusedUserGlasses() const;
  const GlassCatalog& shipped() const { return shipped_; }
  // The shipped catalogs and those beside the lens, for messages: "SCHOTT, OHARA, ...".
  std::string SearchedCatalogs() const;

 private:
  struct Source {
    const GlassCatalog* catalogs;
    std::string name;
    std::shared_ptr<const GlassCatalog> owner;  // null for the shipped set
  };
  std::optional<GlassMatch> FindInGroup(const std::vector<Source>& group, const std::string& name,
                                        const std::optional<StatedGlass>& stated) const;
  std::vector<std::vector<Source>> Groups() const;

  const GlassCatalog& shipped_;
  std::vector<Source> user_, preferred_;
  std::string user_label_;
  mutable std::set<const Glass*> used_;
};

}  // namespace objektiv
