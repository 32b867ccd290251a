// The double image a lens's birefringent crystals make (optics/uniaxial_crystal.h): where each
// crystal's extraordinary wave puts the image of an on-axis point at infinity, relative to the
// ordinary image (every crystal's ordinary wave), and how far either spreads on the film (a
// lens crystal focuses its two waves apart). Each image is the centroid on the film of 17 rays
// parallel to the axis, spread over half the entrance pupil (the axial ray and two rings of
// eight), with that crystal's wave alone extraordinary; its spread, their RMS distance from it.
#pragma once
#include <optional>
#include <vector>

#include "base/vec.h"
#include "optics/lens_system.h"

namespace objektiv {

struct CrystalImage {
  Vec2d offset;       // film x, y from the ordinary image's centroid (mm)
  double rms = 0;     // the rays' RMS distance from their own centroid (mm)
};
struct CrystalImages {
  double ordinary_rms = 0;                     // the ordinary image's spread (mm)
  std::vector<std::optional<CrystalImage>> extraordinary;  // one per crystal, in the lens's order;
                                                           // nothing where no ray reaches the film
};
// Empty (no crystal, or no ordinary ray reaching the film): no images.
std::optional<CrystalImages> CrystalImagesOf(const LensSystem& lens, double lambda_nm);

}  // namespace objektiv
