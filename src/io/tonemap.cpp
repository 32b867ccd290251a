#include "io/tonemap.h"

#include "io/image_io.h"

namespace objektiv {

float ToneCurve(float v, ToneMap mode) {
  v = std::max(0.f, v);
  if (mode == ToneMap::kFilmic) {
    // Narkowicz's rational fit of the ACES reference tone curve (with 0.6 exposure).
    float a = v * 0.6f;
    v = (a * (2.51f * a + 0.03f)) / (a * (2.43f * a + 0.59f) + 0.14f);
  }
  return Clamp(v, 0, 1);
}

Image ApplyToneMap(const Image& linear, ToneMap mode) {
  Image out(linear.width, linear.height, {"R", "G", "B"});
  for (int y = 0; y < linear.height; ++y)
    for (int x = 0; x < linear.width; ++x)
      for (int c = 0; c < 3; ++c) out.At(x, y, c) = LinearToSrgb(ToneCurve(linear.At(x, y, c), mode));
  return out;
}

}  // namespace objektiv
