#include "render/film.h"

#include <cmath>

#include "base/cie.h"

namespace objektiv {

Film::Film(int width, int height, CropWindow crop, std::shared_ptr<const Filter> filter)
    : width_(width), height_(height), crop_(crop), filter_(std::move(filter)),
      pixels_(size_t(crop.Width()) * crop.Height()) {}

Vec3f SampledToXYZ(const SampledSpectrum& L, const SampledWavelengths& lambda) {
  Vec3f xyz(0.f);
  for (int i = 0; i < kSpectrumSamples; ++i) {
    float pdf = lambda.Pdf(i);
    if (pdf == 0) continue;
    xyz += CieXyz(lambda[i]) * (L[i] / pdf);
  }
  return xyz / (float(kSpectrumSamples) * CieYIntegral());
}

void Film::AddSample(Vec2i pixel, const SampledSpectrum& L, const SampledWavelengths& lambda, float weight) {
  Vec3f xyz = SampledToXYZ(L, lambda);
  Pixel& px = At(pixel);
  for (int c = 0; c < 3; ++c) px.xyz[c] += double(weight) * xyz[c];
  px.weight += weight;
}

Image Film::ToImage(const ColorSpace& cs, float exposure_stops) const {
  Image img(crop_.Width(), crop_.Height(), {"R", "G", "B"});
  float scale = std::exp2(exposure_stops);
  for (int y = 0; y < crop_.Height(); ++y)
    for (int x = 0; x < crop_.Width(); ++x) {
      const Pixel& px = pixels_[size_t(y) * crop_.Width() + x];
      Vec3f xyz(0.f);
      if (px.weight != 0) xyz = Vec3f(float(px.xyz[0] / px.weight), float(px.xyz[1] / px.weight), float(px.xyz[2] / px.weight));
      Vec3f rgb = cs.ToRGB(xyz) * scale;
      for (int c = 0; c < 3; ++c) img.At(x, y, c) = rgb[c];
    }
  return img;
}

}  // namespace objektiv
