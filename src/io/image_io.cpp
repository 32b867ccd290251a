#include "io/image_io.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <new>
#include <optional>

#include "base/error.h"
#include "base/input_files.h"
#include "base/output_file.h"
#include "base/text_file.h"
#include "io/image_file_checks.h"

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
std::atomic<int64_t> max_pixels{kMaxImagePixels};
std::atomic<int64_t> max_bytes{kMaxImageBytes};
}  // namespace

ImageReadLimits CurrentImageReadLimits() { return {max_pixels.load(), max_bytes.load()}; }

void SetImageReadLimits(ImageReadLimits limits) {
  max_pixels = limits.pixels > 0 ? std::min(limits.pixels, kMaxImagePixels) : kMaxImagePixels;
  max_bytes = limits.bytes > 0 ? std::min(limits.bytes, kMaxImageBytes) : kMaxImageBytes;
}

namespace {
struct RawImage {
  Image image;
  bool integer_format = false;
};

// The pixels of subimage 0 as floats, a strip of rows at a time (whole rows of tiles for a
// tiled file) into storage reserved for all of them: a file that ends early fails having
// touched only the memory for what it held.
bool ReadPixels(OIIO::ImageInput& in, std::vector<float>& pixels) {
  const OIIO::ImageSpec& spec = in.spec();
  const size_t row = size_t(spec.width) * size_t(spec.nchannels);
  const int strip = spec.tile_width > 0 ? std::max(spec.tile_height, 1) : 64;
  pixels.reserve(row * size_t(spec.height));
  for (int y = spec.y; y < spec.y + spec.height; y += strip) {
    const int y_end = std::min(y + strip, spec.y + spec.height);
    const size_t done = pixels.size();
    pixels.resize(done + row * size_t(y_end - y));
    float* out = pixels.data() + done;
    bool ok = spec.tile_width > 0
                  ? in.read_tiles(0, 0, spec.x, spec.x + spec.width, y, y_end, spec.z, spec.z + 1, 0, spec.nchannels,
                                  OIIO::TypeDesc::FLOAT, out)
                  : in.read_scanlines(0, 0, y, y_end, spec.z, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, out);
    // OpenImageIO 2.4's TIFF reader records a strip it could not read (a header claiming more
    // rows than its strips hold) as an error, fills it with zeros and reports success.
    if (!ok || in.has_error()) return false;
  }
  return true;
}

// The formats read, chosen by the file's extension (no other reader is tried): common image
// formats whose readers report a truncated file as an error (JPEG and OpenEXR with the
// checks of image_file_checks.h).
// Movies, camera raw files, volumes and the rest of what OpenImageIO can read are refused.
constexpr const char* kImageFormats[] = {"openexr", "hdr",  "png", "jpeg",     "tiff", "targa",
                                         "bmp",     "pnm",  "webp", "jpeg2000", "gif",  "heif"};
constexpr const char* kImageFormatList = "EXR, HDR, PNG, JPEG, TIFF, TGA, BMP, PNM, WebP, JPEG 2000, GIF, HEIF/AVIF";

// Throws unless a width x height image (as its header claims) is within the pixel limit and,
// for BMP and PNM, which store pixels raw or run-length coded (at most 255 pixels in two
// bytes), within 256 pixels a byte of the file: OpenImageIO's BMP reader would allocate for a
// false claim before finding no data (2.7 GB for 246 bytes, found by fuzz_image).
void CheckPixelCount(const std::string& path, const std::string& format, uintmax_t file_size, int64_t width,
                     int64_t height) {
  const int64_t pixels = width * height;
  const int64_t limit = CurrentImageReadLimits().pixels;
  if (pixels > limit) {
    const int64_t side = int64_t(std::sqrt(double(limit)));
    throw MakeInputError(path, 0, "the image is {}x{}, more than the limit of {} pixels ({}x{})", width, height, limit,
                         side, side);
  }
  if ((format == "bmp" || format == "pnm") && pixels > int64_t(std::min<uintmax_t>(file_size, INT64_MAX / 512)) * 256)
    throw MakeInputError(path, 0, "cannot read image: its header claims {}x{} pixels, more than a {}-byte {} file can hold",
                         width, height, file_size, format == "bmp" ? "BMP" : "PNM");
}

// A reader's error message, its first line only: OpenImageIO reports one line per strip or
// tile that failed, thousands for a large file.
std::string FirstErrorLine(OIIO::ImageInput& in) {
  const std::string all = in.geterror();
  const size_t end = all.find('\n');
  if (end == std::string::npos) return all;
  const auto more = std::count(all.begin() + end, all.end(), '\n');
  return fmt::format("{} (and {} more such errors)", all.substr(0, end), more);
}

// decode(), with an exception from inside a decoder (a malformed file driving one of its
// containers past its limits: std::length_error, std::out_of_range, ...) reported as the
// file's error. An allocation failure goes on to NamingAllocationFailures.
template <typename F>
bool Decoding(const std::string& path, F decode) {
  try {
    return decode();
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw MakeInputError(path, 0, "cannot decode image: its decoder failed on malformed data ({})", e.what());
  }
}

RawImage ReadRaw(const std::string& path) {
  const uintmax_t file_size = CheckInputFile(path, "image", UINTMAX_MAX);
  RecordInputFile(path);
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  auto in = ext.size() > 1 ? OIIO::ImageInput::create(ext.substr(1)) : nullptr;
  if (!in || std::none_of(std::begin(kImageFormats), std::end(kImageFormats),
                          [&](const char* f) { return std::string(in->format_name()) == f; }))
    throw MakeInputError(path, 0, "not an image format that is read (by its extension: {})", kImageFormatList);
  const std::string format = in->format_name();
  if (format == "openexr") CheckExrHeaders(path, file_size);
  if (format == "bmp")
    if (const std::optional<ImageSize> claim = BmpClaimedSize(path))
      CheckPixelCount(path, format, file_size, claim->width, claim->height);
  OIIO::ImageSpec opened, config;
  // OpenImageIO 2.4 reads a BMP whose palette is all grey as one channel, but decodes a
  // run-length-coded one three bytes a pixel into that channel's rows: a wrong image, written
  // past its buffer. Read as the three channels a BMP has.
  if (format == "bmp") config.attribute("bmp:monochrome_detect", 0);
  if (!Decoding(path, [&] { return in->open(path, opened, config); }))
    throw MakeInputError(path, 0, "cannot read image: {}", FirstErrorLine(*in));
  if (std::string(in->format_name()) == "jpeg" && !JpegIsComplete(path))
    throw MakeInputError(path, 0, "cannot decode image: the JPEG data ends before its end-of-image marker (truncated)");
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    throw MakeInputError(path, 0, "image has no pixels");
  if (spec.depth != 1) throw MakeInputError(path, 0, "volume images (depth {}) are not supported", spec.depth);
  CheckPixelCount(path, format, file_size, spec.width, spec.height);
  const int64_t max_bytes = CurrentImageReadLimits().bytes;
  const int64_t bytes = int64_t(spec.width) * spec.height * spec.nchannels * int64_t(sizeof(float));
  if (bytes > max_bytes)
    throw MakeInputError(path, 0, "the {}x{} image with {} channels needs {} MiB as floats, more than the limit of {} MiB",
                         spec.width, spec.height, spec.nchannels, bytes >> 20, max_bytes >> 20);
  // OpenImageIO's readers decode up to 256 rows at once (a tiled file: whole rows of tiles)
  // into a buffer of their own, however few rows the image has: a 2-row EXR 16.8 million
  // pixels wide asked for 51 GB (found by fuzz_image).
  const int64_t rows_at_once = std::max<int64_t>(256, spec.tile_width > 0 ? spec.tile_height : 0);
  const int64_t chunk = int64_t(spec.width) * spec.nchannels * int64_t(sizeof(float)) * rows_at_once;
  if (chunk > max_bytes)
    throw MakeInputError(path, 0, "the image's rows are too wide to read: {} pixels with {} channels, {} MiB for the {} rows "
                         "its reader decodes at once, more than the limit of {} MiB",
                         spec.width, spec.nchannels, chunk >> 20, rows_at_once, max_bytes >> 20);
  RawImage r;
  r.integer_format = !spec.format.is_floating_point();
  r.image.width = spec.width;
  r.image.height = spec.height;
  for (int c = 0; c < spec.nchannels; ++c) r.image.channels.push_back(spec.channel_name(c));
  if (!Decoding(path, [&] { return ReadPixels(*in, r.image.pixels); })) throw MakeInputError(path, 0, "cannot decode image: {}", FirstErrorLine(*in));
  in->close();
  return r;
}

// f(), with an allocation failure turned into an error naming the file.
template <typename F>
auto NamingAllocationFailures(const std::string& path, F f) {
  try {
    return f();
  } catch (const std::bad_alloc&) {
    throw MakeInputError(path, 0, "not enough memory to load the image");
  }
}

// Three channels (grey replicated, alpha dropped), decoded from sRGB unless `raw`.
Image ToRgb(const RawImage& r, bool raw, const std::string& path) {
  const Image& src = r.image;
  Image out(src.width, src.height, {"R", "G", "B"});
  int n = src.NumChannels();
  bool decode = r.integer_format && !raw;
  for (int y = 0; y < src.height; ++y)
    for (int x = 0; x < src.width; ++x)
      for (int c = 0; c < 3; ++c) {
        float v = src.At(x, y, n >= 3 ? c : 0);
        if (!std::isfinite(v)) throw MakeInputError(path, 0, "pixel ({}, {}) is not finite", x, y);
        if (std::abs(v) > kMaxPixelValue)
          throw MakeInputError(path, 0, "pixel ({}, {}) holds {:g}, beyond the largest value read ({:g})", x, y, v,
                               kMaxPixelValue);
        out.At(x, y, c) = decode ? SrgbToLinear(v) : v;
      }
  return out;
}
}  // namespace

Image ReadImageAny(const std::string& path) {
  return NamingAllocationFailures(path, [&] { return ReadRaw(path).image; });
}

Image ReadImageRgb(const std::string& path, bool raw) {
  return NamingAllocationFailures(path, [&] { return ToRgb(ReadRaw(path), raw, path); });
}

namespace {
void Write(const std::string& path, const Image& image, OIIO::TypeDesc format, const char* compression,
           const std::vector<ImageAttribute>& attributes) {
  // The format follows the target's extension; the pixels go to a temporary file first.
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw InputError(fmt::format("{}: cannot create image file: {}", path, OIIO::geterror()));
  OIIO::ImageSpec spec(image.width, image.height, image.NumChannels(), format);
  spec.channelnames = image.channels;
  if (compression) spec.attribute("compression", compression);
  for (const ImageAttribute& a : attributes) {
    if (const std::string* text = std::get_if<std::string>(&a.value)) {
      spec.attribute(a.name, *text);
    } else if (const int* i = std::get_if<int>(&a.value)) {
      spec.attribute(a.name, *i);
    } else {
      const double d = std::get<double>(a.value);
      spec.attribute(a.name, OIIO::TypeDesc::DOUBLE, &d);
    }
  }
  WriteFileAtomically(path, [&](const std::string& temp) {
    if (!out->open(temp, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()) || !out->close())
      throw InputError(fmt::format("{}: cannot write image: {}", path, out->geterror()));
  });
}
}  // namespace

void WriteExr(const std::string& path, const Image& image, const std::vector<ImageAttribute>& attributes) {
  Write(path, image, OIIO::TypeDesc::FLOAT, "zip", attributes);
}

void WritePng(const std::string& path, const Image& display) { Write(path, display, OIIO::TypeDesc::UINT8, nullptr, {}); }

}  // namespace objektiv
