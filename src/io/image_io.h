// Reading and writing images through OpenImageIO.
#pragma once
#include <cstdint>
#include <string>

#include "base/image.h"

namespace objektiv {

// Largest image read: 2^28 pixels (16384 x 16384), and 4 GiB once decoded to floats (all
// channels). The header's size is checked before anything is allocated for the pixels, and
// they are decoded a strip at a time, so a short file claiming a huge image fails early.
inline constexpr int64_t kMaxImagePixels = int64_t(1) << 28;
inline constexpr int64_t kMaxImageBytes = int64_t(4) << 30;

// Linear RGB (3 channels). Grey images are replicated, alpha is dropped. Integer-encoded
// files (PNG, JPEG, 8/16-bit TIFF) are taken as sRGB and decoded to linear unless `raw`.
// Throws InputError naming the file if it cannot be read (missing, not a regular file, beyond
// the limits above, truncated or corrupt, or too large for the memory left).
Image ReadImageRgb(const std::string& path, bool raw = false);
// Every channel as stored (float), for comparisons.
Image ReadImageAny(const std::string& path);

// Linear float EXR (ZIP compressed) with the image's channel names.
void WriteExr(const std::string& path, const Image& image);
// 8-bit PNG of an image whose values are already display-encoded in [0, 1].
void WritePng(const std::string& path, const Image& display);

float SrgbToLinear(float v);
float LinearToSrgb(float v);

}  // namespace objektiv
