// Plots of the lens library as SVG: the lens designer's layout (cross-section and ray fans).
#pragma once
#include <vector>

#include "io/svg.h"
#include "optics/lens_tracer.h"

namespace objektiv {

// Cross-section of the elements (from the exact surface sags), the stop, the film, and
// meridional fans of real rays (five per field, across the entrance pupil) for each field
// angle in degrees. Rays stop where an aperture blocks them.
Svg PlotLensLayout(const LensSystem& lens, const std::vector<double>& fields_deg, double lambda_nm = 587.5618);

// A default set of fields: on axis, 70% and 100% of the field that covers a full-frame
// half-diagonal (21.6 mm) or the largest the lens can trace, whichever is smaller.
std::vector<double> DefaultFields(const LensSystem& lens, double lambda_nm = 587.5618);

}  // namespace objektiv
