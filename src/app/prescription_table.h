// The prescription as `lens info` lists it: per row the radius, the thickness after it, the
// medium after it (the glass as found: catalog and name, so a user sees which glass a name in
// the file became), its nd and Vd, and the clear semi-diameter; as text and as JSON.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "optics/lens_prescription.h"

namespace objektiv {

// "SCHOTT:N-BK7", "air", "n=1.768", "model 1.516800/64.17".
std::string MediumLabel(const LensSurface& s);
// The same for a medium (air where null).
std::string MediumLabel(const std::shared_ptr<const Glass>& medium);
// The table's lines, each indented by two spaces and ending in a newline.
std::string PrescriptionTable(const LensPrescription& lens);
nlohmann::ordered_json PrescriptionJson(const LensPrescription& lens);

}  // namespace objektiv
