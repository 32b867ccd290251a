// Whole-renderer tests with analytic answers or independent estimators.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "base/error.h"
#include "render_helpers.h"

namespace objektiv {
namespace {

using test::ChannelMean;
using test::RenderXml;

std::string Furnace(const std::string& bsdf, const std::string& integrator = "path") {
  return fmt::format(R"(<scene version="3.0.0">
  <integrator type="{}"/>
  <sensor type="perspective">
    <float name="fov" value="30"/>
    <transform name="to_world"><lookat origin="0, 0, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="sobol"><integer name="sample_count" value="64"/></sampler>
    <film type="hdrfilm"><integer name="width" value="24"/><integer name="height" value="24"/>
      <rfilter type="box"/></film>
  </sensor>
  <emitter type="constant"><float name="radiance" value="1"/></emitter>
  <shape type="sphere"><float name="radius" value="1"/>{}</shape>
</scene>)",
                     integrator, bsdf);
}

// The sphere fills part of the view; every pixel must read the environment's 1.
void ExpectFurnace(const std::string& xml, const char* what) {
  auto r = RenderXml(xml);
  for (int c = 0; c < 3; ++c) {
    auto m = ChannelMean(r.image, c);
    // 1e-3 allows for the RGB-to-spectrum round trip of the constant illuminant.
    EXPECT_NEAR(m.mean, 1.0, 4 * m.se + 3e-3) << what << " channel " << c << " se " << m.se;
  }
  EXPECT_EQ(r.stats.nan_count, 0u);
  EXPECT_EQ(r.stats.inf_count, 0u);
}

TEST(WhiteFurnace, WhiteDiffuseSphereConservesEnergy) {
  ExpectFurnace(Furnace(R"(<bsdf type="twosided"><bsdf type="diffuse"><float name="reflectance" value="1"/></bsdf></bsdf>)"),
                "diffuse");
}

TEST(WhiteFurnace, SmoothDielectricSphereConservesEnergy) {
  ExpectFurnace(Furnace(R"(<bsdf type="dielectric"><float name="int_ior" value="1.5"/></bsdf>)"), "dielectric");
}

TEST(WhiteFurnace, RoughDielectricSphereNeverGainsEnergy) {
  // Single-scattering microfacets lose energy (inside glass at alpha 0.2 the directional
  // albedo is 0.83-0.95, and light bounces inside the sphere many times); they must never gain.
  auto r = RenderXml(Furnace(R"(<bsdf type="roughdielectric"><float name="alpha" value="0.2"/></bsdf>)"));
  for (int c = 0; c < 3; ++c) {
    auto m = ChannelMean(r.image, c);
    EXPECT_LT(m.mean, 1.0 + 4 * m.se + 3e-3);
    EXPECT_GT(m.mean, 0.5);  // and the sphere is not black
  }
}

TEST(WhiteFurnace, DispersiveGlassConservesEnergy) {
  ExpectFurnace(Furnace(R"(<bsdf type="dielectric"><float name="sellmeier_b1" value="1.03961212"/>
      <float name="sellmeier_b2" value="0.231792344"/><float name="sellmeier_b3" value="1.01046945"/>
      <float name="sellmeier_c1" value="0.00600069867"/><float name="sellmeier_c2" value="0.0200179144"/>
      <float name="sellmeier_c3" value="103.560653"/></bsdf>)"),
                "dispersive dielectric");
}

TEST(WhiteFurnace, CatalogGlassConservesEnergy) {
  ExpectFurnace(Furnace(R"(<bsdf type="dielectric"><string name="int_ior" value="N-BK7"/></bsdf>)"), "catalog N-BK7");
  ExpectFurnace(Furnace(R"(<bsdf type="dielectric"><string name="int_ior" value="OHARA:S-TIH53"/></bsdf>)"),
                "catalog S-TIH53");
}

std::string SmallBox(const std::string& integrator, int spp) {
  return fmt::format(R"(<scene version="3.0.0">
  {}
  <sensor type="perspective">
    <float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0, 1, 3.5" target="0, 1, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="{}"/></sampler>
    <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="16"/>
      <rfilter type="box"/></film>
  </sensor>
  <bsdf type="twosided" id="w"><bsdf type="diffuse"><rgb name="reflectance" value="0.7, 0.6, 0.5"/></bsdf></bsdf>
  <bsdf type="roughconductor" id="metal"><string name="material" value="Au"/><float name="alpha" value="0.3"/></bsdf>
  <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="-90"/><scale value="2"/></transform><ref id="w"/></shape>
  <shape type="rectangle"><transform name="to_world"><translate z="-1.5"/><scale value="2"/></transform><ref id="w"/></shape>
  <shape type="sphere"><point name="center" x="0.4" y="0.5" z="0"/><float name="radius" value="0.5"/><ref id="metal"/></shape>
  <shape type="sphere"><point name="center" x="-0.5" y="1.8" z="0.3"/><float name="radius" value="0.15"/>
    <emitter type="area"><rgb name="radiance" value="20, 18, 15"/></emitter></shape>
  <shape type="rectangle"><transform name="to_world"><translate x="0.8" y="2" z="0"/><rotate x="1" angle="90"/>
    <scale value="0.3"/></transform><emitter type="area"><rgb name="radiance" value="8"/></emitter></shape>
  <emitter type="point"><point name="position" x="-1" y="1.5" z="1"/><rgb name="intensity" value="2, 2, 3"/></emitter>
</scene>)",
                     integrator, spp);
}

TEST(Integrators, PathWithTwoSegmentsAgreesWithDirect) {
  // Two independent estimators of the same direct illumination (different sampling
  // strategies and MIS weights): per-pixel differences must average to zero.
  auto a = RenderXml(SmallBox(R"(<integrator type="path"><integer name="max_depth" value="2"/></integrator>)", 256));
  auto b = RenderXml(SmallBox(R"(<integrator type="direct"><integer name="emitter_samples" value="2"/>
      <integer name="bsdf_samples" value="3"/></integrator>)", 256));
  for (int c = 0; c < 3; ++c) {
    Image d(a.image.width, a.image.height, {"D"});
    for (int y = 0; y < d.height; ++y)
      for (int x = 0; x < d.width; ++x) d.At(x, y, 0) = a.image.At(x, y, c) - b.image.At(x, y, c);
    auto m = ChannelMean(d, 0);
    EXPECT_NEAR(m.mean, 0, 4 * m.se) << "channel " << c;
    EXPECT_GT(ChannelMean(a.image, c).mean, 0.05);  // the scene is lit
  }
}

// Renders with 1, 2 and 7 threads and different tile sizes; returns the first render.
test::RenderResult ExpectSameImageForAnyThreads(const std::string& xml) {
  auto one = RenderXml(xml, 1, 16);
  auto two = RenderXml(xml, 2, 4);
  auto many = RenderXml(xml, 7, 3);
  EXPECT_EQ(one.image.pixels.size(), two.image.pixels.size());
  EXPECT_EQ(one.image.pixels, two.image.pixels);
  EXPECT_EQ(one.image.pixels, many.image.pixels);
  return one;
}

TEST(Integrators, ImageIsIdenticalForAnyThreadCountAndTiling) {
  ExpectSameImageForAnyThreads(SmallBox(R"(<integrator type="path"><integer name="max_depth" value="6"/></integrator>)", 8));
}

TEST(Integrators, RealisticCameraImageIsIdenticalForAnyThreadCount) {
  // Camera rays made in batches per pixel (thread-local buffers), a dispersive lens (one
  // wavelength per ray), a bladed stop: still the same image for any threads and tiles.
  std::string xml = SmallBox(R"(<integrator type="path"><integer name="max_depth" value="4"/></integrator>)", 8);
  size_t a = xml.find("<sensor"), b = xml.find("</sensor>") + 9;
  xml.replace(a, b - a, R"(<sensor type="realistic">
    <string name="lens" value="tessar.brendel.100mm"/><float name="focal_length" value="30"/>
    <float name="fnumber" value="4"/><integer name="blades" value="6"/><float name="focus_distance" value="3.5"/>
    <float name="exposure_scale" value="16"/>
    <transform name="to_world"><lookat origin="0, 1, 3.5" target="0, 1, 0" up="0, 1, 0"/></transform>
    <sampler type="sobol"><integer name="sample_count" value="8"/></sampler>
    <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="16"/></film>
  </sensor>)");
  auto one = ExpectSameImageForAnyThreads(xml);
  EXPECT_GT(ChannelMean(one.image, 1).mean, 0.01);  // something is seen
  EXPECT_GT(one.stats.camera_rays_traced, 0u);
}

TEST(Integrators, ConvergesWithSampleCount) {
  // Error against a high-sample reference falls like 1/sqrt(spp) (not stuck on a bias).
  std::string ref_xml = SmallBox(R"(<integrator type="path"/>)", 1024);
  auto ref = RenderXml(ref_xml);
  auto err = [&](int spp) {
    auto r = RenderXml(SmallBox(R"(<integrator type="path"/>)", spp));
    double s = 0;
    for (size_t i = 0; i < r.image.pixels.size(); ++i) s += Sqr(r.image.pixels[i] - ref.image.pixels[i]);
    return std::sqrt(s / r.image.pixels.size());
  };
  double e16 = err(16), e64 = err(64);
  EXPECT_LT(e64, 0.75 * e16) << e16 << " -> " << e64;
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

std::string InstancingScene(const std::string& objects) {
  return fmt::format(R"(<scene version="3.0.0">
  <integrator type="path"><integer name="max_depth" value="4"/></integrator>
  <sensor type="perspective">
    <float name="fov" value="45"/>
    <transform name="to_world"><lookat origin="0, 1.5, 5" target="0, 0.5, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="16"/></sampler>
    <film type="hdrfilm"><integer name="width" value="24"/><integer name="height" value="24"/><rfilter type="box"/></film>
  </sensor>
  <emitter type="constant"><float name="radiance" value="0.5"/></emitter>
  <emitter type="directional"><vector name="direction" x="-1" y="-2" z="-1"/><float name="irradiance" value="3"/></emitter>
  <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="-90"/><scale value="4"/></transform></shape>
  {}
</scene>)",
                     objects);
}

TEST(Instancing, InstancesRenderLikeTheShapesThemselves) {
  const char* placements[2] = {R"(<translate x="-0.8" y="0.5"/>)", R"(<scale value="0.7"/><rotate y="1" angle="30"/><translate x="0.9" y="0.35" z="0.4"/>)"};
  std::string direct, group = R"(<shape type="shapegroup" id="g">
      <shape type="sphere"><float name="radius" value="0.5"/><bsdf type="plastic"/></shape>
      <shape type="cube"><transform name="to_world"><scale value="0.3"/><translate y="0.7"/></transform>
        <bsdf type="roughconductor"><string name="material" value="Cu"/></bsdf></shape></shape>)";
  std::string instances;
  for (const char* t : placements) {
    direct += fmt::format(R"(<shape type="sphere"><float name="radius" value="0.5"/><transform name="to_world">{}</transform>
      <bsdf type="plastic"/></shape>
      <shape type="cube"><transform name="to_world"><scale value="0.3"/><translate y="0.7"/>{}</transform>
      <bsdf type="roughconductor"><string name="material" value="Cu"/></bsdf></shape>)",
                          t, t);
    instances += fmt::format(R"(<shape type="instance"><ref id="g"/><transform name="to_world">{}</transform></shape>)", t);
  }
  auto a = test::RenderXml(InstancingScene(direct));
  auto b = test::RenderXml(InstancingScene(group + instances));
  // The same sample sequences meet the same surfaces: only float rounding differs.
  double diff = 0, sum = 0;
  for (size_t i = 0; i < a.image.pixels.size(); ++i) {
    diff += std::abs(a.image.pixels[i] - b.image.pixels[i]);
    sum += std::abs(a.image.pixels[i]);
  }
  EXPECT_LT(diff / sum, 1e-3);
  EXPECT_GT(sum / a.image.pixels.size(), 0.05);
}

// Camera rays are traced in packets (Scene::IntersectCoherent): every packet answer must be
// the single-ray one, for meshes, analytic shapes (user geometry called with N = 8),
// instances, misses, empty lanes and a count that is not a multiple of the packet size.
TEST(Scene, RaysEmbreeCannotTakeAreSkippedAndCounted) {
  // Debian's Embree has its assertions on: a non-finite origin or direction, or one beyond
  // 1.8e18, aborted the process (a shadow ray toward a vertex at 9.2e18).
  RenderSetup setup = LoadSceneFromString(InstancingScene(R"(<shape type="cube"/>)"), "test.xml", {});
  const Scene& scene = *setup.scene;
  const float nan = std::nanf(""), inf = std::numeric_limits<float>::infinity();
  const Ray good{{0, 0, 5}, {0, 0, -1}};
  const std::vector<Ray> bad = {Ray{{0, 0, 5}, {nan, 0, -1}}, Ray{{0, 2e18f, 5}, {0, 0, -1}}, Ray{{inf, 0, 5}, {0, 0, -1}},
                                Ray{{0, 0, 5}, {0, 0, -1}, nan}, Ray{{0, 0, 5}, {0, -3e18f, -1}}};
  ASSERT_TRUE(scene.Intersect(good));
  EXPECT_FALSE(scene.Occluded(Ray{{0, 0, 5}, {0, 0, 1}}));
  for (const Ray& r : bad) {
    EXPECT_FALSE(scene.Intersect(r));
    EXPECT_TRUE(scene.Occluded(r));  // no light along a ray that cannot be traced
  }
  std::vector<const Ray*> packet = {&good, &bad[0], &good, &bad[1], &bad[2]};
  std::vector<std::optional<SurfaceInteraction>> out(packet.size());
  scene.IntersectCoherent(packet, out);
  EXPECT_TRUE(out[0] && out[2]);
  EXPECT_FALSE(out[1] || out[3] || out[4]);
  EXPECT_EQ(scene.SkippedRays(), 2 * bad.size() + 3);
}

TEST(Scene, PacketIntersectionMatchesSingleRays) {
  std::string xml = InstancingScene(R"(<shape type="shapegroup" id="g">
      <shape type="sphere"><float name="radius" value="0.5"/></shape>
      <shape type="cube"><transform name="to_world"><scale value="0.3"/><translate y="0.7"/></transform></shape></shape>
    <shape type="instance"><ref id="g"/><transform name="to_world"><translate x="-0.8" y="0.5"/></transform></shape>
    <shape type="sphere"><point name="center" x="0.9" y="0.4" z="0.3"/><float name="radius" value="0.4"/></shape>
    <shape type="cylinder"><transform name="to_world"><scale value="0.2"/><translate x="0.1" y="0.1" z="1"/></transform></shape>
    <shape type="disk"><transform name="to_world"><scale value="0.3"/><translate x="-0.2" y="1.2" z="0.5"/></transform></shape>
    <shape type="cube"><transform name="to_world"><scale value="0.25"/><translate y="0.25" z="-0.6"/></transform></shape>)");
  RenderSetup setup = LoadSceneFromString(xml, "test.xml", {});
  const Scene& scene = *setup.scene;
  PCG32 rng(3, 5);
  std::vector<Ray> rays;
  for (int k = 0; k < 61; ++k) {
    // Mostly from the camera toward the objects (coherent), some in random directions.
    Vec3f o(0, 1.5f, 5);
    Vec3f target(rng.UniformFloat() * 3 - 1.5f, rng.UniformFloat() * 1.5f, rng.UniformFloat() * 2 - 1);
    Vec3f d = k % 5 == 4 ? SampleUniformSphere({rng.UniformFloat(), rng.UniformFloat()}) : Normalize(target - o);
    rays.push_back(Ray{o, d, k % 7 == 3 ? 4.5f : std::numeric_limits<float>::infinity()});
  }
  std::vector<const Ray*> ptrs;
  for (size_t k = 0; k < rays.size(); ++k) ptrs.push_back(k % 9 == 2 ? nullptr : &rays[k]);
  std::vector<std::optional<SurfaceInteraction>> out(rays.size(), SurfaceInteraction{});
  scene.IntersectCoherent(ptrs, out);
  int hits = 0, misses = 0;
  for (size_t k = 0; k < rays.size(); ++k) {
    if (!ptrs[k]) {
      EXPECT_FALSE(out[k]) << k;
      continue;
    }
    std::optional<SurfaceInteraction> single = scene.Intersect(rays[k]);
    ASSERT_EQ(single.has_value(), out[k].has_value()) << k;
    if (!single) {
      ++misses;
      continue;
    }
    ++hits;
    EXPECT_EQ(single->shape, out[k]->shape) << k;
    EXPECT_NEAR(single->t, out[k]->t, 1e-5f * single->t) << k;
    EXPECT_LT(Length(single->p - out[k]->p), 1e-5f) << k;
    EXPECT_GT(Dot(single->n, out[k]->n), 1 - 1e-5f) << k;
    EXPECT_NEAR(single->uv.x, out[k]->uv.x, 1e-4f) << k;
    EXPECT_NEAR(single->uv.y, out[k]->uv.y, 1e-4f) << k;
  }
  // Both kinds of answer were checked.
  EXPECT_GE(hits, 20);
  EXPECT_GE(misses, 5);
}

TEST(Instancing, InstancedShapesCannotEmit) {
  std::string xml = InstancingScene(R"(<shape type="shapegroup" id="g"><shape type="sphere">
      <emitter type="area"><rgb name="radiance" value="1"/></emitter></shape></shape>)");
  EXPECT_THROW(LoadSceneFromString(xml, "t.xml", {}), InputError);
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

// Radiance so large that the film's conversion and sums would overflow single precision (a sky
// of 1e37) is counted and dropped as Inf, never written as NaN pixels behind a summary of none.
TEST(FilmSafety, RadianceBeyondSinglePrecisionsReachIsCountedNotWrittenAsNaN) {
  const test::RenderResult r = test::RenderXml(R"(<scene version="3.0.0">
  <sensor type="perspective"><float name="fov" value="45"/>
    <sampler type="independent"><integer name="sample_count" value="4"/></sampler>
    <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="16"/></film></sensor>
  <shape type="sphere"><point name="center" x="0" y="0" z="3"/><bsdf type="diffuse"/></shape>
  <emitter type="constant"><rgb name="radiance" value="1e37"/></emitter>
</scene>)");
  EXPECT_EQ(r.stats.inf_count, 16u * 16u * 4u);
  for (float v : r.image.pixels) EXPECT_FALSE(std::isnan(v));
}

}  // namespace
}  // namespace objektiv
