// The double image a lens's birefringent crystals make (optics/uniaxial_crystal.h): where each
// crystal's extraordinary wave puts the image of an on-axis point at infinity, relative to the
// ordinary image (every crystal's ordinary wave). Each is the centroid on the film of 17 rays
// parallel to the axis, spread over half the entrance pupil (the axial ray and two rings of
// eight), with that crystal's wave alone extraordinary.
#pragma once
#include <optional>
#include <vector>

#include "base/vec.h"
#include "optics/lens_system.h"

namespace objektiv {

// One offset (film x, y in mm) per crystal, in the lens's order; nothing for a crystal whose
// rays do not reach the film (or where the ordinary ones do not).
std::vector<std::optional<Vec2d>> ExtraordinaryImageOffsets(const LensSystem& lens, double lambda_nm);

}  // namespace objektiv
