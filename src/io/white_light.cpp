#include "io/white_light.h"

#include "base/cie.h"
#include "base/color_space.h"

namespace objektiv {

std::vector<std::pair<double, double>> LuminanceWeights(double step_nm) {
  std::vector<std::pair<double, double>> weights;
  double total = 0;
  for (double l = 400; l <= 700 + 1e-9; l += step_nm) {
    const double y = CieXyz(float(l)).y * D65Normalized(float(l));
    weights.push_back({l, y});
    total += y;
  }
  for (auto& [l, w] : weights) w /= total;
  return weights;
}

Image WhiteLightImage(int width, int height, double step_nm, const std::function<std::vector<double>(double)>& picture) {
  std::vector<Vec3f> xyz(size_t(width) * height, Vec3f(0.f));
  double total_y = 0;
  for (double l = 400; l <= 700 + 1e-9; l += step_nm) {
    const Vec3f weight = CieXyz(float(l)) * D65Normalized(float(l));
    total_y += weight.y;
    const std::vector<double> values = picture(l);
    for (size_t i = 0; i < xyz.size(); ++i) xyz[i] += weight * float(values[i]);
  }
  const ColorSpace& rec709 = ColorSpace::Rec709();
  Image image(width, height, {"R", "G", "B"});
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Vec3f rgb = rec709.ToRGB(xyz[size_t(y) * width + x] / float(total_y));
      for (int c = 0; c < 3; ++c) image.At(x, y, c) = rgb[c];
    }
  return image;
}

}  // namespace objektiv
