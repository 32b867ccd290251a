// Plots of the lens library as SVG: the lens designer's layout (cross-section and ray fans).
#pragma once
#include <vector>

#include "optics/dispersion.h"
#include "io/svg.h"
#include "optics/lens_tracer.h"

namespace objektiv {

// Cross-section of the elements (from the exact surface sags), the stop, the film, and
// meridional fans of real rays (five per field, across the entrance pupil) for each field
// angle in degrees. Rays stop where an aperture blocks them.
Svg PlotLensLayout(const LensSystem& lens, const std::vector<double>& fields_deg, double lambda_nm = kLambdad);
// The same with the fans from the plane the lens is focused on (the viewer's lens, set up as
// its camera is): the object plane paraxially conjugate to the film (Newton's x x' = -f^2), its
// points at each field angle seen from the entrance pupil, each fan aimed across the paraxial
// entrance pupil; from infinity where the film lies at or before the back focus.
Svg PlotLensLayoutAsFocused(const LensSystem& lens, const std::vector<double>& fields_deg, double lambda_nm = kLambdad);

// A default set of fields: on axis, 70% and 100% of the field that covers a full-frame
// half-diagonal (21.6 mm) or the largest the lens can trace, whichever is smaller.
std::vector<double> DefaultFields(const LensSystem& lens, double lambda_nm = kLambdad);

}  // namespace objektiv
