// Reader of pbrt's lens files (the `realistic` camera's .dat format), as pbrt-v4 reads them:
// rows of (radius, thickness, index after, aperture diameter) from the object side; the row
// with radius 0 is the aperture stop (its index column, 0 in the files, means air); the last
// thickness is the distance to the film (0 in pbrt's files, where the camera focuses).
#pragma once
#include <string>

#include "optics/lens_prescription.h"

namespace objektiv {

// Throws InputError with file:line for malformed rows, a missing or second stop, non-finite
// or impossible values (negative aperture, an aperture larger than its sphere).
LensPrescription ReadPbrtLens(const std::string& path);
LensPrescription ParsePbrtLens(const std::string& text, const std::string& path);

}  // namespace objektiv
