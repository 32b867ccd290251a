// What a lens file's birefringent crystals (optics/uniaxial_crystal.h) must satisfy, checked for
// the readers, which name the line: a crystal is a medium of its own between two refracting
// surfaces (no gradient in it, no mirror or stop in glass at its far end), and a lens holds at
// most kMaxCrystals of them (the camera's pupil bounds trace every combination of their waves,
// 2^count of them).
#pragma once
#include <optional>
#include <string>
#include <utility>

#include "optics/lens_prescription.h"

namespace objektiv {

inline constexpr int kMaxCrystals = 4;

// The first surface to blame and why; nothing where every crystal can be traced.
std::optional<std::pair<size_t, std::string>> FirstCrystalMismatch(const LensPrescription& lens);

}  // namespace objektiv
