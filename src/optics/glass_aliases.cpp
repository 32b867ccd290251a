#include "optics/glass_aliases.h"

#include <cctype>

namespace objektiv {
namespace {

struct EcoPrefix {
  const char* catalog;
  const char* prefix;
};
// The prefix each maker gave its lead- and arsenic-free successors.
constexpr EcoPrefix kEcoPrefixes[] = {{"SCHOTT", "N-"}, {"OHARA", "S-"}, {"HOYA", "E-"}, {"CDGM", "H-"}};

// Schott names that changed beyond the prefix.
struct Renamed {
  const char* old_name;
  const char* successor;
};
constexpr Renamed kSchottRenamed[] = {{"SF56A", "N-SF56"}};

// Schott's "N" infix (LAKN22, LASFN9, SSKN8, KZFSN4): the family letters, an N, then the
// number. The successor drops the infix: N-LAK22.
std::string WithoutSchottInfix(std::string_view name) {
  size_t digit = 0;
  while (digit < name.size() && std::isalpha(static_cast<unsigned char>(name[digit]))) ++digit;
  if (digit < 2 || digit == name.size() || name[digit - 1] != 'N' ||
      !std::isdigit(static_cast<unsigned char>(name[digit])))
    return {};
  return std::string(name.substr(0, digit - 1)) + std::string(name.substr(digit));
}

struct Material {
  const char* name;
  const char* catalog;
  const char* glass;
};
constexpr Material kMaterials[] = {{"SILICA", "SCHOTT", "LITHOSIL-Q"},     {"F_SILICA", "SCHOTT", "LITHOSIL-Q"},
                                   {"FUSED_SILICA", "SCHOTT", "LITHOSIL-Q"}, {"FUSEDSILICA", "SCHOTT", "LITHOSIL-Q"},
                                   {"CAF2", "SCHOTT", "LITHOTEC-CAF2"}};

}  // namespace

std::optional<CatalogGlassName> SameMaterial(std::string_view name) {
  for (const Material& m : kMaterials)
    if (name == m.name) return CatalogGlassName{m.catalog, m.glass};
  return std::nullopt;
}

std::vector<std::string> SuccessorCandidates(std::string_view catalog, std::string_view name) {
  std::vector<std::string> out;
  for (const EcoPrefix& e : kEcoPrefixes) {
    if (catalog != e.catalog) continue;
    std::string_view prefix = e.prefix;
    if (name.substr(0, prefix.size()) == prefix) return out;  // already an eco glass's name
    out.push_back(std::string(prefix) + std::string(name));
    if (catalog == "SCHOTT") {
      for (const Renamed& r : kSchottRenamed)
        if (name == r.old_name) out.insert(out.begin(), r.successor);
      if (std::string plain = WithoutSchottInfix(name); !plain.empty()) out.push_back("N-" + plain);
    }
  }
  return out;
}

}  // namespace objektiv
