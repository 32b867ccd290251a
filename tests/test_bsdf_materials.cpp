// The materials roughplastic, blendbsdf and mask in scenes: masks let rays through alike for
// camera paths, light paths and shadow rays (an image through a mask equals the image of the
// light dimmed by its opacity, in every integrator); a blend of weight 0 or 1 renders as its
// part; rough plastic and principled render in every integrator; the loader's checks at
// file:line.
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "base/error.h"
#include "image_estimates.h"
#include "render_helpers.h"
#include "sanitizer_build.h"
#include "scene/scene.h"

namespace objektiv {
namespace {

using test::Estimate;
using test::Estimated;
using test::ExpectSameImage;
using test::kSize;
using test::RenderXml;

// A grey floor seen from low down (y = 0.6), lit from above; `between` sits between the light
// and the floor at y = 1.2, out of the camera's view.
std::string FloorScene(const std::string& integrator, const std::string& light, const std::string& between, int spp,
                       int seed) {
  return fmt::format(R"(<scene version="3.0.0">
  {}
  <sensor type="perspective"><float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0, 0.6, 2.5" target="0, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="{}"/><integer name="seed" value="{}"/></sampler>
    <film type="hdrfilm"><integer name="width" value="{}"/><integer name="height" value="{}"/><rfilter type="box"/></film>
  </sensor>
  <shape type="rectangle"><transform name="to_world"><scale value="3"/><rotate x="1" angle="-90"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.6, 0.5, 0.4"/></bsdf></shape>
  {}
  {}
</scene>)",
                     integrator, spp, seed, kSize, kSize, light, between);
}

// A black plate (nothing it stops comes back) behind a mask of opacity 0.4; the same light
// without it, dimmed to 0.6, must give the same image.
const char* kMaskedPlate = R"(<shape type="rectangle">
    <transform name="to_world"><rotate x="1" angle="-90"/><translate y="1.2"/></transform>
    <bsdf type="mask"><float name="opacity" value="0.4"/><bsdf type="diffuse"><rgb name="reflectance" value="0"/></bsdf></bsdf></shape>)";

std::string PointLight(float scale) {
  return fmt::format(R"(<emitter type="point"><point name="position" x="0.2" y="1.6" z="0"/><rgb name="intensity" value="{}"/></emitter>)",
                     3 * scale);
}
// A lamp facing down; black itself, so that light reflected up is not sent back down.
std::string AreaLight(float scale) {
  return fmt::format(R"(<shape type="rectangle">
    <transform name="to_world"><scale value="0.3"/><rotate x="1" angle="90"/><translate y="1.6"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0"/></bsdf>
    <emitter type="area"><rgb name="radiance" value="{}"/></emitter></shape>)",
                     8 * scale);
}

std::string Integrator(const char* type) { return fmt::format(R"(<integrator type="{}"/>)", type); }

void ExpectMaskDims(const char* integrator, bool area, int spp) {
  const std::string what = fmt::format("{} with {} light", integrator, area ? "an area" : "a point");
  const Estimate masked = Estimated([&](int seed) {
    return FloorScene(Integrator(integrator), area ? AreaLight(1) : PointLight(1), kMaskedPlate, spp, seed);
  });
  const Estimate dimmed = Estimated([&](int seed) {
    return FloorScene(Integrator(integrator), area ? AreaLight(0.6f) : PointLight(0.6f), "", spp, seed);
  });
  ExpectSameImage(dimmed, masked, 0.03, what);
}

TEST(BsdfMaterials, MaskLetsLightThroughInThePathTracer) {
  ExpectMaskDims("path", false, 4);
  ExpectMaskDims("path", true, 32);
}

TEST(BsdfMaterials, MaskLetsLightThroughInTheDirectAndClassicTracers) {
  ExpectMaskDims("direct", false, 4);
  ExpectMaskDims("direct", true, 32);
  ExpectMaskDims("whitted", false, 4);
  ExpectMaskDims("whitted", true, 4);
}

TEST(BsdfMaterials, MaskLetsLightThroughInTheLightTracer) {
  ExpectMaskDims("ptracer", false, 256);
  ExpectMaskDims("ptracer", true, 64);
}

// Seen straight through a half-opaque, unlit white plate, a lamp shows half its radiance.
std::string LampBehind(const char* integrator, bool plate) {
  return fmt::format(R"(<scene version="3.0.0">
  <integrator type="{}"/>
  <sensor type="perspective"><float name="fov" value="30"/>
    <transform name="to_world"><lookat origin="0, 0, 3" target="0, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="64"/></sampler>
    <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="16"/><rfilter type="box"/></film>
  </sensor>
  <shape type="rectangle"><transform name="to_world"><scale value="5"/><translate z="-1"/></transform>
    <emitter type="area"><rgb name="radiance" value="2"/></emitter></shape>
  {}
</scene>)",
                     integrator,
                     plate ? R"(<shape type="rectangle"><transform name="to_world"><scale value="3"/></transform>
    <bsdf type="mask"><float name="opacity" value="0.5"/><bsdf type="diffuse"><rgb name="reflectance" value="1"/></bsdf></bsdf></shape>)"
                           : "");
}

TEST(BsdfMaterials, HalfOpaqueMaskInFrontOfALampShowsHalfItsRadiance) {
  for (const char* integrator : {"path", "direct", "whitted"}) {
    const Image masked = RenderXml(LampBehind(integrator, true)).image;
    const Image plain = RenderXml(LampBehind(integrator, false)).image;
    for (int c = 0; c < 3; ++c) {
      const test::MeanSe m = test::ChannelMean(masked, c), p = test::ChannelMean(plain, c);
      EXPECT_GT(p.mean, 1.5) << integrator;
      EXPECT_NEAR(m.mean, 0.5 * p.mean, 4 * std::hypot(m.se, 0.5 * p.se) + 1e-6) << integrator << " channel " << c;
    }
  }
}

// The scene's own test: rays pass a mask of opacity a in the share 1 - a, Intersect and
// Occluded alike, and a ray that passes hits what lies behind at its own parameter t.
TEST(BsdfMaterials, IntersectAndOccludedPassAMaskInTheSameShare) {
  const std::string xml = R"(<scene version="3.0.0">
  <sensor type="perspective"/>
  <shape type="rectangle"><transform name="to_world"><translate z="1"/></transform>
    <bsdf type="mask"><float name="opacity" value="0.3"/><bsdf type="diffuse"/></bsdf></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="4"/><translate z="3"/></transform></shape>
</scene>)";
  RenderSetup setup = LoadSceneFromString(xml, "mask.xml", {});
  const Scene& scene = *setup.scene;
  PCG32 g(1, 1);
  int stopped = 0, occluded = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const Ray ray{Vec3f(g.UniformFloat() - 0.5f, g.UniformFloat() - 0.5f, 0), Vec3f(0, 0, 1)};
    const std::optional<SurfaceInteraction> si = scene.Intersect(ray);
    ASSERT_TRUE(si);
    if (si->p.z < 2) {
      ++stopped;
      EXPECT_NEAR(si->t, 1, 1e-4);
    } else {
      EXPECT_NEAR(si->t, 3, 1e-4);
    }
    Ray shadow = ray;
    shadow.tmax = 2;  // ends before the back wall
    occluded += scene.Occluded(shadow);
  }
  const double se = std::sqrt(0.3 * 0.7 / n);
  EXPECT_NEAR(stopped / double(n), 0.3, 4 * se);
  EXPECT_NEAR(occluded / double(n), 0.3, 4 * se);
}

// --- blendbsdf and roughplastic in scenes ------------------------------------------------

std::string BallScene(const std::string& integrator, const std::string& bsdf, int spp, int seed) {
  return fmt::format(R"(<scene version="3.0.0">
  {}
  <sensor type="perspective"><float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0, 1, 3" target="0, 0.4, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="{}"/><integer name="seed" value="{}"/></sampler>
    <film type="hdrfilm"><integer name="width" value="{}"/><integer name="height" value="{}"/><rfilter type="box"/></film>
  </sensor>
  <shape type="rectangle"><transform name="to_world"><scale value="3"/><rotate x="1" angle="-90"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.5"/></bsdf></shape>
  <shape type="sphere"><point name="center" x="0" y="0.5" z="0"/><float name="radius" value="0.5"/>{}</shape>
  <emitter type="point"><point name="position" x="1" y="2" z="1.5"/><rgb name="intensity" value="6"/></emitter>
  <emitter type="constant"><rgb name="radiance" value="0.3"/></emitter>
</scene>)",
                     integrator, spp, seed, kSize, kSize, bsdf);
}

const char* kRoughPlastic = R"(<bsdf type="roughplastic"><float name="alpha" value="0.15"/>
    <rgb name="diffuse_reflectance" value="0.6, 0.2, 0.1"/></bsdf>)";

TEST(BsdfMaterials, BlendOfWeightZeroOrOneRendersAsItsPart) {
  SKIP_UNDER_SANITIZERS("BsdfMaterials.BlendOfTwoDiffusesIsTheDiffuseOfTheMeanColour");
  const std::string conductor = R"(<bsdf type="roughconductor"><float name="alpha" value="0.2"/></bsdf>)";
  for (int w : {0, 1}) {
    const std::string blend = fmt::format(R"(<bsdf type="blendbsdf"><float name="weight" value="{}"/>{}{}</bsdf>)", w,
                                          kRoughPlastic, conductor);
    // The blend draws its lobe choice where the part might not: the same estimate, other noise.
    const std::string path = R"(<integrator type="path"><integer name="max_depth" value="3"/></integrator>)";
    const Estimate ea = Estimated([&](int seed) { return BallScene(path, blend, 8, seed); });
    const Estimate eb = Estimated([&](int seed) { return BallScene(path, w == 0 ? kRoughPlastic : conductor, 8, seed); });
    ExpectSameImage(eb, ea, 0.03, fmt::format("blend of weight {}", w));
  }
}

// A blend of two diffuse greys is the diffuse of the blended grey, in the classic tracer's
// ambient term and lights as in the path tracer.
TEST(BsdfMaterials, BlendOfTwoDiffusesIsTheDiffuseOfTheMeanColour) {
  // (Numbers: constant spectra, which mix exactly as the numbers do; RGB spectra do not.)
  const std::string blend = R"(<bsdf type="blendbsdf"><float name="weight" value="0.25"/>
    <bsdf type="diffuse"><float name="reflectance" value="0.8"/></bsdf>
    <bsdf type="diffuse"><float name="reflectance" value="0.2"/></bsdf></bsdf>)";
  const std::string mean = R"(<bsdf type="diffuse"><float name="reflectance" value="0.65"/></bsdf>)";
  for (const char* integrator : {"path", "whitted"}) {
    const Estimate a = Estimated([&](int seed) { return BallScene(Integrator(integrator), blend, 8, seed); });
    const Estimate b = Estimated([&](int seed) { return BallScene(Integrator(integrator), mean, 8, seed); });
    ExpectSameImage(b, a, 0.03, integrator);
  }
}

// Rough plastic (and a normal-mapped blend holding it) render alike in the path and light tracers.
TEST(BsdfMaterials, RoughPlasticAndBlendsAgreeBetweenPathAndLightTracer) {
  SKIP_UNDER_SANITIZERS("BsdfMaterials.MaskLetsLightThroughInTheLightTracer and Bsdf.SamplingMatchesPdf");
  const std::string blend = std::string(R"(<bsdf type="normalmap"><rgb name="normalmap" value="0.7, 0.45, 0.9"/>
    <bsdf type="blendbsdf"><float name="weight" value="0.4"/>)") + kRoughPlastic +
                            R"(<bsdf type="diffuse"><rgb name="reflectance" value="0.2, 0.5, 0.7"/></bsdf></bsdf></bsdf>)";
  for (const std::string& bsdf : {std::string(kRoughPlastic), blend}) {
    const Estimate path = Estimated([&](int seed) {
      return BallScene(R"(<integrator type="path"><integer name="max_depth" value="3"/></integrator>)", bsdf, 16, seed);
    });
    const Estimate light = Estimated([&](int seed) {
      return BallScene(R"(<integrator type="ptracer"><integer name="max_depth" value="3"/></integrator>)", bsdf, 64, seed);
    });
    ExpectSameImage(path, light, 0.03, bsdf);
  }
}

// The principled BSDF (clearcoat, sheen, a little metal; and a half-transmissive one inside a
// normal-mapped blend) renders alike in the path and light tracers.
const char* kPrincipled = R"(<bsdf type="principled"><rgb name="base_color" value="0.7, 0.3, 0.1"/>
    <float name="roughness" value="0.4"/><float name="metallic" value="0.2"/><float name="clearcoat" value="1"/>
    <float name="clearcoat_gloss" value="0.5"/><float name="sheen" value="1"/><float name="spec_tint" value="0.5"/></bsdf>)";

TEST(BsdfMaterials, PrincipledAgreesBetweenPathAndLightTracer) {
  const std::string wrapped = std::string(R"(<bsdf type="normalmap"><rgb name="normalmap" value="0.6, 0.45, 0.9"/>
    <bsdf type="blendbsdf"><float name="weight" value="0.5"/>)") + kPrincipled +
                              R"(<bsdf type="principled"><float name="spec_trans" value="0.5"/><float name="roughness" value="0.7"/>
      <float name="anisotropic" value="0.5"/></bsdf></bsdf></bsdf>)";
  for (const std::string& bsdf : {std::string(kPrincipled), wrapped}) {
    const Estimate path = Estimated([&](int seed) {
      return BallScene(R"(<integrator type="path"><integer name="max_depth" value="3"/></integrator>)", bsdf, 16, seed);
    });
    const Estimate light = Estimated([&](int seed) {
      return BallScene(R"(<integrator type="ptracer"><integer name="max_depth" value="3"/></integrator>)", bsdf, 64, seed);
    });
    ExpectSameImage(path, light, 0.03, bsdf);
  }
}

// Direct lighting alone: the `direct` integrator and the path tracer stopped after one bounce
// give the same image of a principled ball (bump-mapped, under a mask of opacity 1), and the
// classic tracer renders it (glossy: lights sampled and BSDF-sampled, no NaN, not black).
TEST(BsdfMaterials, PrincipledRendersInTheOtherIntegratorsAndWrappers) {
  const std::string bsdf = std::string(R"(<bsdf type="mask"><float name="opacity" value="1"/>
    <bsdf type="bumpmap"><float name="scale" value="0.5"/><texture type="bitmap"><string name="filename" value=")" +
                           std::string(OBJEKTIV_SCENES_DIR) + R"(/bump/textures/tile-height.png"/></texture>)") +
                           kPrincipled + "</bsdf></bsdf>";
  const Estimate direct = Estimated([&](int seed) { return BallScene(Integrator("direct"), bsdf, 8, seed); });
  const Estimate path = Estimated([&](int seed) {
    return BallScene(R"(<integrator type="path"><integer name="max_depth" value="2"/></integrator>)", bsdf, 8, seed);
  });
  ExpectSameImage(direct, path, 0.03, "direct vs path, depth 2");
  const Estimate whitted = Estimated([&](int seed) { return BallScene(Integrator("whitted"), bsdf, 4, seed); });
  double total = 0;
  for (double v : whitted.mean) {
    EXPECT_TRUE(std::isfinite(v));
    total += v;
  }
  EXPECT_GT(total, 0);
}

// --- the loader's checks -------------------------------------------------------------------

void ExpectLoadError(const std::string& bsdf, const std::string& part, const std::string& emitter = "") {
  const std::string xml = "<scene version=\"3.0.0\">\n<sensor type=\"perspective\"/>\n<shape type=\"sphere\">\n" + bsdf +
                          emitter + "</shape>\n</scene>";
  try {
    LoadSceneFromString(xml, "bad.xml", {});
    ADD_FAILURE() << "no error for " << bsdf;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.xml:4"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(BsdfMaterials, LoaderErrorsNameTheLine) {
  ExpectLoadError(R"(<bsdf type="roughplastic"><float name="alpha" value="0"/></bsdf>)", "alpha must lie in [0.001, 1]");
  ExpectLoadError(R"(<bsdf type="roughplastic"><float name="alpha" value="1.5"/></bsdf>)", "alpha must lie in [0.001, 1]");
  ExpectLoadError(R"(<bsdf type="roughplastic"><string name="distribution" value="phong"/></bsdf>)", "ggx");
  ExpectLoadError(R"(<bsdf type="roughplastic"><string name="int_ior" value="unobtainium"/></bsdf>)", "unobtainium");
  ExpectLoadError(R"(<bsdf type="roughplastic"><rgb name="diffuse_reflectance" value="1.2, 0, 0"/></bsdf>)", "[0, 1]");
  const std::string two = R"(<bsdf type="diffuse"/><bsdf type="diffuse"/>)";
  ExpectLoadError(R"(<bsdf type="blendbsdf"><float name="weight" value="1.5"/>)" + two + "</bsdf>", "'weight' must lie in [0, 1]");
  ExpectLoadError(R"(<bsdf type="blendbsdf"><float name="weight" value="-0.1"/>)" + two + "</bsdf>", "'weight' must be finite and not negative");
  ExpectLoadError(R"(<bsdf type="blendbsdf"><rgb name="weight" value="0.5, 2, 0"/>)" + two + "</bsdf>", "[0, 1]");
  ExpectLoadError(R"(<bsdf type="blendbsdf"><bsdf type="diffuse"/></bsdf>)", "exactly 2 nested <bsdf>s, got 1");
  ExpectLoadError(R"(<bsdf type="blendbsdf"><bsdf type="diffuse"/><bsdf type="diffuse"/><bsdf type="diffuse"/></bsdf>)",
                  "exactly 2 nested <bsdf>s, got 3");
  const std::string blend4 = R"(<bsdf type="blendbsdf"><bsdf type="blendbsdf">)" + two + R"(</bsdf><bsdf type="blendbsdf">)" +
                             two + "</bsdf></bsdf>";
  ExpectLoadError(R"(<bsdf type="blendbsdf">)" + blend4 + R"(<bsdf type="diffuse"/></bsdf>)", "more than the 4");
  ExpectLoadError(R"(<bsdf type="blendbsdf"><bsdf type="dielectric"><rgb name="absorption" value="1"/></bsdf><bsdf type="diffuse"/></bsdf>)",
                  "absorption");
  ExpectLoadError(R"(<bsdf type="mask"><float name="opacity" value="1.01"/><bsdf type="diffuse"/></bsdf>)",
                  "'opacity' must lie in [0, 1]");
  ExpectLoadError(R"(<bsdf type="mask"><float name="opacity" value="0.5"/></bsdf>)", "exactly 1 nested <bsdf>, got 0");
  ExpectLoadError(R"(<bsdf type="mask">)" + two + "</bsdf>", "exactly 1 nested <bsdf>, got 2");
  ExpectLoadError(R"(<bsdf type="mask"><bsdf type="diffuse"/></bsdf>)", "area emitter cannot be on a shape whose BSDF is a mask",
                  "<emitter type=\"area\"/>");
}

TEST(BsdfMaterials, PrincipledLoaderErrorsNameTheLine) {
  ExpectLoadError(R"(<bsdf type="principled"><float name="roughness" value="1.5"/></bsdf>)", "'roughness' must lie in [0, 1]");
  ExpectLoadError(R"(<bsdf type="principled"><rgb name="metallic" value="0.5, 2, 0"/></bsdf>)", "'metallic' must lie in [0, 1]");
  ExpectLoadError(R"(<bsdf type="principled"><float name="sheen" value="-0.5"/></bsdf>)", "sheen");
  ExpectLoadError(R"(<bsdf type="principled"><float name="eta" value="0.9"/></bsdf>)", "eta must lie in (1, 10]");
  ExpectLoadError(R"(<bsdf type="principled"><float name="specular" value="0"/></bsdf>)", "specular must lie in (0, 8.37]");
  ExpectLoadError(R"(<bsdf type="principled"><float name="specular" value="9"/></bsdf>)", "specular must lie in (0, 8.37]");
  ExpectLoadError(R"(<bsdf type="principled"><float name="eta" value="1.4"/><float name="specular" value="0.5"/></bsdf>)",
                  "either eta or specular");
  ExpectLoadError(R"(<bsdf type="principled"><float name="main_specular_sampling_rate" value="0"/></bsdf>)",
                  "main_specular_sampling_rate must be positive");
  ExpectLoadError(R"(<bsdf type="principled"><float name="flatness" value="0.5"/></bsdf>)",
                  "'flatness' belongs to Mitsuba's principledthin");
  ExpectLoadError(R"(<bsdf type="principled"><float name="diff_trans" value="0.5"/></bsdf>)", "'diff_trans' belongs");
  ExpectLoadError(R"(<bsdf type="principledthin"><float name="flatness" value="0.5"/></bsdf>)",
                  "'principledthin' (Mitsuba's thin principled");
  ExpectLoadError(R"(<bsdf type="twosided"><bsdf type="principledthin"/></bsdf>)", "not supported");
}

TEST(BsdfMaterials, FourBsdfsInNestedBlendsAreAccepted) {
  const std::string two = R"(<bsdf type="diffuse"/><bsdf type="roughplastic"/>)";
  const std::string xml = R"(<scene version="3.0.0"><sensor type="perspective"/><shape type="sphere">
    <bsdf type="blendbsdf"><bsdf type="blendbsdf">)" + two + R"(</bsdf><bsdf type="mask"><bsdf type="blendbsdf">)" + two +
                          R"(</bsdf></bsdf></bsdf></shape></scene>)";
  EXPECT_NO_THROW(LoadSceneFromString(xml, "ok.xml", {}));
}

}  // namespace
}  // namespace objektiv
