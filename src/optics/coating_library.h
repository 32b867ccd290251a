// The coatings a lens can name, and the materials their layers are made of.
//
// Built in (names compared without case):
//   none, uncoated       bare glass: Fresnel's reflectance
//   MgF2, MgF2@NM        one quarter-wave layer of magnesium fluoride at 550 nm (or NM)
//   multi, multi@NM      a broadband quarter-half-quarter stack at 550 nm (or NM): MgF2 0.25 |
//                        ZrO2 0.5 | matched 0.25 (see optics/coating.h)
//   I.xx                 Zemax's ideal coating: transmittance 0.xx everywhere (I.95, I.995)
// A lens file defines more (docs/lens-format.md): a name, a design wavelength and layers
// written MATERIAL:THICKNESS, where MATERIAL is a coating material (below), `matched`, a
// catalog glass or n=INDEX, and THICKNESS is optical, in waves at the design wavelength
// (0.25), or physical with `nm` (98.5nm).
//
// Coating materials: MgF2 (Sellmeier, ordinary ray: M. J. Dodge, Appl. Opt. 23, 1984) and SiO2
// (Sellmeier, fused silica: I. H. Malitson, JOSA 55, 1965), dispersive; Al2O3 1.62, ZrO2 2.05,
// Ta2O5 2.10 and TiO2 2.35, typical indices of evaporated films near 550 nm (films differ from
// the bulk crystals), without dispersion.
#pragma once
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "optics/coating.h"
#include "optics/glass_catalog.h"
#include "optics/lens_prescription.h"

namespace objektiv {

// Coating names and layer materials compare without case ("mgf2" is MgF2).
bool SameCoatingName(std::string_view a, std::string_view b);

// A coating material by name (case-insensitive), or null.
std::shared_ptr<const Glass> FindCoatingMaterial(std::string_view name);
// "MgF2, SiO2, ..." for messages.
std::string CoatingMaterialNames();

// A built-in coating by name: nothing if the name is unknown; a null pointer for none/uncoated.
// Throws InputError (without a location) for a built-in's name with a parameter out of range
// (MgF2@100, I.0).
std::optional<std::shared_ptr<const Coating>> FindBuiltInCoating(std::string_view name);
// "none, MgF2[@NM], multi[@NM], I.xx" for messages.
std::string BuiltInCoatingNames();

// A coating by name for a lens: built in, or one the lens's surfaces carry (defined in its
// file); null for none. Throws InputError (without a location) for an unknown name.
std::shared_ptr<const Coating> CoatingForLens(std::string_view name, const LensPrescription& lens);
// What a scene's or `lens info`'s coating choice does: every air-glass surface gets `coating`;
// null leaves every surface bare, cemented ones too. Throws InputError (without a location)
// where the coating cannot lie on a surface's glass (optics/coating.h: CoatingMismatch).
void Recoat(LensPrescription& lens, const std::shared_ptr<const Coating>& coating);

// A coating definition's fields after its name: [design=NM] LAYER... Throws InputError
// "PATH:LINE: ..." on a bad field.
std::shared_ptr<const Coating> ParseCoatingDefinition(const std::string& name, std::span<const std::string> fields,
                                                      const GlassCatalog& glasses, const std::string& path, int line);

}  // namespace objektiv
