// First-order imaging of objects at finite distance, and unit focusing: moving the whole
// lens away from the film until an object at a given distance is sharp.
#pragma once
#include <optional>

#include "optics/lens_prescription.h"

namespace objektiv {

struct FocusSolution {
  double back_focus = 0;       // last vertex to film, mm (the last thickness)
  double object_to_first_vertex = 0;  // mm
  double magnification = 0;    // image height / object height (negative: inverted)
  double working_fnumber = 0;  // 1 / (2 |u'|) of the marginal ray at the film
};

// Paraxial image of an object `object_to_first_vertex` mm in front of the first vertex.
FocusSolution ImageObject(const LensPrescription& lens, double object_to_first_vertex, double lambda_nm = 587.5618);

// Unit focusing: the back focus that makes an object `distance_from_film` mm in front of the
// film sharp (the lens moves as a whole). Nothing if the object is too close to be focused
// (inside the closest distance, 4 f plus the lens's own length for a thin lens).
std::optional<FocusSolution> FocusAtDistance(const LensPrescription& lens, double distance_from_film,
                                             double lambda_nm = 587.5618);

// The same lens scaled by `factor` (radii, thicknesses, apertures; aspheric terms accordingly).
LensPrescription ScaleLens(const LensPrescription& lens, double factor);
// Scaled so that its paraxial EFL at the d line is `focal_length` mm.
LensPrescription ScaleToFocalLength(const LensPrescription& lens, double focal_length);

}  // namespace objektiv
