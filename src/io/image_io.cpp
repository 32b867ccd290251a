#include "io/image_io.h"

#include <OpenImageIO/imageio.h>

#include <cmath>

#include "base/error.h"
#include "base/text_file.h"

namespace objektiv {

float SrgbToLinear(float v) {
  if (v <= 0.04045f) return v / 12.92f;
  return std::pow((v + 0.055f) / 1.055f, 2.4f);
}

float LinearToSrgb(float v) {
  if (v <= 0.0031308f) return 12.92f * v;
  return 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
}

namespace {
struct RawImage {
  Image image;
  bool integer_format = false;
};

RawImage ReadRaw(const std::string& path) {
  CheckInputFile(path, "image", UINTMAX_MAX);
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw MakeInputError(path, 0, "cannot read image: {}", OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    throw MakeInputError(path, 0, "image has no pixels");
  RawImage r;
  r.integer_format = !spec.format.is_floating_point();
  std::vector<std::string> names;
  for (int c = 0; c < spec.nchannels; ++c) names.push_back(spec.channel_name(c));
  r.image = Image(spec.width, spec.height, names);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, r.image.pixels.data()))
    throw MakeInputError(path, 0, "cannot decode image: {}", in->geterror());
  in->close();
  return r;
}
}  // namespace

Image ReadImageAny(const std::string& path) { return ReadRaw(path).image; }

Image ReadImageRgb(const std::string& path, bool raw) {
  RawImage r = ReadRaw(path);
  const Image& src = r.image;
  Image out(src.width, src.height, {"R", "G", "B"});
  int n = src.NumChannels();
  bool decode = r.integer_format && !raw;
  for (int y = 0; y < src.height; ++y)
    for (int x = 0; x < src.width; ++x)
      for (int c = 0; c < 3; ++c) {
        float v = src.At(x, y, n >= 3 ? c : 0);
        if (!std::isfinite(v)) throw MakeInputError(path, 0, "pixel ({}, {}) is not finite", x, y);
        out.At(x, y, c) = decode ? SrgbToLinear(v) : v;
      }
  return out;
}

namespace {
void Write(const std::string& path, const Image& image, OIIO::TypeDesc format, const char* compression) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw InputError(fmt::format("{}: cannot create image file: {}", path, OIIO::geterror()));
  OIIO::ImageSpec spec(image.width, image.height, image.NumChannels(), format);
  spec.channelnames = image.channels;
  if (compression) spec.attribute("compression", compression);
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()) || !out->close())
    throw InputError(fmt::format("{}: cannot write image: {}", path, out->geterror()));
}
}  // namespace

void WriteExr(const std::string& path, const Image& image) { Write(path, image, OIIO::TypeDesc::FLOAT, "zip"); }

void WritePng(const std::string& path, const Image& display) { Write(path, display, OIIO::TypeDesc::UINT8, nullptr); }

}  // namespace objektiv
