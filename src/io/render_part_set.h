// Whether render parts (io/render_part.h) make one whole render, before any pixel is read:
// - each is a finished part (not a checkpoint; every pixel has its samples);
// - all are parts of the same render (RenderPartInfo::Mismatch);
// - every pixel of the render's crop window has each sample index of [0, spp) in exactly one
//   part: no overlap, no gap (parts may mix crops and sample ranges freely: the whole image's
//   first samples in one part, the rest in crops). Checked per cell of the grid that the
//   crops' edges draw (in a cell every pixel is in the same parts).
// Throws InputError naming the files (and the samples or the pixel) of the first problem.
#pragma once
#include <string>
#include <vector>

#include "io/render_part.h"

namespace objektiv {

void CheckPartsMakeOneRender(const std::vector<std::string>& paths, const std::vector<RenderPartInfo>& parts);

}  // namespace objektiv
