// Fuzz harness: image files through Objektiv's image reader, then the image in each role a
// scene gives it: a bitmap texture, an environment map, an aperture mask. The file is named
// with the extension its first bytes suggest, as a user's files are (TGA, which has no
// signature, for anything else).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "camera/aperture_mask.h"
#include "fuzz_support.h"
#include "io/image_io.h"
#include "scene/infinite_light.h"
#include "scene/texture.h"

namespace {

const char* ExtensionFor(std::string_view b) {
  struct Signature {
    std::string_view magic;
    size_t offset;
    const char* extension;
  };
  static constexpr Signature kSignatures[] = {
      {"\x89PNG", 0, ".png"},         {"\xff\xd8\xff", 0, ".jpg"},     {"v/1\x01", 0, ".exr"},
      {"#?", 0, ".hdr"},              {{"II*\0", 4}, 0, ".tif"},       {{"MM\0*", 4}, 0, ".tif"},
      {"BM", 0, ".bmp"},              {"GIF8", 0, ".gif"},             {"WEBP", 8, ".webp"},
      {"\xff\x4f\xff\x51", 0, ".j2k"}, {"jP  ", 4, ".jp2"},          {"ftypheic", 4, ".heic"},
      {"ftypavif", 4, ".avif"},        {"P", 0, ".ppm"}};
  for (const Signature& s : kSignatures)
    if (b.substr(std::min(s.offset, b.size()), s.magic.size()) == s.magic) return s.extension;
  return ".tga";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace objektiv;
  fuzz::Quiet();
  // 2048 x 2048 pixels and 256 MiB: a true image at the product's limits (16384 x 16384, 3 GiB
  // as RGB floats and again as a texture) is beyond libFuzzer's memory cap, and the fuzzer
  // cannot tell it from a file that only claims that size (image_io.h).
  static const bool limited = (SetImageReadLimits({int64_t(1) << 22, int64_t(256) << 20}), true);
  (void)limited;
  std::string_view bytes = fuzz::Bytes(data, size);
  std::string path = fuzz::WriteScratchFile(std::string("input") + ExtensionFor(bytes), bytes);
  fuzz::IgnoringInputErrors([&] {
    Image image = ReadImageRgb(path);
    for (float v : image.pixels)
      if (!(std::abs(v) <= kMaxPixelValue)) {
        std::fprintf(stderr, "accepted image with a pixel value not finite or beyond the limit\n");
        std::abort();
      }
    const Vec2f uvs[] = {{0.5f, 0.5f}, {0, 0}, {0.999f, 0.001f}, {-3.25f, 7.5f}};
    BitmapTexture texture(image, SpectrumUsage::kAlbedo, FilterMode::kBilinear, WrapMode::kMirror, Transform());
    for (Vec2f uv : uvs) texture.LookupRgb(uv);
    ApertureMask mask(image);
    mask.Transmittance(0.25f, -0.5f);
    EnvironmentMap envmap(std::move(image), 1, Transform());
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    for (Vec2f u : {Vec2f(0.1f, 0.3f), Vec2f(0.9f, 0.7f)})
      if (auto s = envmap.SampleLi(Vec3f(0.f), u, lambda)) envmap.PdfLi(s->wi);
  });
  return 0;
}
