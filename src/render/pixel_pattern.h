// Pixel sample patterns: where in the pixel a camera sample goes, and its weight, for the
// classic supersampling patterns. Positions are in the filter's sample space [0,1]^2
// (Filter::Sample turns them into offsets from the pixel centre): with the box filter of radius
// 0.5 they are the positions in the pixel themselves (0: its left/top edge, 1: its right/bottom
// edge); other filters warp them as they warp any sampler's numbers.
//
// Each pattern comes in rounds. Round 0 is the classic pattern at its exact positions; every
// later round is the pattern shifted by a random toroidal offset (wrapped into the unit square)
// drawn per (pixel, round) from the sampler's seed. A uniform random shift makes each point of
// a round uniform over the pixel, so the later rounds are unbiased estimates of the box-filtered
// pixel, and the round-0 pattern's aliasing (that of any fixed pattern) fades as rounds add up.
// A sample count that is not a whole number of rounds ends with a part of a round.
//   grid      side x side cell centres, side = floor(sqrt(spp)) (1 for spp < 4): the regular
//             grid; spp 16 is the 4 x 4 grid. All weights 1.
//   rgss      the 4-sample rotated grid (the grid rotated by atan(1/2), 26.6 degrees; as in
//             4x MSAA): (3/8, 1/8), (7/8, 3/8), (1/8, 5/8), (5/8, 7/8); every row and column
//             of the pixel's 4 x 4 subgrid holds one sample, so near-horizontal and near-vertical
//             edges get 4 levels each. Weights 1.
//   quincunx  round 0: the pixel's centre (weight 1/2) and its four corners (1/8 each), the
//             classic quincunx filter. In the classic scheme each corner is traced once and
//             shared by the four pixels that meet there (2 rays per pixel); here every pixel
//             traces its own corners (5 rays per pixel; the same positions and weights, so the
//             same image up to sampling noise): sharing would make pixels depend on each other,
//             which per-pixel determinism, tiles on threads, sample ranges and resumed renders
//             rule out. Later rounds take the quincunx lattice (centre and corners, the corners
//             all one point once wrapped) shifted at random: 2 samples of weight 1/2 each.
// Weights are scaled so that a round's weights average 1 (quincunx round 0: 2.5 and 0.625).
#pragma once
#include <cstdint>

#include "base/vec.h"

namespace objektiv {

enum class PixelPattern {
  kSampler,   // the sampler's own first two dimensions (stratified, Sobol', independent)
  kGrid,
  kRgss,
  kQuincunx,
};
const char* PixelPatternName(PixelPattern p);

struct PatternSample {
  Vec2f u;       // in [0,1]^2 (1 itself kept just below 1)
  float weight;  // relative to the round's mean weight of 1
};

// Samples in one round of the pattern (the first round for quincunx), for `spp` samples per pixel.
int PatternRoundSize(PixelPattern p, int spp);
// Sample `index` of a pixel whose own hash (per pixel and seed) is `pixel_hash`.
PatternSample PatternPosition(PixelPattern p, int spp, int index, uint64_t pixel_hash);

}  // namespace objektiv
