// The diffraction pattern of a lens's stop as an image (`objektiv lens psf`): at one
// wavelength (grey), or for white light (D65) as the sum of the patterns at 400..700 nm in
// 10 nm steps, each scaled by its wavelength, weighted by the CIE colour matching functions
// and turned into linear Rec.709 RGB. A pixel holds the fraction of the light that falls on
// it (each channel of the whole pattern sums to 1; white light is (1, 1, 1) in total).
#pragma once
#include <optional>

#include "base/image.h"
#include "optics/diffraction_psf.h"

namespace objektiv {

Image DiffractionImage(const PupilFunction& pupil, double fnumber, std::optional<double> lambda_nm, double pitch_um,
                       int size);

}  // namespace objektiv
