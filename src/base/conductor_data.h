// Measured complex refractive indices of metals, for `conductor` material="Au" etc.
#pragma once
#include <optional>
#include <string>

#include "base/spectrum.h"

namespace objektiv {

struct ConductorIndex {
  Spectrum eta, k;
};

// "Au", "Ag", "Cu", "Al", or "none" (a perfect mirror: eta = 0, k = 1).
std::optional<ConductorIndex> NamedConductor(const std::string& name);
std::string NamedConductorList();

}  // namespace objektiv
