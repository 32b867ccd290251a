// Display transforms from linear RGB to sRGB-encoded [0, 1] for PNG output.
#pragma once
#include "base/image.h"

namespace objektiv {

enum class ToneMap {
  kClamp,   // clip to [0, 1], then the sRGB curve
  kFilmic,  // ACES filmic fit (Narkowicz 2015) on each channel, then the sRGB curve
};

Image ApplyToneMap(const Image& linear, ToneMap mode);
// The tone curve alone, in linear light: a linear value to the display's linear [0, 1].
float ToneCurve(float linear, ToneMap mode);

}  // namespace objektiv
