// Reading lenses: the native `.lens` format (docs/lens-format.md), pbrt `.dat` files, Zemax
// `.zmx` files, and the lenses shipped in data/lenses by name.
#pragma once
#include <string>
#include <vector>

#include "optics/glass_catalog.h"
#include "optics/lens_prescription.h"

namespace objektiv {

// The lens file formats, by extension, in the order a shipped lens's name tries them.
inline constexpr const char* kLensFileExtensions[] = {".lens", ".dat", ".zmx"};
// "`.lens`, `.dat` or `.zmx`"-style list of kLensFileExtensions, for messages and help.
std::string LensFileExtensionList();

// Glass names in lens files are looked up in `glasses` (the catalogs a caller chose, in lookup
// order; GlassCatalog::Default() is the shipped set).
LensPrescription ReadLensFile(const std::string& path, const GlassCatalog& glasses);  // by extension (any case)
LensPrescription ParseNativeLens(const std::string& text, const std::string& path, const GlassCatalog& glasses);
// Where a lens named on the command line or in a scene is, the one rule for both: `name` as a
// file path (relative to `base_dir`; the current directory when empty), else a shipped lens by
// name, with or without its extension ("dgauss.50mm", "tessar.brendel.100mm.dat"; without one,
// data/lenses/NAME.lens, then .dat, then .zmx). Throws InputError without a location (the
// caller knows where the name was written) that lists the shipped lenses.
std::string ResolveLens(const std::string& name, const std::string& base_dir = "");
// ReadLensFile(ResolveLens(name, base_dir), glasses).
LensPrescription LoadLens(const std::string& name, const GlassCatalog& glasses, const std::string& base_dir = "");
// Names of the shipped lenses (without extension), sorted.
std::vector<std::string> ShippedLensNames();

}  // namespace objektiv
