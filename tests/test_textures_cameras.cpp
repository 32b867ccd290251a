// Textures (bitmap decoding, filtering, wrapping; checkerboard) and cameras.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "base/error.h"
#include "camera/camera.h"
#include "io/image_io.h"
#include "render_helpers.h"
#include "scene/texture.h"

namespace objektiv {
namespace {

TEST(Bitmap, DecodesSrgbAndFiltersBilinearly) {
  namespace fs = std::filesystem;
  fs::path png = fs::temp_directory_path() / "objektiv_texture_test.png";
  Image img(2, 1, {"R", "G", "B"});
  // Left texel sRGB 0.5 (linear 0.214), right texel sRGB 1.
  for (int c = 0; c < 3; ++c) {
    img.At(0, 0, c) = 0.5f;
    img.At(1, 0, c) = 1.f;
  }
  WritePng(png.string(), img);
  Image lin = ReadImageRgb(png.string(), false);
  EXPECT_NEAR(lin.At(0, 0, 0), SrgbToLinear(128 / 255.f), 1e-6);
  EXPECT_NEAR(lin.At(1, 0, 1), 1, 1e-6);
  Image raw = ReadImageRgb(png.string(), true);
  EXPECT_NEAR(raw.At(0, 0, 0), 128 / 255.f, 1e-6);

  BitmapTexture clamp(lin, SpectrumUsage::kAlbedo, FilterMode::kBilinear, WrapMode::kClamp, Transform());
  // Texel centres at u = 0.25 and 0.75; halfway between them, the average.
  EXPECT_NEAR(clamp.LookupRgb({0.25f, 0.5f}).x, lin.At(0, 0, 0), 1e-6);
  EXPECT_NEAR(clamp.LookupRgb({0.5f, 0.5f}).x, 0.5f * (lin.At(0, 0, 0) + 1), 1e-6);
  EXPECT_NEAR(clamp.LookupRgb({0.0f, 0.5f}).x, lin.At(0, 0, 0), 1e-6);  // clamped at the edge
  BitmapTexture repeat(lin, SpectrumUsage::kAlbedo, FilterMode::kBilinear, WrapMode::kRepeat, Transform());
  EXPECT_NEAR(repeat.LookupRgb({0.0f, 0.5f}).x, 0.5f * (lin.At(0, 0, 0) + 1), 1e-6);  // wraps to the right texel
  BitmapTexture nearest(lin, SpectrumUsage::kAlbedo, FilterMode::kNearest, WrapMode::kRepeat, Transform());
  EXPECT_NEAR(nearest.LookupRgb({0.6f, 0.5f}).x, 1, 1e-6);
  EXPECT_NEAR(nearest.LookupRgb({1.6f, 0.5f}).x, 1, 1e-6);
  fs::remove(png);
}

TEST(Bitmap, CoordinatesBeyondAnIntWrapExactly) {
  // Texture coordinates of 1e30 (a to_uv scale, or an OBJ 'vt') were converted to int before
  // wrapping: undefined behaviour, in practice INT_MIN and the wrong texel.
  Image img(3, 1, {"R", "G", "B"});
  for (int x = 0; x < 3; ++x)
    for (int c = 0; c < 3; ++c) img.At(x, 0, c) = float(x + 1);
  auto lookup = [&](WrapMode wrap, FilterMode filter, float u) {
    return BitmapTexture(img, SpectrumUsage::kUnbounded, filter, wrap, Transform()).LookupRgb({u, 0.5f}).x;
  };
  // u = 1e9: x = 3e9 texels, a multiple of 3 (and of 6), beyond an int: texel 0 when repeating
  // or mirroring, the last texel when clamping (the half-texel shift of bilinear filtering is
  // below a float's resolution there).
  for (FilterMode f : {FilterMode::kNearest, FilterMode::kBilinear}) {
    EXPECT_FLOAT_EQ(lookup(WrapMode::kRepeat, f, 1e9f), 1);
    EXPECT_FLOAT_EQ(lookup(WrapMode::kClamp, f, 1e9f), 3);
    EXPECT_FLOAT_EQ(lookup(WrapMode::kClamp, f, -1e30f), 1);
  }
  EXPECT_FLOAT_EQ(lookup(WrapMode::kMirror, FilterMode::kNearest, 1e9f), 1);
  EXPECT_TRUE(std::isfinite(lookup(WrapMode::kRepeat, FilterMode::kBilinear, 1e30f)));
  // No texel answers a NaN or infinite coordinate: NaN, which the film counts and drops.
  EXPECT_TRUE(std::isnan(lookup(WrapMode::kRepeat, FilterMode::kBilinear, std::nanf(""))));
  EXPECT_TRUE(std::isnan(lookup(WrapMode::kMirror, FilterMode::kNearest, INFINITY)));
  EXPECT_TRUE(std::isnan(lookup(WrapMode::kClamp, FilterMode::kNearest, INFINITY)));
}

TEST(Bitmap, MissingOrBrokenFilesAreInputErrors) {
  EXPECT_THROW(ReadImageRgb("/nonexistent/texture.png"), InputError);
  namespace fs = std::filesystem;
  fs::path bad = fs::temp_directory_path() / "objektiv_broken.png";
  std::ofstream(bad) << "not a png";
  EXPECT_THROW(ReadImageRgb(bad.string()), InputError);
  fs::remove(bad);
}

TEST(Checkerboard, AlternatesWithToUv) {
  auto a = std::make_shared<ConstantTexture>(Spectrum(0.1f)), b = std::make_shared<ConstantTexture>(Spectrum(0.9f));
  CheckerboardTexture c(a, b, Transform::Scale({4, 4, 1}));
  SampledWavelengths w = SampledWavelengths::SampleVisible(0.5f);
  // With to_uv scale 4 the squares are 1/8 wide.
  EXPECT_FLOAT_EQ(c.Evaluate({0.01f, 0.01f}, w)[0], 0.1f);
  EXPECT_FLOAT_EQ(c.Evaluate({0.13f, 0.01f}, w)[0], 0.9f);
  EXPECT_FLOAT_EQ(c.Evaluate({0.13f, 0.13f}, w)[0], 0.1f);
  EXPECT_FLOAT_EQ(c.Evaluate({-0.01f, 0.01f}, w)[0], 0.9f);
  // Far beyond an int (undefined behaviour when converted): every float there is even.
  EXPECT_FLOAT_EQ(c.Evaluate({1e30f, 0.13f}, w)[0], 0.9f);
  EXPECT_FLOAT_EQ(c.Evaluate({-1e30f, 0.01f}, w)[0], 0.1f);
}

std::string CameraScene(const std::string& sensor_type, const std::string& extra) {
  return fmt::format(R"(<scene version="3.0.0">
  <integrator type="path"><integer name="max_depth" value="3"/></integrator>
  <sensor type="{}">
    <float name="fov" value="40"/>{}
    <transform name="to_world"><lookat origin="0, 1, 4" target="0, 0.5, 0" up="0, 1, 0"/></transform>
    <sampler type="sobol"><integer name="sample_count" value="16"/></sampler>
    <film type="hdrfilm"><integer name="width" value="32"/><integer name="height" value="24"/><rfilter type="box"/></film>
  </sensor>
  <emitter type="constant"><float name="radiance" value="0.3"/></emitter>
  <shape type="sphere"><float name="radius" value="0.5"/><point name="center" y="0.5"/>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.8, 0.3, 0.2"/></bsdf></shape>
  <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="-90"/><scale value="5"/></transform>
    <bsdf type="diffuse"><texture type="checkerboard" name="reflectance"/></bsdf></shape>
  <emitter type="point"><point name="position" x="1" y="3" z="2"/><float name="intensity" value="10"/></emitter>
</scene>)",
                     sensor_type, extra);
}

TEST(Cameras, ThinLensWithZeroApertureIsThePinhole) {
  auto pin = test::RenderXml(CameraScene("perspective", ""));
  auto thin = test::RenderXml(CameraScene(
      "thinlens", R"(<float name="aperture_radius" value="0"/><float name="focus_distance" value="3"/>)"));
  double diff = 0, sum = 0;
  for (size_t i = 0; i < pin.image.pixels.size(); ++i) {
    diff += std::abs(pin.image.pixels[i] - thin.image.pixels[i]);
    sum += pin.image.pixels[i];
  }
  EXPECT_LT(diff / sum, 1e-4);
}

TEST(Cameras, ThinLensFocusesItsFocusPlane) {
  // All rays through one film point meet at the focus distance, wherever they cross the lens.
  ThinLensCamera cam(Transform(), 64, 64, 40, FovAxis::kX, 0.0f, 1e4f, 0.05f, 2.5f, 6, 10);
  SampledWavelengths w = SampledWavelengths::SampleVisible(0.5f);
  Vec3f first;
  for (int i = 0; i < 20; ++i) {
    CameraSample s{Vec2f(17.3f, 40.1f), Vec2f((i * 0.37f) - std::floor(i * 0.37f), (i * 0.61f) - std::floor(i * 0.61f))};
    auto r = cam.GenerateRay(s, w);
    ASSERT_TRUE(r);
    Vec3f p = r->ray.o + r->ray.d * ((2.5f - r->ray.o.z) / r->ray.d.z);
    if (i == 0) first = p;
    EXPECT_NEAR(p.x, first.x, 1e-5);
    EXPECT_NEAR(p.y, first.y, 1e-5);
  }
}

TEST(Cameras, PerspectiveFieldOfViewAndOrthographicRays) {
  SampledWavelengths w = SampledWavelengths::SampleVisible(0.5f);
  PerspectiveCamera p(Transform(), 200, 100, 60, FovAxis::kX, 0.f, 1e4f);
  // The left edge of the image looks 30 degrees to the left (camera +x, as Mitsuba).
  auto edge = p.GenerateRay({Vec2f(0, 50), Vec2f(0.5f, 0.5f)}, w);
  EXPECT_NEAR(std::atan2(edge->ray.d.x, edge->ray.d.z), Radians(30), 1e-5);
  OrthographicCamera o(Transform::Scale({2, 2, 1}), 100, 50, 0.f, 1e4f);
  auto a = o.GenerateRay({Vec2f(0, 0), Vec2f(0.5f, 0.5f)}, w);
  auto b = o.GenerateRay({Vec2f(100, 50), Vec2f(0.5f, 0.5f)}, w);
  EXPECT_EQ(a->ray.d, b->ray.d);
  EXPECT_NEAR(a->ray.o.x - b->ray.o.x, 4, 1e-5);  // [-1, 1] scaled by 2
  EXPECT_NEAR(a->ray.o.y - b->ray.o.y, 2, 1e-5);  // aspect 2: [-1/2, 1/2] scaled by 2
}

}  // namespace
}  // namespace objektiv
