// The `aov` integrator (render/aov.h): the first hit's depth, normals, position and uv beside an
// image that is the nested integrator's, bit for bit; its parse errors.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "io/scene_loader.h"
#include "base/color_space.h"
#include "render/aov.h"
#include "render/renderer.h"

namespace objektiv {
namespace {

// A wall at z = 0 filling the view of a camera 5 units away on the z axis (32 x 24 pixels).
std::string WallScene(const std::string& integrator) {
  return fmt::format(R"(<scene version="3.0.0">
  {}
  <sensor type="perspective">
    <float name="fov" value="30"/>
    <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="8"/></sampler>
    <film type="hdrfilm"><integer name="width" value="32"/><integer name="height" value="24"/><rfilter type="box"/></film>
  </sensor>
  <shape type="rectangle"><transform name="to_world"><scale x="10" y="10"/></transform><bsdf type="diffuse"/></shape>
  <emitter type="point"><point name="position" x="1" y="1" z="3"/><rgb name="intensity" value="5"/></emitter>
</scene>)",
                     integrator);
}

struct Rendered {
  Image image;
  std::vector<float> aovs;
  int channels = 0;
};

Rendered RenderScene(const std::string& xml) {
  RenderSetup setup = LoadSceneFromString(xml, "aov.xml", {});
  std::unique_ptr<Sampler> sampler = MakeSampler(setup.sampler);
  Film film(setup.film.width, setup.film.height, setup.film.crop, setup.film.filter);
  Rendered r;
  if (const auto* aov = dynamic_cast<const AovIntegrator*>(setup.integrator.get())) film.KeepAovs(r.channels = aov->AovChannels());
  RenderOptions options;
  options.spp_end = sampler->spp();
  Render(*setup.camera, *setup.integrator, *sampler, film, options);
  r.image = film.ToImage(*setup.film.color_space);
  r.aovs = film.Aovs();
  return r;
}

TEST(Aov, FirstHitValuesBesideTheNestedIntegratorsImage) {
  const Rendered plain = RenderScene(WallScene(R"(<integrator type="path"><integer name="max_depth" value="3"/></integrator>)"));
  const Rendered aov = RenderScene(WallScene(R"(<integrator type="aov">
      <string name="aovs" value="dd.y:depth,nn:sh_normal,gn:geo_normal,p:position,tex:uv"/>
      <integrator type="path"><integer name="max_depth" value="3"/></integrator></integrator>)"));
  ASSERT_EQ(aov.channels, 1 + 3 + 3 + 3 + 2);
  // The image: the nested integrator's, exactly (the AOVs draw no random numbers).
  EXPECT_EQ(plain.image.pixels, aov.image.pixels);
  // Every pixel: the distance from the ray's start (the near clip plane, 0.01 in front of the
  // camera) to the wall, the normal +z, the point on the wall (z 0).
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x) {
      const float* v = &aov.aovs[(size_t(y) * 32 + x) * aov.channels];
      const float px = v[7], py = v[8];
      EXPECT_NEAR(v[0], std::sqrt(25 + px * px + py * py) - 0.01, 1e-3) << x << "," << y;
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(v[1 + c], c == 2 ? 1 : 0, 1e-5);
        EXPECT_NEAR(v[4 + c], c == 2 ? 1 : 0, 1e-5);
      }
      EXPECT_NEAR(v[9], 0, 1e-5);
      EXPECT_GE(v[10], 0);
      EXPECT_LE(v[10], 1);
    }
  // The centre pixel looks straight at the wall.
  EXPECT_NEAR(aov.aovs[(size_t(12) * 32 + 16) * aov.channels], 4.99, 0.002);
}

// The albedo: a wall's reflectance toward the camera, as RGB relative to the colour space's
// white (the film keeps XYZ under D65): a grey diffuse wall, a red one, clear glass (all its
// light goes on, reflected or transmitted) and a gold conductor (its tint, below one). The
// image stays the nested integrator's, bit for bit.
TEST(Aov, AlbedoIsTheSurfacesReflectance) {
  auto wall = [](const std::string& bsdf) {
    std::string xml = WallScene(R"(<integrator type="aov"><string name="aovs" value="a:albedo"/>
      <integrator type="path"><integer name="max_depth" value="3"/></integrator></integrator>)");
    const std::string plain = "<bsdf type=\"diffuse\"/>";
    xml.replace(xml.find(plain), plain.size(), bsdf);
    const Rendered r = RenderScene(xml);
    EXPECT_EQ(r.channels, 3);
    Vec3d mean(0.0);
    for (size_t i = 0; i < r.aovs.size(); i += 3) {
      const Vec3f rgb = ColorSpace::Rec709().ToRGB(Vec3f(r.aovs[i], r.aovs[i + 1], r.aovs[i + 2]));
      mean += Vec3d(rgb.x, rgb.y, rgb.z) / double(r.aovs.size() / 3);
    }
    return mean;
  };
  const Vec3d grey = wall(R"(<bsdf type="diffuse"><rgb name="reflectance" value="0.5"/></bsdf>)");
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(grey[c], 0.5, 0.02) << c;
  const Vec3d red = wall(R"(<bsdf type="diffuse"><rgb name="reflectance" value="0.8, 0.1, 0.1"/></bsdf>)");
  EXPECT_NEAR(red.x, 0.8, 0.04);
  EXPECT_NEAR(red.y, 0.1, 0.03);
  EXPECT_NEAR(red.z, 0.1, 0.03);
  const Vec3d glass = wall(R"(<bsdf type="dielectric"/>)");
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(glass[c], 1.0, 0.03) << c;
  const Vec3d gold = wall(R"(<bsdf type="conductor"><string name="material" value="Au"/></bsdf>)");
  // Gold's reflectance near normal incidence in linear sRGB: the usual tables give about
  // (1.00, 0.77, 0.34) (Real-Time Rendering, 4th ed.); measured spectra and their routes to RGB
  // differ by a few hundredths.
  std::printf("gold albedo %.3f %.3f %.3f\n", gold.x, gold.y, gold.z);
  EXPECT_NEAR(gold.x, 1.00, 0.06);
  EXPECT_NEAR(gold.y, 0.77, 0.06);
  EXPECT_NEAR(gold.z, 0.34, 0.06);
  // The image with the albedo is the nested integrator's.
  const Rendered plain = RenderScene(WallScene(R"(<integrator type="path"><integer name="max_depth" value="3"/></integrator>)"));
  const Rendered with = RenderScene(WallScene(R"(<integrator type="aov"><string name="aovs" value="a:albedo"/>
      <integrator type="path"><integer name="max_depth" value="3"/></integrator></integrator>)"));
  EXPECT_EQ(plain.image.pixels, with.image.pixels);
}

// Through a real lens many camera samples start no ray (the rims and the stop stop them):
// they are left out of the average, which describes the rays that leave (counting them as 0
// read 7% of a wall's pixels short by up to a quarter at f/2).
TEST(Aov, ThroughALensOnlyTheRaysThatLeaveCount) {
  std::string xml = WallScene(R"(<integrator type="aov"><string name="aovs" value="d:depth"/>
      <integrator type="path"><integer name="max_depth" value="1"/></integrator></integrator>)");
  const std::string perspective = R"(<sensor type="perspective">
    <float name="fov" value="30"/>)";
  xml.replace(xml.find(perspective), perspective.size(), R"(<sensor type="realistic">
    <string name="lens" value="dgauss.50mm"/><float name="fnumber" value="2"/><float name="focus_distance" value="5"/>)");
  const Rendered r = RenderScene(xml);
  ASSERT_EQ(r.channels, 1);
  int empty = 0;
  for (size_t i = 0; i < r.aovs.size(); ++i) {
    if (r.aovs[i] == 0) {
      ++empty;
      continue;
    }
    // The wall 5 m from the camera, a little less from the front element; 1.14 at the corners
    // of a 50 mm lens's 36 x 24 mm film (a field angle of 23 degrees).
    EXPECT_GT(r.aovs[i], 4.9) << i;
    EXPECT_LT(r.aovs[i], 5.0 * 1.14) << i;
  }
  EXPECT_LT(empty, 5);
}

TEST(Aov, BadListsNameWhatIsWrong) {
  EXPECT_EQ(ParseAovs("a:depth, b : uv").size(), 2u);
  for (const char* bad : {"", "dd.y", "a:depth,", "a:foo", "a:depth,a:uv", ":depth"})
    EXPECT_THROW(ParseAovs(bad), std::invalid_argument) << bad;
  try {
    LoadSceneFromString(WallScene(R"(<integrator type="aov"><string name="aovs" value="d:dpeth"/></integrator>)"), "a.xml", {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a.xml:2: aovs: unknown AOV type 'dpeth' (known: depth, position, uv"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace objektiv
