#include "optics/crystal_checks.h"

#include <fmt/format.h>

namespace objektiv {

std::optional<std::pair<size_t, std::string>> FirstCrystalMismatch(const LensPrescription& lens) {
  int count = 0;
  for (size_t i = 0; i < lens.surfaces.size(); ++i) {
    const LensSurface& s = lens.surfaces[i];
    if (!s.crystal) continue;
    if (++count > kMaxCrystals)
      return std::pair{i, fmt::format("a {}th birefringent crystal: at most {} in a lens", count, kMaxCrystals)};
    if (!s.medium) return std::pair{i, std::string("a crystal needs its glass (the medium column names air)")};
    if (s.gradient) return std::pair{i, std::string("a crystal with a gradient-index medium is not modelled")};
    if (s.mirror) return std::pair{i, std::string("a mirror cannot start a crystal (the medium follows a refracting surface)")};
    if (i + 1 < lens.surfaces.size()) {
      const LensSurface& next = lens.surfaces[i + 1];
      if (next.mirror) return std::pair{i + 1, std::string("a mirror at the far end of a crystal is not modelled")};
      if (next.is_stop && next.medium)
        return std::pair{i + 1, std::string("the stop lies inside glass after a crystal; put it in air (a crystal ends "
                                            "at a refracting surface)")};
    }
  }
  return std::nullopt;
}

}  // namespace objektiv
