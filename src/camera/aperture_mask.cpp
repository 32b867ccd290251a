#include "camera/aperture_mask.h"

#include <algorithm>
#include <cmath>

namespace objektiv {

ApertureMask::ApertureMask(const Image& image) : width_(image.width), height_(image.height) {
  values_.resize(size_t(width_) * height_);
  const int c = image.NumChannels();
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      float v = c >= 3 ? (image.At(x, y, 0) + image.At(x, y, 1) + image.At(x, y, 2)) / 3 : image.At(x, y, 0);
      values_[size_t(y) * width_ + x] = std::clamp(v, 0.f, 1.f);
    }
}

float ApertureMask::Transmittance(float x, float y) const {
  // Lens +x is the photographer's left: image u grows with -x; image v grows downward (-y).
  float u = (1 - x) * 0.5f * width_ - 0.5f, v = (1 - y) * 0.5f * height_ - 0.5f;
  if (!(u > -0.5f && v > -0.5f && u < width_ - 0.5f && v < height_ - 0.5f)) return 0;
  // Bilinear, clamped at the border.
  int x0 = std::clamp(int(std::floor(u)), 0, width_ - 1), y0 = std::clamp(int(std::floor(v)), 0, height_ - 1);
  int x1 = std::min(x0 + 1, width_ - 1), y1 = std::min(y0 + 1, height_ - 1);
  float fx = std::clamp(u - x0, 0.f, 1.f), fy = std::clamp(v - y0, 0.f, 1.f);
  auto at = [&](int xi, int yi) { return values_[size_t(yi) * width_ + xi]; };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x1, y0)) + fy * ((1 - fx) * at(x0, y1) + fx * at(x1, y1));
}

ConvexPolygon ApertureMask::OpenHull() const {
  // A pixel's value reaches one pixel to each side through the bilinear lookup, and no
  // further than the image's border: per row, the footprints of its outermost open pixels.
  auto u_to_x = [&](double u) { return 1 - 2 * (std::clamp(u, -0.5, width_ - 0.5) + 0.5) / width_; };
  auto v_to_y = [&](double v) { return 1 - 2 * (std::clamp(v, -0.5, height_ - 0.5) + 0.5) / height_; };
  std::vector<Vec2d> corners;
  for (int y = 0; y < height_; ++y) {
    const float* row = &values_[size_t(y) * width_];
    int first = 0, last = width_ - 1;
    while (first < width_ && row[first] == 0) ++first;
    if (first == width_) continue;
    while (row[last] == 0) --last;
    for (double u : {first - 1.0, last + 1.0})
      for (double v : {y - 1.0, y + 1.0}) corners.push_back({u_to_x(u), v_to_y(v)});
  }
  return ConvexPolygon::HullOf(std::move(corners));
}

}  // namespace objektiv
