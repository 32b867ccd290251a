#include "io/anaglyph.h"

#include <algorithm>
#include <stdexcept>

namespace objektiv {

namespace {
// Dubois' red-cyan matrices (rows: the anaglyph's R, G, B; columns: the eye's R, G, B). The left
// eye's light ends up almost all in the red channel, the right eye's in green and blue; the
// small negative terms cancel what the other filter lets through.
constexpr float kLeft[3][3] = {{0.437f, 0.449f, 0.164f}, {-0.062f, -0.062f, -0.024f}, {-0.048f, -0.050f, -0.017f}};
constexpr float kRight[3][3] = {{-0.011f, -0.032f, -0.007f}, {0.377f, 0.761f, 0.009f}, {-0.026f, -0.093f, 1.234f}};
}  // namespace

Vec3f DuboisRedCyan(const Vec3f& left, const Vec3f& right) {
  const float l[3] = {left.x, left.y, left.z}, r[3] = {right.x, right.y, right.z};
  float out[3];
  for (int i = 0; i < 3; ++i) {
    float v = 0;
    for (int j = 0; j < 3; ++j) v += kLeft[i][j] * l[j] + kRight[i][j] * r[j];
    out[i] = std::clamp(v, 0.f, 1.f);
  }
  return {out[0], out[1], out[2]};
}

Image AnaglyphImage(const Image& sbs, const ColorSpace& cs, ToneMap tonemap) {
  if (sbs.width % 2 != 0 || sbs.NumChannels() < 3)
    throw std::invalid_argument("AnaglyphImage: needs an even width and R, G, B");
  const int w = sbs.width / 2, h = sbs.height, n = sbs.NumChannels();
  std::vector<std::string> names = {"R", "G", "B"};
  for (const char* eye : {"left.", "right."})
    for (const std::string& c : sbs.channels) names.push_back(eye + c);
  Image out(w, h, names);
  const ColorSpace& rec709 = ColorSpace::Rec709();
  const bool convert = &cs != &rec709;
  // The eye's pixel as the display shows it: Rec.709, through the tone curve, linear.
  auto display = [&](int x, int y) {
    Vec3f rgb = sbs.Rgb(x, y);
    if (convert) rgb = rec709.ToRGB(cs.ToXYZ(rgb));
    return Vec3f(ToneCurve(rgb.x, tonemap), ToneCurve(rgb.y, tonemap), ToneCurve(rgb.z, tonemap));
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Vec3f a = DuboisRedCyan(display(x, y), display(x + w, y));
      out.At(x, y, 0) = a.x, out.At(x, y, 1) = a.y, out.At(x, y, 2) = a.z;
      for (int c = 0; c < n; ++c) {
        out.At(x, y, 3 + c) = sbs.At(x, y, c);
        out.At(x, y, 3 + n + c) = sbs.At(x + w, y, c);
      }
    }
  return out;
}

}  // namespace objektiv
