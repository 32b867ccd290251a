// `lens analyze`: the real-ray figures of a lens as SVG plots and one JSON file.
#pragma once
#include <string>

#include "optics/lens_tracer.h"

namespace objektiv {

// Writes spots.svg, distortion.svg, field_curvature.svg, relative_illumination.svg,
// axial_colour.svg and analysis.json into `directory` (created if needed). The film is where
// the lens has it (the paraxial focus for an object at infinity, as callers set it).
void WriteLensAnalysis(const LensSystem& lens, const std::string& directory);

}  // namespace objektiv
