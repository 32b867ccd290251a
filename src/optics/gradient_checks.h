// What a lens file's gradient-index media (optics/gradient_index.h) must satisfy, checked for
// the readers, which name the line: the index stays a glass's (1 to 5, at the d line) over the
// whole element (its clear aperture, between its surfaces' sags); a spherical profile's centre
// lies outside the element on the axis (the shells shrink to a point there); the gap ends at a
// refracting surface of its own (no stop inside glass after it, no Fresnel surface on its sides)
// and the lens has no mirrors (the traced media follow the direction of travel toward the
// film).
#pragma once
#include <optional>
#include <string>
#include <utility>

#include "optics/lens_prescription.h"

namespace objektiv {

// The first surface to blame and why; nothing where every gradient medium can be traced.
std::optional<std::pair<size_t, std::string>> FirstGradientMismatch(const LensPrescription& lens);

}  // namespace objektiv
