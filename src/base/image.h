// A float image with named channels (interleaved), the common currency of film and I/O.
#pragma once
#include <string>
#include <vector>

#include "base/vec.h"

namespace objektiv {

struct Image {
  int width = 0, height = 0;
  std::vector<std::string> channels;  // e.g. {"R", "G", "B"}
  std::vector<float> pixels;          // width * height * channels.size(), rows top to bottom

  Image() = default;
  Image(int w, int h, std::vector<std::string> names)
      : width(w), height(h), channels(std::move(names)), pixels(size_t(w) * h * channels.size(), 0.f) {}

  int NumChannels() const { return int(channels.size()); }
  float& At(int x, int y, int c) { return pixels[(size_t(y) * width + x) * channels.size() + c]; }
  float At(int x, int y, int c) const { return pixels[(size_t(y) * width + x) * channels.size() + c]; }
  Vec3f Rgb(int x, int y) const { return {At(x, y, 0), At(x, y, 1), At(x, y, 2)}; }
};

}  // namespace objektiv
