// How noisy a render is, as the film holds it, for `--noise-target`: per pixel, the relative
// standard error of its luminance estimate,
//   e = sqrt(variance / n) / (|mean| + floor),
// n the pixel's samples, mean and variance those of one sample's luminance Y (filter-weighted,
// from the film's sums of w*Y and w*Y^2), floor = 1% of the image's mean luminance, so that
// near-black pixels, whose noise does not show, do not count as noisy. The image's figure is
// the 95th percentile of e over its pixels: 95% of the pixels are at least that good. Pixels
// with fewer than 2 camera samples count as infinitely noisy (no variance yet; so does every
// pixel of a film that only light paths splat into: such a render runs to its samples).
#pragma once
#include "render/film.h"

namespace objektiv {

double RelativeNoise(const Film& film);

}  // namespace objektiv
