// Reading lenses: the native `.lens` format (docs/lens-format.md), pbrt `.dat` files, and
// the lenses shipped in data/lenses by name.
#pragma once
#include <string>
#include <vector>

#include "optics/lens_prescription.h"

namespace objektiv {

LensPrescription ReadLensFile(const std::string& path);  // by extension: .lens or .dat
LensPrescription ParseNativeLens(const std::string& text, const std::string& path);
// A path, or the name of a shipped lens ("dgauss.50mm"): data/lenses/NAME.lens, then .dat.
LensPrescription LoadLens(const std::string& name_or_path);
// Names of the shipped lenses (without extension), sorted.
std::vector<std::string> ShippedLensNames();

}  // namespace objektiv
