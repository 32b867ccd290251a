// A picture of white light from pictures at single wavelengths: each wavelength's picture
// weighted by D65 and the CIE colour matching functions, summed, normalised so that light of
// total luminance 1 counts as 1, and turned into linear Rec.709 RGB (white: (1, 1, 1)).
#pragma once
#include <functional>
#include <vector>

#include "base/image.h"

namespace objektiv {

// `picture(lambda_nm)` gives width x height values (row-major) for wavelengths from 400 to 700
// nm in steps of `step_nm`.
Image WhiteLightImage(int width, int height, double step_nm, const std::function<std::vector<double>(double)>& picture);

// The weights WhiteLightImage gives each wavelength's luminance (summing to 1 over them).
std::vector<std::pair<double, double>> LuminanceWeights(double step_nm);

}  // namespace objektiv
