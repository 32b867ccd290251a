// The classic tracer (render/whitted_integrator.h, integrator `whitted`): the same image as the
// path tracer where both are exact (diffuse and Phong surfaces lit directly by point, spot,
// directional and area lights; a mirror; a glass slab with absorption in front of a lamp); the
// ambient term as the light of a uniform sky; the loader's checks.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "base/error.h"
#include "image_estimates.h"
#include "render_helpers.h"

namespace objektiv {
namespace {

using test::Estimate;
using test::Estimated;
using test::ExpectSameImage;
using test::kSize;
using test::RenderXml;

// `shapes` and `lights` seen from the front and above by a 45-degree pinhole camera.
std::string Scene(const std::string& integrator, const std::string& shapes, int spp, int seed) {
  return fmt::format(R"(<scene version="3.0.0">
  {}
  <sensor type="perspective"><float name="fov" value="45"/>
    <transform name="to_world"><lookat origin="0, 1.2, 3.2" target="0, 0.5, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="{}"/><integer name="seed" value="{}"/></sampler>
    <film type="hdrfilm"><integer name="width" value="{}"/><integer name="height" value="{}"/><rfilter type="box"/></film>
  </sensor>
  {}
</scene>)",
                     integrator, spp, seed, kSize, kSize, shapes);
}

// A checkered floor with a diffuse ball and a Phong ball on it (no surface sees another's
// light but through `lights`' direct light at max_depth 2).
const char* kBalls = R"(
  <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="-90"/><scale value="3"/></transform>
    <bsdf type="diffuse"><texture type="checkerboard" name="reflectance">
      <rgb name="color0" value="0.7, 0.7, 0.7"/><rgb name="color1" value="0.2, 0.3, 0.2"/>
      <transform name="to_uv"><scale x="6" y="6"/></transform></texture></bsdf></shape>
  <shape type="sphere"><point name="center" x="-0.5" y="0.4" z="0"/><float name="radius" value="0.4"/>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.6, 0.5, 0.3"/></bsdf></shape>
  <shape type="sphere"><point name="center" x="0.55" y="0.45" z="-0.2"/><float name="radius" value="0.45"/>
    <bsdf type="phong"><rgb name="diffuse_reflectance" value="0.3, 0.1, 0.1"/>
      <rgb name="specular_reflectance" value="0.5, 0.5, 0.5"/><float name="exponent" value="40"/></bsdf></shape>)";

std::string Integrator(const char* type, int max_depth, const std::string& more = "") {
  return fmt::format(R"(<integrator type="{}"><integer name="max_depth" value="{}"/>{}</integrator>)", type, max_depth,
                     more);
}

// `whitted` and `path` at the same max_depth render the same image, telling an error of
// `resolution` in total.
void ExpectSameAsPathTracer(const std::string& shapes, int max_depth, int path_spp, int whitted_spp,
                            double resolution, const std::string& what) {
  const Estimate path =
      Estimated([&](int seed) { return Scene(Integrator("path", max_depth), shapes, path_spp, seed); });
  const Estimate whitted =
      Estimated([&](int seed) { return Scene(Integrator("whitted", max_depth), shapes, whitted_spp, seed); });
  ExpectSameImage(path, whitted, resolution, what);
}

TEST(Whitted, DirectLightOfPointSpotAndDirectionalLightsIsThePathTracers) {
  for (const char* light :
       {R"(<emitter type="point"><point name="position" x="-1" y="2.5" z="1.5"/><rgb name="intensity" value="8, 8, 7"/></emitter>)",
        R"(<emitter type="spot"><rgb name="intensity" value="12, 12, 12"/><float name="cutoff_angle" value="30"/>
           <transform name="to_world"><lookat origin="1, 2.5, 1" target="0, 0, -0.2"/></transform></emitter>)",
        R"(<emitter type="directional"><vector name="direction" x="0.4" y="-1" z="-0.3"/><rgb name="irradiance" value="2, 2, 2"/></emitter>)"})
    ExpectSameAsPathTracer(std::string(kBalls) + light, 2, 16, 4, 0.03, light);
}

TEST(Whitted, SoftShadowsOfAnAreaLightAreThePathTracers) {
  const std::string lamp = R"(<shape type="rectangle">
    <transform name="to_world"><scale x="0.5" y="0.3"/><rotate x="1" angle="90"/><translate x="-0.3" y="2" z="0.6"/></transform>
    <emitter type="area"><rgb name="radiance" value="10, 9, 8"/></emitter></shape>)";
  ExpectSameAsPathTracer(kBalls + lamp, 2, 64, 4, 0.03, "area light");
  // The sky on the Phong ball's highlight: light and BSDF samples combined.
  ExpectSameAsPathTracer(std::string(kBalls) + R"(<emitter type="constant"><rgb name="radiance" value="0.6, 0.7, 0.9"/></emitter>)", 2,
                         64, 4, 0.03, "sky");
}

// A mirror ball on a diffuse floor lit by a point light: the floor seen in the mirror (camera,
// mirror, floor, light: three segments) and the mirror's shadow on the floor.
TEST(Whitted, MirrorReflectionIsThePathTracers) {
  const char* scene = R"(
  <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="-90"/><scale value="3"/></transform>
    <bsdf type="diffuse"><texture type="checkerboard" name="reflectance">
      <rgb name="color0" value="0.8, 0.8, 0.8"/><rgb name="color1" value="0.1, 0.1, 0.4"/>
      <transform name="to_uv"><scale x="6" y="6"/></transform></texture></bsdf></shape>
  <shape type="sphere"><point name="center" x="0" y="0.6" z="-0.2"/><float name="radius" value="0.6"/>
    <bsdf type="conductor"><string name="material" value="Al"/></bsdf></shape>
  <emitter type="point"><point name="position" x="-1.2" y="2.5" z="1.2"/><rgb name="intensity" value="8, 8, 8"/></emitter>)";
  ExpectSameAsPathTracer(scene, 3, 16, 4, 0.03, "mirror");
}

// A tilted slab of absorbing glass in front of a lamp: the lamp seen through it (refracted,
// shifted, dimmed by Fresnel at two faces and by Beer-Lambert inside, with its internal
// reflections), and the lamp's reflection in it.
TEST(Whitted, GlassSlabWithAbsorptionIsThePathTracers) {
  const char* scene = R"(
  <shape type="rectangle">
    <transform name="to_world"><scale x="0.8" y="0.5"/><translate y="0.5" z="-1"/></transform>
    <emitter type="area"><rgb name="radiance" value="2, 3, 4"/></emitter></shape>
  <shape type="cube">
    <transform name="to_world"><scale x="0.6" y="0.6" z="0.08"/><rotate y="1" angle="35"/><rotate x="1" angle="10"/>
      <translate y="0.55" z="0"/></transform>
    <bsdf type="dielectric"><float name="int_ior" value="1.6"/>
      <rgb name="absorption" value="0.5, 2, 4"/></bsdf></shape>
  <shape type="rectangle">
    <transform name="to_world"><scale x="0.4" y="0.3"/><rotate y="1" angle="180"/><translate x="0.9" y="1.1" z="2"/></transform>
    <emitter type="area"><rgb name="radiance" value="5, 4, 3"/></emitter></shape>)";
  ExpectSameAsPathTracer(scene, 12, 64, 4, 0.03, "glass slab");
}

// A `thindielectric` sheet is a glass slab too thin to shift the light: in front of a lamp, the
// path tracer's sheet and the classic tracer's slab (a cube 1 mm thick, every inner reflection
// followed) show the same.
TEST(Whitted, ThinDielectricSheetIsAVeryThinGlassSlab) {
  const std::string lamp = R"(
  <shape type="rectangle">
    <transform name="to_world"><scale x="0.8" y="0.5"/><translate y="0.5" z="-1"/></transform>
    <emitter type="area"><rgb name="radiance" value="2, 3, 4"/></emitter></shape>
  <shape type="rectangle">
    <transform name="to_world"><scale x="0.4" y="0.3"/><rotate y="1" angle="180"/><translate x="0.9" y="1.1" z="2"/></transform>
    <emitter type="area"><rgb name="radiance" value="5, 4, 3"/></emitter></shape>)";
  const char* tilt = R"(<rotate y="1" angle="50"/><rotate x="1" angle="10"/><translate y="0.55" z="0"/>)";
  const std::string sheet = fmt::format(R"(<shape type="rectangle"><transform name="to_world"><scale value="0.6"/>{}</transform>
    <bsdf type="thindielectric"><float name="int_ior" value="1.7"/></bsdf></shape>)", tilt);
  const std::string slab = fmt::format(R"(<shape type="cube"><transform name="to_world"><scale x="0.6" y="0.6" z="0.0005"/>{}</transform>
    <bsdf type="dielectric"><float name="int_ior" value="1.7"/></bsdf></shape>)", tilt);
  const Estimate path = Estimated([&](int seed) { return Scene(Integrator("path", 40), lamp + sheet, 64, seed); });
  const Estimate whitted = Estimated([&](int seed) {
    return Scene(Integrator("whitted", 40, R"(<float name="bailout" value="1e-4"/>)"), lamp + slab, 4, seed);
  });
  ExpectSameImage(path, whitted, 0.03, "thin sheet and thin slab");
}

// Two perfect mirrors facing each other with the camera between them and a glass ball in the
// middle: at the deepest depth and the smallest bailout every branch still ends (the chain of
// mirror images at max_depth, the glass's branches at the bailout), in a bounded number of rays.
TEST(Whitted, MirrorsFacingEachOtherEndAtTheBounds) {
  const std::string scene = fmt::format(R"(<scene version="3.0.0">
  <integrator type="whitted"><integer name="max_depth" value="64"/><float name="bailout" value="1e-4"/></integrator>
  <sensor type="perspective"><float name="fov" value="20"/>
    <transform name="to_world"><lookat origin="0, 0, 0" target="0, 0, -1" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="1"/></sampler>
    <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="16"/></film>
  </sensor>
  <shape type="rectangle"><transform name="to_world"><scale value="100"/><translate z="-1"/></transform><bsdf type="conductor"/></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="100"/><rotate y="1" angle="180"/><translate z="1"/></transform>
    <bsdf type="conductor"/></shape>
  <shape type="sphere"><point name="center" x="0" y="0" z="-0.5"/><float name="radius" value="0.05"/>
    <bsdf type="dielectric"/></shape>
  <emitter type="constant"><rgb name="radiance" value="1, 1, 1"/></emitter>
</scene>)");
  const test::RenderResult r = RenderXml(scene);
  EXPECT_EQ(r.stats.nan_count, 0u);
  EXPECT_LT(r.stats.rays, 16u * 16u * 4096u);
}

// The ambient term is the light of a uniform sky that nothing shadows: under no other light, a
// diffuse floor that sees only the sky is the path tracer's under that sky.
TEST(Whitted, AmbientTermIsTheLightOfAnUnshadowedUniformSky) {
  const char* floor = R"(<shape type="rectangle"><transform name="to_world"><rotate x="1" angle="-90"/><scale value="30"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.6, 0.4, 0.2"/></bsdf></shape>)";
  Estimate path = Estimated([&](int seed) {
    return Scene(Integrator("path", 2), std::string(floor) + R"(<emitter type="constant"><rgb name="radiance" value="0.5, 0.7, 0.9"/></emitter>)",
                 64, seed);
  });
  Estimate whitted = Estimated([&](int seed) {
    return Scene(Integrator("whitted", 2, R"(<rgb name="ambient" value="0.5, 0.7, 0.9"/>)"), floor, 1, seed);
  });
  // The sky itself is seen above the horizon by the path tracer only: compare the floor's rows.
  for (int k = 0; k < test::kBlocks; ++k)
    if (k < test::kBlocks / 2) path.mean[k] = whitted.mean[k] = path.var[k] = whitted.var[k] = 0;
  ExpectSameImage(path, whitted, 0.03, "ambient");
}

// Rough glass is seen through: a slab of rough glass in front of a glowing wall shows the wall as
// the path tracer shows it with the same paths (max_depth 3: through the slab's two faces to
// the wall). It was black: only the light sources were taken through rough glass, and shadow
// rays stop at glass; the wall's light is found from the slab's back face. (A lit wall would
// not do: the slab's blur of its own shadow moves light between the blocks compared.) The
// wall reflects nothing, and the slab's edges are out of view (they take light in through its
// sides by total internal reflection).
TEST(Whitted, RoughGlassShowsWhatLiesBehindIt) {
  const std::string shapes = R"(
  <shape type="rectangle"><transform name="to_world"><scale value="3"/><translate y="0.5" z="-1.5"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0"/></bsdf>
    <emitter type="area"><rgb name="radiance" value="0.7, 0.6, 0.5"/></emitter></shape>
  <shape type="cube"><transform name="to_world"><scale x="3" y="3" z="0.05"/><translate y="0.5" z="0"/></transform>
    <bsdf type="roughdielectric"><float name="alpha" value="0.05"/></bsdf></shape>)";
  ExpectSameAsPathTracer(shapes, 3, 16, 4, 0.03, "rough glass slab");
}

// Per pixel, the mean absolute difference of neighbours' chromaticities (x and y, from the
// image's RGB summed): the colour noise of an image whose colours vary smoothly.
double ChromaNoise(const Image& img) {
  double sum = 0;
  int n = 0;
  auto chroma = [&](int x, int y, int c) {
    const double total = img.At(x, y, 0) + img.At(x, y, 1) + img.At(x, y, 2);
    return total > 0 ? img.At(x, y, c) / total : 0.0;
  };
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x + 1 < img.width; ++x, ++n)
      for (int c : {0, 2}) sum += std::abs(chroma(x, y, c) - chroma(x + 1, y, c));
  return sum / n;
}

// A grey floor under a blue sky, at one sample per pixel: four wavelengths a pixel leave its
// colour noisy (the Z of a smooth spectrum 50% rms), four sets of them (sixteen) take the
// noise out, and the two converge to the same image.
TEST(Whitted, WavelengthSetsTakeTheColourNoiseOut) {
  const char* floor = R"(<shape type="rectangle"><transform name="to_world"><rotate x="1" angle="-90"/><scale value="30"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.5, 0.5, 0.5"/></bsdf></shape>
    <emitter type="constant"><rgb name="radiance" value="0.25, 0.32, 0.45"/></emitter>)";
  auto scene = [&](int sets, int spp, int seed) {
    return Scene(Integrator("whitted", 2, fmt::format(R"(<integer name="wavelength_sets" value="{}"/>
      <integer name="shadow_grid" value="8"/>)", sets)), floor, spp, seed);
  };
  const double one = ChromaNoise(RenderXml(scene(1, 1, 1)).image), four = ChromaNoise(RenderXml(scene(4, 1, 1)).image);
  EXPECT_LT(four, 0.05 * one) << "colour noise with 4 wavelengths " << one << ", with 16 " << four;
  const Estimate a = Estimated([&](int seed) { return scene(1, 4, seed); });
  const Estimate b = Estimated([&](int seed) { return scene(4, 1, seed); });
  ExpectSameImage(a, b, 0.01, "one set and four");
}

// Dispersive glass keeps each set's hero wavelength alone: the sets' heroes are spread over the
// range (they lay in its first quarter, and four sets took the colour grain of a white wall
// seen through flint glass only from 1.96 to 1.34; now to 0.45).
TEST(Whitted, WavelengthSetsSpreadTheirHeroesThroughDispersiveGlass) {
  auto scene = [](int sets) {
    return Scene(Integrator("whitted", 6, fmt::format(R"(<integer name="wavelength_sets" value="{}"/>)", sets)), R"(
  <shape type="rectangle"><transform name="to_world"><scale value="3"/><translate y="0.5" z="-1.5"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0"/></bsdf>
    <emitter type="area"><rgb name="radiance" value="1, 1, 1"/></emitter></shape>
  <shape type="cube"><transform name="to_world"><scale x="3" y="3" z="0.1"/><rotate y="1" angle="30"/><translate y="0.5"/></transform>
    <bsdf type="dielectric"><string name="int_ior" value="N-SF11"/></bsdf></shape>)",
                 1, 1);
  };
  const double one = ChromaNoise(RenderXml(scene(1)).image), four = ChromaNoise(RenderXml(scene(4)).image);
  EXPECT_LT(four, 0.5 * one) << "colour noise through flint glass with one set " << one << ", with four " << four;
}

// Where nothing depends on wavelength the sets trace the first set's rays only (RayMemo; the
// Phong ball, which picks its lobe by their spectral weights, parts a few); where glass
// disperses, their rays part and each is traced, the image still the same as one set's.
TEST(Whitted, WavelengthSetsShareTheirRaysUnlessGlassDisperses) {
  const std::string lamp = R"(<shape type="rectangle">
    <transform name="to_world"><scale x="0.5" y="0.3"/><rotate x="1" angle="90"/><translate x="-0.3" y="2" z="0.6"/></transform>
    <emitter type="area"><rgb name="radiance" value="10, 9, 8"/></emitter></shape>)";
  const std::string glass = R"(<shape type="sphere"><point name="center" x="0.1" y="0.5" z="0.6"/><float name="radius" value="0.35"/>
    <bsdf type="dielectric">{}</bsdf></shape>)";
  const char* constant = R"(<float name="int_ior" value="1.5"/>)";
  const char* dispersive = R"(<string name="int_ior" value="N-BK7"/>)";
  auto scene = [&](int sets, const char* ior, int seed, int spp = 1) {
    return Scene(Integrator("whitted", 6, fmt::format(R"(<integer name="wavelength_sets" value="{}"/>)", sets)),
                 kBalls + lamp + fmt::format(fmt::runtime(glass), ior), spp, seed);
  };
  const uint64_t one = RenderXml(scene(1, constant, 1)).stats.rays, four = RenderXml(scene(4, constant, 1)).stats.rays;
  EXPECT_LT(double(four) / double(one), 1.1) << one << " rays with one set, " << four << " with four";
  const uint64_t one_dispersive = RenderXml(scene(1, dispersive, 1)).stats.rays;
  const uint64_t four_dispersive = RenderXml(scene(4, dispersive, 1)).stats.rays;
  EXPECT_GT(double(four_dispersive) / double(one_dispersive), 1.05)
      << one_dispersive << " rays with one set, " << four_dispersive << " with four";
  const Estimate a = Estimated([&](int seed) { return scene(1, dispersive, seed + 100, 16); });
  const Estimate b = Estimated([&](int seed) { return scene(4, dispersive, seed + 200, 16); });
  ExpectSameImage(a, b, 0.02, "dispersive glass, one set and four");
}

TEST(Whitted, BadSettingsAreErrorsAtTheirLine) {
  // Every branch is followed: an unbounded depth or no bailout could recurse without end (two
  // mirrors facing each other) or branch without end (glass between them).
  for (const char* bad : {R"(<integer name="max_depth" value="0"/>)", R"(<integer name="max_depth" value="-1"/>)",
                          R"(<integer name="max_depth" value="65"/>)", R"(<integer name="shadow_grid" value="0"/>)",
                          R"(<float name="bailout" value="2"/>)", R"(<float name="bailout" value="0"/>)",
                          R"(<float name="ambient" value="-1"/>)", R"(<integer name="wavelength_sets" value="0"/>)",
                          R"(<integer name="wavelength_sets" value="9"/>)"}) {
    const std::string xml = fmt::format(
        "<scene version=\"3.0.0\">\n<integrator type=\"whitted\">\n{}\n</integrator>\n<sensor type=\"perspective\"/>\n</scene>",
        bad);
    try {
      LoadSceneFromString(xml, "test.xml", {});
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("test.xml:3"), std::string::npos) << e.what();
    }
  }
  const std::string phong =
      "<scene version=\"3.0.0\">\n<sensor type=\"perspective\"/>\n<shape type=\"sphere\"><bsdf type=\"phong\">\n"
      "<float name=\"exponent\" value=\"-2\"/>\n</bsdf></shape>\n</scene>";
  try {
    LoadSceneFromString(phong, "test.xml", {});
    ADD_FAILURE() << "a negative exponent accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("test.xml:4"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace objektiv
