// Reader of Zemax sequential lens files (.zmx, UTF-16 or ASCII): SURF, TYPE STANDARD and
// EVENASPH, CURV, DISZ, GLAS, DIAM, CONI, PARM, STOP, UNIT, NAME. Surface 0 is the object and
// the last surface the image; what the reader does not support is named in a warning, and a
// surface type it cannot trace is an error.
#pragma once
#include <string>

#include "optics/glass_catalog.h"
#include "optics/lens_prescription.h"

namespace objektiv {

// GLAS names are looked up in `glasses`.
LensPrescription ReadZemaxLens(const std::string& path, const GlassCatalog& glasses);
LensPrescription ParseZemaxLens(const std::string& raw, const std::string& path, const GlassCatalog& glasses);

}  // namespace objektiv
