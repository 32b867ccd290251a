// Hostile and broken image files: sizes beyond the limits are refused before the pixels are
// allocated, a file shorter than its header claims fails having touched little memory,
// truncation is an error in every format read, and running out of memory names the file.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "base/error.h"
#include "io/image_io.h"
#include "sanitizer_build.h"

namespace objektiv {
namespace {

namespace fs = std::filesystem;

fs::path TempDir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("objektiv_bad_images_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string ReadBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void WriteBytes(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

// A w x h image with `channels` channels of `format`, written by OpenImageIO (a checker).
void WriteTestImage(const fs::path& p, int w, int h, int channels, OIIO::TypeDesc format) {
  std::vector<float> pixels(size_t(w) * h * channels);
  for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = float((i / channels + i / channels / w) % 2);
  auto out = OIIO::ImageOutput::create(p.string());
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(p.string(), OIIO::ImageSpec(w, h, channels, format)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
  ASSERT_TRUE(out->close());
}

// A 1 x 1 uncompressed TIFF whose header then claims w x h (TIFF has no checksums): the
// width and height tags of its first directory rewritten.
void WriteTiffClaiming(const fs::path& p, uint32_t w, uint32_t h, int channels) {
  WriteTestImage(p, 1, 1, channels, OIIO::TypeDesc::UINT8);
  std::string b = ReadBytes(p);
  ASSERT_EQ(b.substr(0, 2), "II");
  auto u16 = [&](size_t at) { return uint16_t(uint8_t(b[at]) | uint8_t(b[at + 1]) << 8); };
  uint32_t ifd;
  std::memcpy(&ifd, &b[4], 4);
  for (int e = 0; e < u16(ifd); ++e) {
    size_t entry = ifd + 2 + 12 * size_t(e);
    uint16_t tag = u16(entry), type = u16(entry + 2);
    if (tag != 256 && tag != 257) continue;
    uint32_t value = tag == 256 ? w : h;
    ASSERT_TRUE(type == 3 || type == 4);  // SHORT or LONG
    if (type == 3) {
      ASSERT_LE(value, 65535u);
    }
    std::memcpy(&b[entry + 8], &value, type == 3 ? 2 : 4);
  }
  WriteBytes(p, b);
}

template <typename F>
void ExpectImageError(F f, const fs::path& p, const std::string& part) {
  try {
    f();
    ADD_FAILURE() << p << ": no error, expected one containing '" << part << "'";
  } catch (const InputError& e) {
    std::string msg = e.what();
    EXPECT_EQ(msg.rfind(p.string() + ": ", 0), 0u) << msg;
    EXPECT_NE(msg.find(part), std::string::npos) << msg;
  }
}

long PeakRssKiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

TEST(BadImages, SizesBeyondTheLimitsAreRefused) {
  fs::path dir = TempDir("limits");
  // 100000 x 100000 ended in std::bad_alloc with no file name (here 60000 x 60000, what a
  // 1 x 1 TIFF's short fields hold).
  fs::path huge = dir / "huge.tif";
  WriteTiffClaiming(huge, 60000, 60000, 1);
  ExpectImageError([&] { ReadImageRgb(huge.string()); }, huge, "60000x60000, more than the limit of 268435456 pixels");
  // Within the pixel limit, beyond the byte limit: 16384 x 16384 with 5 channels is 5 GiB of floats.
  fs::path wide = dir / "five.tif";
  WriteTiffClaiming(wide, 16384, 16384, 5);
  ExpectImageError([&] { ReadImageAny(wide.string()); }, wide, "needs 5120 MiB as floats, more than the limit of 4096 MiB");
}

// The fuzz harness lowers the limits for its process (a true 16384 x 16384 image is beyond
// libFuzzer's memory cap); they can be lowered, never raised beyond the constants.
TEST(BadImages, LimitsCanBeLoweredNotRaised) {
  fs::path dir = TempDir("lowered");
  fs::path p = dir / "claim.tif";
  WriteTiffClaiming(p, 4096, 4096, 3);
  SetImageReadLimits({int64_t(1) << 22, int64_t(256) << 20});
  ExpectImageError([&] { ReadImageRgb(p.string()); }, p, "4096x4096, more than the limit of 4194304 pixels (2048x2048)");
  SetImageReadLimits({int64_t(1) << 26, int64_t(64) << 20});
  ExpectImageError([&] { ReadImageRgb(p.string()); }, p, "needs 192 MiB as floats, more than the limit of 64 MiB");
  SetImageReadLimits({int64_t(1) << 40, -1});
  EXPECT_EQ(CurrentImageReadLimits().pixels, kMaxImagePixels);
  EXPECT_EQ(CurrentImageReadLimits().bytes, kMaxImageBytes);
  // Within the limits, with no data for the rows after the first strip: OpenImageIO filled
  // them with zeros, reporting success with the errors pending.
  ExpectImageError([&] { ReadImageRgb(p.string()); }, p,
                   "cannot decode image: TIFFReadRawStrip failed reading line y=32,z=0: Incorrect count for "
                   "\"StripByteCounts\"; tag ignored");
}

// Finite values near the float maximum overflowed the environment map's sums and bilinear
// blends into Inf and NaN (found by fuzz_image): refused as not finite values are.
TEST(BadImages, PixelValuesBeyondTheLimitAreRefused) {
  fs::path dir = TempDir("values");
  for (float v : {3.4e38f, -2e21f, INFINITY}) {
    fs::path p = dir / "big.exr";
    auto out = OIIO::ImageOutput::create(p.string());
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(p.string(), OIIO::ImageSpec(2, 1, 3, OIIO::TypeDesc::FLOAT)));
    const float pixels[6] = {0.5f, 0.5f, 0.5f, 1, v, 2};
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels));
    ASSERT_TRUE(out->close());
    ExpectImageError([&] { ReadImageRgb(p.string()); }, p, std::isinf(v) ? "pixel (1, 0) is not finite" : "pixel (1, 0) holds");
  }
  fs::path p = dir / "fine.exr";
  auto out = OIIO::ImageOutput::create(p.string());
  ASSERT_TRUE(out->open(p.string(), OIIO::ImageSpec(1, 1, 3, OIIO::TypeDesc::FLOAT)));
  const float pixels[3] = {1e20f, -1e20f, 1.6e9f};
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels));
  ASSERT_TRUE(out->close());
  EXPECT_EQ(ReadImageRgb(p.string()).At(0, 0, 0), 1e20f);
}

TEST(BadImages, AShortFileClaimingAHugeImageFailsEarly) {
  // Repro 06: 68 bytes whose header claims 12000 x 12000 took the process to 1.8 GB (the
  // whole float image allocated and cleared) before the decoder found no data.
  const fs::path png = fs::path(OBJEKTIV_FUZZ_DIR) / "06-png-header-12000x12000.png";
  const long before = PeakRssKiB();
  ExpectImageError([&] { ReadImageRgb(png.string()); }, png, "cannot decode image");
  if (!kAddressSanitizer) {  // it writes the shadow of the reserved storage (an eighth of it)
    EXPECT_LT(PeakRssKiB() - before, 100 * 1024) << "peak memory grew by " << (PeakRssKiB() - before) / 1024 << " MiB";
  }
}

TEST(BadImages, TruncatedFilesAreErrorsInEveryFormat) {
  fs::path dir = TempDir("truncated");
  for (const char* ext : {"png", "jpg", "exr", "hdr", "tif", "tga", "bmp", "ppm", "webp"}) {
    fs::path full = dir / (std::string("full.") + ext), cut = dir / (std::string("cut.") + ext);
    const bool is_float = std::string(ext) == "exr" || std::string(ext) == "hdr";
    WriteTestImage(full, 64, 48, 3, is_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    EXPECT_NO_THROW(ReadImageRgb(full.string())) << ext;
    std::string bytes = ReadBytes(full);
    WriteBytes(cut, bytes.substr(0, bytes.size() * 3 / 4));
    // libjpeg fills a cut JPEG's missing rows with grey and reports success.
    ExpectImageError([&] { ReadImageRgb(cut.string()); }, cut, "cannot ");
  }
  // A JPEG followed by other data (as some cameras append) is complete.
  fs::path trailing = dir / "trailing.jpg";
  WriteBytes(trailing, ReadBytes(dir / "full.jpg") + std::string("\xff\xd8 appended data, not JPEG", 26));
  EXPECT_NO_THROW(ReadImageRgb(trailing.string()));
}

TEST(BadImages, ExrAttributeSizesAreCheckedBeforeOpenExrAllocates) {
  fs::path dir = TempDir("exr");
  fs::path good = dir / "tagged.exr", bad = dir / "bad.exr";
  {
    OIIO::ImageSpec spec(8, 8, 3, OIIO::TypeDesc::HALF);
    spec.attribute("Software", "objektiv test");
    auto out = OIIO::ImageOutput::create(good.string());
    std::vector<float> pixels(8 * 8 * 3, 0.5f);
    ASSERT_TRUE(out->open(good.string(), spec) && out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) && out->close());
  }
  EXPECT_NO_THROW(ReadImageRgb(good.string()));
  // A mutated size field (found by fuzzing): OpenEXR took 2 GiB for the attribute before it
  // found the file too short.
  std::string bytes = ReadBytes(good);
  size_t at = bytes.find(std::string("Software\0string\0", 16));
  ASSERT_NE(at, std::string::npos);
  const uint32_t huge = 0x7f000041;
  std::memcpy(&bytes[at + 16], &huge, 4);
  WriteBytes(bad, bytes);
  const long before = PeakRssKiB();
  ExpectImageError([&] { ReadImageRgb(bad.string()); }, bad, "attribute 'Software' larger than the file");
  EXPECT_LT(PeakRssKiB() - before, 100 * 1024);
  // A multi-part file (its headers in a row) passes the check; part 0 is read.
  fs::path multi = dir / "multi.exr";
  {
    OIIO::ImageSpec specs[2] = {OIIO::ImageSpec(4, 4, 3, OIIO::TypeDesc::FLOAT), OIIO::ImageSpec(2, 2, 1, OIIO::TypeDesc::FLOAT)};
    specs[1].full_width = specs[1].full_height = 4;  // the parts share one display window
    auto out = OIIO::ImageOutput::create(multi.string());
    ASSERT_TRUE(out->supports("multiimage"));
    ASSERT_TRUE(out->open(multi.string(), 2, specs)) << out->geterror();
    std::vector<float> a(4 * 4 * 3, 0.25f), b(2 * 2, 1.f);
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, a.data()));
    ASSERT_TRUE(out->open(multi.string(), specs[1], OIIO::ImageOutput::AppendSubimage));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, b.data()) && out->close());
  }
  Image m = ReadImageRgb(multi.string());
  EXPECT_EQ(m.width, 4);
  EXPECT_FLOAT_EQ(m.At(3, 3, 2), 0.25f);
}

// A run-length-coded 8-bit BMP (RLE8) of width x height (the header's height field as given:
// negative for rows top-down) whose rows are runs of `rows[y]` palette entries, y from the
// bottom as stored; palette entry i is (red, green, blue) = (i, 255 - i, 7), or (i, i, i) if `grey`.
std::string RleBmp(int32_t width, int32_t height, const std::vector<std::vector<std::pair<uint8_t, uint8_t>>>& rows,
                   bool grey = false) {
  auto le = [](uint32_t v, int bytes) {
    std::string s;
    for (int i = 0; i < bytes; ++i) s += char((v >> (8 * i)) & 0xff);
    return s;
  };
  std::string data;
  for (size_t y = 0; y < rows.size(); ++y) {
    for (auto [count, index] : rows[y]) data += std::string{char(count), char(index)};
    data += std::string(y + 1 < rows.size() ? "\0\0" : "\0\1", 2);  // end of line, of the bitmap
  }
  std::string palette;
  for (int i = 0; i < 256; ++i)  // stored blue, green, red
    palette += grey ? std::string{char(i), char(i), char(i), '\0'} : std::string{char(7), char(255 - i), char(i), '\0'};
  const std::string info = le(40, 4) + le(uint32_t(width), 4) + le(uint32_t(height), 4) + le(1, 2) + le(8, 2) +
                           le(1, 4) /* RLE8 */ + le(uint32_t(data.size()), 4) + le(2835, 4) + le(2835, 4) + le(0, 4) + le(0, 4);
  const uint32_t offset = 14 + uint32_t(info.size() + palette.size());
  return "BM" + le(offset + uint32_t(data.size()), 4) + le(0, 4) + le(offset, 4) + info + palette + data;
}

TEST(BadImages, RunLengthBmpClaimIsCheckedBeforeOpening) {
  fs::path dir = TempDir("bmp_rle");
  // A good one reads: 3 x 2, bottom row entries 200 200 10, top row 50 50 50.
  fs::path good = dir / "good.bmp";
  WriteBytes(good, RleBmp(3, 2, {{{2, 200}, {1, 10}}, {{3, 50}}}));
  Image g = ReadImageRgb(good.string(), /*raw=*/true);
  ASSERT_EQ(g.width, 3);
  ASSERT_EQ(g.height, 2);
  EXPECT_NEAR(g.At(0, 1, 0), 200 / 255.f, 1e-6f);
  EXPECT_NEAR(g.At(2, 1, 1), 245 / 255.f, 1e-6f);
  EXPECT_NEAR(g.At(1, 0, 0), 50 / 255.f, 1e-6f);
  EXPECT_NEAR(g.At(1, 0, 2), 7 / 255.f, 1e-6f);
  // With a grey palette OpenImageIO 2.4 made it one channel and wrote three bytes a pixel
  // into its rows (the bottom row read 200 200 200, past the row's end).
  fs::path grey = dir / "grey.bmp";
  WriteBytes(grey, RleBmp(3, 2, {{{2, 200}, {1, 10}}, {{3, 50}}}, /*grey=*/true));
  Image gr = ReadImageRgb(grey.string(), /*raw=*/true);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(gr.At(1, 1, c), 200 / 255.f, 1e-6f);
    EXPECT_NEAR(gr.At(2, 1, c), 10 / 255.f, 1e-6f);
    EXPECT_NEAR(gr.At(0, 0, c), 50 / 255.f, 1e-6f);
  }
  // OpenImageIO decodes RLE inside open(), into width * height bytes multiplied in an int:
  // 50000 x 50000 overflowed to a negative size (std::length_error, an abort, found by
  // fuzz_image), a top-down -50000 too; 16000 x 16000 (within the pixel limit, beyond 256
  // pixels a byte of this file) took 256 MB before anything checked the claim.
  fs::path huge = dir / "huge.bmp", top_down = dir / "top_down.bmp", large = dir / "large.bmp";
  WriteBytes(huge, RleBmp(50000, 50000, {{{255, 1}}}));
  WriteBytes(top_down, RleBmp(50000, -50000, {{{255, 1}}}));
  WriteBytes(large, RleBmp(16000, 16000, {{{255, 1}}}));
  const long before = PeakRssKiB();
  ExpectImageError([&] { ReadImageRgb(huge.string()); }, huge, "50000x50000, more than the limit of 268435456 pixels");
  ExpectImageError([&] { ReadImageRgb(top_down.string()); }, top_down, "50000x50000, more than the limit");
  ExpectImageError([&] { ReadImageRgb(large.string()); }, large,
                   "its header claims 16000x16000 pixels, more than a " + std::to_string(fs::file_size(large)) +
                       "-byte BMP file can hold");
  if (!kAddressSanitizer) {
    EXPECT_LT(PeakRssKiB() - before, 100 * 1024);
  }
  // The fuzzing finding itself, through the replay folder and the command line too.
  const fs::path finding = fs::path(OBJEKTIV_FUZZ_DIR) / "13-bmp-rle8-50000x50000.bmp";
  ExpectImageError([&] { ReadImageRgb(finding.string()); }, finding, "more than the limit");
}

TEST(BadImages, FormatsOutsideTheListAreRefused) {
  fs::path dir = TempDir("formats");
  // Read by its extension only: a movie or a Maya IFF (whose reader takes a cut file without
  // complaint) is not tried, nor is any other reader when the extension is unknown.
  for (const char* name : {"clip.mp4", "image.iff", "noextension", "image.unknown"}) {
    WriteTestImage(dir / "real.png", 4, 4, 3, OIIO::TypeDesc::UINT8);
    fs::copy_file(dir / "real.png", dir / name);
    ExpectImageError([&] { ReadImageRgb((dir / name).string()); }, dir / name, "not an image format that is read");
  }
  WriteTestImage(dir / "upper.PNG", 4, 4, 3, OIIO::TypeDesc::UINT8);
  EXPECT_NO_THROW(ReadImageRgb((dir / "upper.PNG").string()));
}

TEST(BadImages, RunningOutOfMemoryNamesTheFile) {
  if (kAddressSanitizer) GTEST_SKIP() << "AddressSanitizer reserves more address space than the limit set here";
  // 16384 x 16384 x 3 floats (3 GiB) is within the limits, but not within 1 GiB of address
  // space more than the process has: std::bad_alloc, which said nothing about the file.
  fs::path dir = TempDir("memory");
  fs::path big = dir / "big.tif";
  WriteTiffClaiming(big, 16384, 16384, 3);
  rlimit old{};
  getrlimit(RLIMIT_AS, &old);
  std::ifstream status("/proc/self/statm");
  size_t pages = 0;
  status >> pages;
  rlimit low = old;
  low.rlim_cur = rlim_t(pages) * 4096 + (rlim_t(1) << 30);
  ASSERT_EQ(setrlimit(RLIMIT_AS, &low), 0);
  try {
    ReadImageRgb(big.string());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(big.string() + ": not enough memory"), std::string::npos) << e.what();
  } catch (...) {
    ADD_FAILURE() << "not an InputError";
  }
  setrlimit(RLIMIT_AS, &old);
}

}  // namespace
}  // namespace objektiv
