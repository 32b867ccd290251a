// A lens without dispersion: every homogeneous glass (and the medium before the lens) replaced
// by its index at the d line (587.56 nm) at every wavelength, its transmittance kept, so that
// each wavelength takes the path the d line takes. What a lens draws without its axial and
// lateral colour, to see how much of a picture they are (the sensor's `dispersion false`, the
// viewer's toggle). Gradient-index media and crystals keep their own dispersion.
#pragma once
#include "optics/lens_prescription.h"

namespace objektiv {

LensPrescription WithoutDispersion(const LensPrescription& lens);

// Whether WithoutDispersion leaves some dispersion: a gradient-index medium or a crystal.
bool KeepsDispersionWithout(const LensPrescription& lens);

}  // namespace objektiv
