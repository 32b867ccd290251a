// Reader of pbrt's lens files (the `realistic` camera's .dat format), as pbrt-v4 reads them:
// rows of (radius, thickness, index after, aperture diameter) from the object side; index 0
// means air; the row with radius 0 is the aperture stop, whose index is the medium after it
// (air, or glass for a stop inside an element); the last thickness is the distance to the
// film (0 in pbrt's files, where the camera focuses). A stop between two different media is
// also a flat interface: Objektiv refracts there (pbrt-v4 does not) and warns.
#pragma once
#include <string>

#include "optics/lens_prescription.h"

namespace objektiv {

// Throws InputError with file:line for malformed rows, a missing or second stop, non-finite
// or impossible values (negative aperture, an aperture larger than its sphere).
LensPrescription ReadPbrtLens(const std::string& path);
LensPrescription ParsePbrtLens(const std::string& text, const std::string& path);

}  // namespace objektiv
