// The light tracer (render/light_tracer.h, integrator `ptracer`): the same image as the path
// tracer where both see everything (diffuse rooms under every kind of light, through the ideal
// cameras and a real lens), the white furnace, the closed-form energy that a glass sphere lets
// through, and a caustic against a long path-traced reference.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include <fmt/format.h>

#include "base/error.h"
#include "base/rng.h"
#include "image_estimates.h"
#include "render_helpers.h"
#include "room_scene.h"
#include "sanitizer_build.h"
#include "scene/analytic_shape.h"
#include "scene/infinite_light.h"
#include "scene/texture.h"

namespace objektiv {
namespace {

using test::RenderXml;

using test::Estimate;
using test::Estimated;
using test::ExpectSameImage;
using test::kSize;

// The room (room_scene.h) rendered by the integrator of type `integrator`.
std::string Room(const std::string& integrator, const std::string& sensor, const std::string& light, int spp,
                 int seed) {
  return test::DiffuseRoom("<integrator type=\"" + integrator + "\"/>", sensor, light, spp, seed);
}

const char* kPerspective = R"(<sensor type="perspective"><float name="fov" value="45"/>)";

// The light tracer's image equals the path tracer's, telling a 3% error.
void ExpectSameAsPathTracer(const std::string& sensor, const std::string& light, int path_spp, int light_spp) {
  const Estimate path = Estimated([&](int seed) { return Room("path", sensor, light, path_spp, seed); });
  const Estimate ptracer = Estimated([&](int seed) { return Room("ptracer", sensor, light, light_spp, seed); });
  ExpectSameImage(path, ptracer, 0.03, light);
}

TEST(LightTracer, AreaLightRoomMatchesThePathTracer) {
  // The light faces the ceiling (the camera sees its dark back): the blocks' light is all
  // scattered, none seen straight from the emitter, whose pixels would outweigh the rest.
  ExpectSameAsPathTracer(kPerspective, R"(<shape type="rectangle">
    <transform name="to_world"><scale x="0.3" y="0.2"/><rotate x="1" angle="-90"/><translate y="1.2" z="-0.6"/></transform>
    <emitter type="area"><rgb name="radiance" value="12, 10, 8"/></emitter></shape>)",
                         64, 64);
}

TEST(LightTracer, PointSpotAndDirectionalLightsMatchThePathTracer) {
  ExpectSameAsPathTracer(kPerspective, R"(<emitter type="point"><point name="position" x="-0.3" y="1.6" z="0.2"/>
    <rgb name="intensity" value="2, 2, 1.5"/></emitter>)", 16, 32);
  ExpectSameAsPathTracer(kPerspective, R"(<emitter type="spot"><rgb name="intensity" value="6, 6, 6"/>
    <float name="cutoff_angle" value="35"/><float name="beam_width" value="20"/>
    <transform name="to_world"><lookat origin="0.5, 1.9, 0.5" target="0, 0, -0.3"/></transform></emitter>)", 16, 32);
  ExpectSameAsPathTracer(kPerspective, R"(<emitter type="directional"><vector name="direction" x="0.3" y="-1" z="-0.5"/>
    <rgb name="irradiance" value="3, 3, 3"/></emitter>)", 16, 32);
}

TEST(LightTracer, ThinLensAndRealLensMatchThePathTracer) {
  SKIP_UNDER_SANITIZERS("CameraImportance.PinholeAndThinLensLightTracedMatchTheirCameraRays and "
                        "CameraImportance.LightTracedImageMatchesTheCameraRays");
  const char* light = R"(<emitter type="point"><point name="position" x="-0.3" y="1.6" z="0.2"/>
    <rgb name="intensity" value="2, 2, 2"/></emitter>)";
  ExpectSameAsPathTracer(R"(<sensor type="thinlens"><float name="fov" value="45"/>
    <float name="aperture_radius" value="0.1"/><float name="focus_distance" value="3"/>)", light, 16, 32);
  ExpectSameAsPathTracer(R"(<sensor type="realistic"><string name="lens" value="dgauss.50mm"/>
    <float name="fnumber" value="4"/><float name="focus_distance" value="3"/>
    <float name="sensor_width" value="24"/><float name="sensor_height" value="24"/>)", light, 16, 128);
}

// Under water behind a flat port (tests/data/flat-port-dgauss.lens): light paths carry flux,
// which is the same on both sides of the port, camera paths radiance, which the port divides by
// 1.333^2; both give the same image (the light tracer's importance once took the 1 / n^2 too:
// its image came out 0.56 of the path tracer's).
TEST(LightTracer, RealLensUnderWaterMatchesThePathTracer) {
  SKIP_UNDER_SANITIZERS("ObjectMedium.TheCameraSeesTheScenesRadianceOverNSquared");
  const char* light = R"(<emitter type="point"><point name="position" x="-0.3" y="1.6" z="0.2"/>
    <rgb name="intensity" value="2, 2, 2"/></emitter>)";
  ExpectSameAsPathTracer(fmt::format(R"(<sensor type="realistic"><string name="lens" value="{}/flat-port-dgauss.lens"/>
    <float name="fnumber" value="4"/><float name="focus_distance" value="3"/>
    <float name="sensor_width" value="24"/><float name="sensor_height" value="24"/>)", OBJEKTIV_TEST_DATA_DIR), light, 16, 128);
}

// A glass ball (index 1.5) on a floor under a spherical lamp, seen from above, framing its
// shadow: the caustic in the shadow is found by camera paths (through the glass to the lamp: fireflies) or,
// with `caustics`, by light paths; the two images agree.
std::string BallUnderLamp(bool caustics, int spp, int seed) {
  return fmt::format(R"(<scene version="3.0.0">
  <integrator type="path"><boolean name="caustics" value="{}"/></integrator>
  <sensor type="perspective"><float name="fov" value="24"/>
    <transform name="to_world"><lookat origin="0.7, 2.2, 0.9" target="0.35, 0, 0.22" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="{}"/><integer name="seed" value="{}"/></sampler>
    <film type="hdrfilm"><integer name="width" value="{}"/><integer name="height" value="{}"/><rfilter type="box"/></film>
  </sensor>
  <shape type="rectangle"><transform name="to_world"><scale value="3"/><rotate x="1" angle="-90"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.6, 0.5, 0.4"/></bsdf></shape>
  <shape type="sphere"><point name="center" x="0" y="0.35" z="0"/><float name="radius" value="0.35"/>
    <bsdf type="dielectric"><float name="int_ior" value="1.5"/></bsdf></shape>
  <shape type="sphere"><point name="center" x="-0.9" y="1.5" z="-0.4"/><float name="radius" value="0.25"/>
    <emitter type="area"><rgb name="radiance" value="20, 20, 20"/></emitter></shape>
</scene>)",
                     caustics, spp, seed, kSize, kSize);
}

TEST(LightTracer, PathTracerWithLightTracedCausticsConvergesToThePathTracer) {
  const Estimate path = Estimated([](int seed) { return BallUnderLamp(false, 256, seed); });
  const Estimate caustics = Estimated([](int seed) { return BallUnderLamp(true, 128, seed); });
  // A wrong split of the paths would miss or double the caustic: most of the image's light.
  ExpectSameImage(path, caustics, 0.05, "glass ball under a lamp");
}

// The rays a light starts carry its power: the mean of Flux() over many is the light's closed-
// form power (W, for emission 1 at every wavelength).
double MeanFlux(const Light& light) {
  PCG32 rng(3, 7);
  const SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
  constexpr int kRays = 200000;
  double sum = 0;
  for (int i = 0; i < kRays; ++i) {
    const Vec2f u_pos(rng.UniformFloat(), rng.UniformFloat()), u_dir(rng.UniformFloat(), rng.UniformFloat());
    if (const std::optional<LightLeSample> s = light.SampleLe(u_pos, u_dir, lambda)) sum += s->Flux()[0];
  }
  return sum / kRays;
}

TEST(LightTracer, LightsStartRaysCarryingTheirPower) {
  const Spectrum one(1.f);
  EXPECT_NEAR(MeanFlux(PointLight(Vec3f(1, 2, 3), one)), 4 * kPi, 1e-3);
  // A spot without falloff (beam width = cutoff): its cone's solid angle.
  const float cutoff = 30;
  EXPECT_NEAR(MeanFlux(SpotLight(Vec3f(0.f), Vec3f(0, -1, 0), one, cutoff, cutoff)),
              2 * kPi * (1 - std::cos(Radians(cutoff))), 1e-3);
  // Lights at infinity: through the disc across the scene's bounding sphere (radius R).
  Bounds3f bounds;
  bounds.Extend(Vec3f(-1, -2, -3));
  bounds.Extend(Vec3f(3, 2, 1));
  const double R = bounds.Radius();
  DirectionalLight sun(Vec3f(0.3f, -1, 0.2f), one);
  sun.Preprocess(bounds);
  EXPECT_NEAR(MeanFlux(sun) / (kPi * R * R), 1, 1e-4);
  ConstantEnvironment sky(one);
  sky.Preprocess(bounds);
  EXPECT_NEAR(MeanFlux(sky) / (kPi * R * R * 4 * kPi), 1, 1e-4);
  // Area lights: pi L A per side.
  const Sphere ball(Vec3f(0.5f, 0, 0), 0.7f, false, Transform());
  const auto radiance = std::make_shared<ConstantTexture>(one);
  EXPECT_NEAR(MeanFlux(AreaLight(&ball, radiance, false, 1)) / (kPi * ball.Area()), 1, 1e-4);
  EXPECT_NEAR(MeanFlux(AreaLight(&ball, radiance, true, 1)) / (2 * kPi * ball.Area()), 1, 1e-4);
}

TEST(LightTracer, CamerasThatLightCannotReachAreRefused) {
  for (const char* integrator : {R"(<integrator type="ptracer"/>)",
                                 R"(<integrator type="path"><boolean name="caustics" value="true"/></integrator>)"}) {
    const std::string xml = fmt::format(R"(<scene version="3.0.0">
  {}
  <sensor type="orthographic"><film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film></sensor>
  <emitter type="point"><point name="position" x="0" y="0" z="1"/></emitter>
</scene>)",
                                        integrator);
    try {
      RenderXml(xml);
      ADD_FAILURE() << "accepted: " << integrator;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("test.xml:2"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("orthographic"), std::string::npos) << e.what();
    }
  }
}

TEST(LightTracer, WhiteFurnace) {
  // A white diffuse sphere under a constant sky reads the sky's 1 everywhere, through its many
  // bounces of light paths started at infinity.
  const auto r = RenderXml(R"(<scene version="3.0.0">
  <integrator type="ptracer"/>
  <sensor type="perspective"><float name="fov" value="30"/>
    <transform name="to_world"><lookat origin="0, 0, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="128"/></sampler>
    <film type="hdrfilm"><integer name="width" value="24"/><integer name="height" value="24"/><rfilter type="box"/></film>
  </sensor>
  <emitter type="constant"><float name="radiance" value="1"/></emitter>
  <shape type="sphere"><float name="radius" value="1"/><bsdf type="diffuse"><float name="reflectance" value="1"/></bsdf></shape>
</scene>)");
  double sum = 0, sum2 = 0;
  const int n = 24 * 24;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x) {
      const double v = r.image.At(x, y, 1);
      sum += v;
      sum2 += v * v;
    }
  const double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1));
  EXPECT_NEAR(mean, 1.0, 4 * se + 3e-3);
  EXPECT_LT(se, 0.01);
  EXPECT_EQ(r.stats.nan_count, 0u);
}

// A spot light at the centre of a glass sphere (index 1.5, absorption sigma per unit, radius r),
// aimed at a patch of floor the camera sees from above. Light leaves the centre along radii, so
// it meets the glass at normal incidence: R = (0.5 / 2.5)^2 of it is reflected back through the
// centre, leaves on the far side going up (lost) or is reflected again and comes back out on the
// spot's side; each crossing of the radius absorbs a = exp(-sigma r). What reaches the floor is
// the light's own times T = (1 - R) a / (1 - R^2 a^4).
std::string GlassSphereOverFloor(const std::string& sphere, int seed) {
  return fmt::format(R"(<scene version="3.0.0">
  <integrator type="ptracer"/>
  <sensor type="perspective"><float name="fov" value="20"/>
    <transform name="to_world"><lookat origin="0, 3, 0" target="0, 0, 0" up="0, 0, -1"/></transform>
    <sampler type="independent"><integer name="sample_count" value="16"/><integer name="seed" value="{}"/></sampler>
    <film type="hdrfilm"><integer name="width" value="24"/><integer name="height" value="24"/><rfilter type="box"/></film>
  </sensor>
  <shape type="rectangle"><transform name="to_world"><scale x="4" y="4"/><rotate x="1" angle="-90"/></transform>
    <bsdf type="diffuse"><float name="reflectance" value="0.5"/></bsdf></shape>
  <emitter type="spot"><float name="intensity" value="10"/><float name="cutoff_angle" value="8"/>
    <float name="beam_width" value="8"/>
    <transform name="to_world"><lookat origin="1.2, 1, 0" target="0, 0, 0"/></transform></emitter>
  {}
</scene>)",
                     seed, sphere);
}

// The image's total (G) over 8 renders of different seeds: their mean and its standard error.
test::MeanSe TotalOverSeeds(const std::string& sphere) {
  constexpr int kSeeds = 8;
  double s = 0, s2 = 0;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    const Image img = RenderXml(GlassSphereOverFloor(sphere, seed)).image;
    double total = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) total += img.At(x, y, 1);
    s += total;
    s2 += total * total;
  }
  const double mean = s / kSeeds;
  return {mean, std::sqrt(std::max(0.0, s2 / kSeeds - mean * mean) / (kSeeds - 1))};
}

TEST(LightTracer, GlassSphereLetsThroughItsClosedFormTransmittance) {
  const double r = 0.1, R = 0.04;
  const test::MeanSe bare = TotalOverSeeds("");
  ASSERT_GT(bare.mean, 0);
  for (double sigma : {0.0, 5.0}) {
    const test::MeanSe through = TotalOverSeeds(fmt::format(R"(<shape type="sphere">
      <point name="center" x="1.2" y="1" z="0"/><float name="radius" value="{}"/>
      <bsdf type="dielectric"><float name="int_ior" value="1.5"/><spectrum name="absorption" value="{}"/></bsdf>
      </shape>)",
                                                            r, sigma));
    const double a = std::exp(-sigma * r);
    const double expected = (1 - R) * a / (1 - R * R * a * a * a * a);
    const double ratio = through.mean / bare.mean;
    const double se = ratio * std::hypot(through.se / through.mean, bare.se / bare.mean);
    EXPECT_NEAR(ratio, expected, 4 * se) << "sigma " << sigma;
    EXPECT_LT(4 * se, 0.02) << "sigma " << sigma;  // tells the glass's reflection (4%) apart
  }
}

}  // namespace
}  // namespace objektiv
