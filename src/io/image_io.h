// Reading and writing images through OpenImageIO.
#pragma once
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "base/image.h"

namespace objektiv {

// Largest image read: 2^28 pixels (16384 x 16384), and 4 GiB once decoded to floats (all
// channels). The header's size is checked before anything is allocated for the pixels, and
// they are decoded a strip at a time, so a short file claiming a huge image fails early.
inline constexpr int64_t kMaxImagePixels = int64_t(1) << 28;
inline constexpr int64_t kMaxImageBytes = int64_t(4) << 30;
// The limits the reader applies: the two above, unless lowered for this process by
// SetImageReadLimits (values above them, or not positive, are taken as the constants). The
// fuzz harness lowers them: its memory cap cannot tell a true 16384 x 16384 image, which
// needs 3 GiB as RGB floats, from a false claim, and the reader's checks work alike at any size.
struct ImageReadLimits {
  int64_t pixels = kMaxImagePixels;
  int64_t bytes = kMaxImageBytes;
};
ImageReadLimits CurrentImageReadLimits();
void SetImageReadLimits(ImageReadLimits limits);
// Largest pixel value read, in magnitude. No scene's radiance or reflectance comes near it
// (the Sun's disc is about 1.6e9 cd/m^2), and beyond it the sums and products a renderer
// forms (an environment map's importance over all its texels, bilinear blends, radiance over
// a small pdf) overflow single precision into Inf and NaN.
inline constexpr float kMaxPixelValue = 1e20f;

// Linear RGB (3 channels). Grey images are replicated, alpha is dropped. Integer-encoded
// files (PNG, JPEG, 8/16-bit TIFF) are taken as sRGB and decoded to linear unless `raw`.
// Throws InputError naming the file if it cannot be read (missing, not a regular file, beyond
// the limits above, a pixel value not finite or beyond kMaxPixelValue, truncated or corrupt,
// or too large for the memory left). Records the file
// as an input of this run (base/input_files.h), as the mesh readers do.
Image ReadImageRgb(const std::string& path, bool raw = false);
// Every channel as stored (float), for comparisons.
Image ReadImageAny(const std::string& path);

// A header attribute of an EXR file, e.g. {"objektiv:partial", 1}.
struct ImageAttribute {
  using Value = std::variant<int, double, std::string>;
  std::string name;
  Value value;
};

// Both writers write atomically (base/output_file.h: a temporary file renamed over `path`)
// and throw InputError naming `path` on failure.
// Linear float EXR (ZIP compressed) with the image's channel names and extra attributes.
void WriteExr(const std::string& path, const Image& image, const std::vector<ImageAttribute>& attributes = {});
// 8-bit PNG of an image whose values are already display-encoded in [0, 1].
void WritePng(const std::string& path, const Image& display);

float SrgbToLinear(float v);
float LinearToSrgb(float v);

}  // namespace objektiv
