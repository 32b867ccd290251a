// How the pupil bounds (optics/pupil_bounds.h, optics/pupil_grid.h) are built.
#pragma once
#include <vector>

#include "optics/dispersion.h"

namespace objektiv {

struct PupilBoundsOptions {
  int bins = 128;  // radial film bins (half as many for an opening that is not round)
  // A probe passes if it passes at any of these wavelengths: a dispersive lens's pupil
  // changes a little with wavelength, and the bound must hold the light of every one.
  std::vector<double> wavelengths = {kLambdad};
  bool rims = true;  // false: only the stop clips (a lens without optical vignetting)
};

}  // namespace objektiv
