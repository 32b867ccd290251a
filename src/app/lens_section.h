// The lens in cross-section in the viewer's panel: the drawing `objektiv lens plot` writes as
// SVG (io/lens_plot.h: elements, stop, film and ray fans), drawn with Dear ImGui at the
// panel's width (outlines: ImGui fills only convex shapes, and a meniscus is not).
#pragma once
#include "io/svg.h"

namespace objektiv {

// Draws it at the cursor, `width` pixels wide, its texts (field labels, caption) below it in
// their colours, wrapped at that width, and moves the cursor below them.
void DrawLensSection(const Svg& plot, float width);

}  // namespace objektiv
