// Red-cyan anaglyphs by Dubois' least-squares projection (E. Dubois, "A projection method to
// generate anaglyph stereo images", ICASSP 2001): the colour each eye sees through its filter is
// matched, in the least-squares sense over the display's spectra, by one RGB image, instead of
// copying the left image's red channel and the right one's green and blue (which loses colour
// and leaves ghosting). The matrices are those Dubois publishes for red-cyan glasses
// ("Conversion of a stereo pair to anaglyph with the least-squares projection method", 2009).
#pragma once
#include "base/color_space.h"
#include "base/image.h"
#include "io/tonemap.h"

namespace objektiv {

// The anaglyph of one pixel: `left` and `right` are LINEAR RGB with the sRGB / Rec.709
// primaries (the display primaries the matrices were fitted to: the method works on a display's
// linear intensities, the gamma removed), display-referred in [0, 1]; the result is linear
// Rec.709 clipped to [0, 1], as the method does (clip, then the display's gamma curve).
Vec3f DuboisRedCyan(const Vec3f& left, const Vec3f& right);

// What a stereo render with layout "anaglyph" writes, from the film's side-by-side image
// (width 2W: the left eye's W columns first; linear, in `cs`, R, G, B then any other channels):
// a W x H image whose R, G, B are the anaglyph (linear Rec.709 in [0, 1]: each eye's RGB
// converted to Rec.709 and put through the film's tone curve `tonemap`, in linear light, then
// DuboisRedCyan), followed by every channel of each eye as it was, as layers left.* and right.*
// (left.R, left.G, left.B, left.<aov>..., right.R, ...).
Image AnaglyphImage(const Image& side_by_side, const ColorSpace& cs, ToneMap tonemap);

}  // namespace objektiv
