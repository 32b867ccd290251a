// The cameras from the light's side (Camera::SampleImportance): light traced from an emitting
// rectangle through the realistic camera's front element and lens (or the pinhole, or a thin
// lens) to the film gives the image the camera's own rays give of it (the same lens, the same
// weights: vignetting, transmittance, the aperture mask), block by block within the two
// estimates' noise.
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "base/rng.h"
#include "io/scene_loader.h"
#include "render/renderer.h"

namespace objektiv {
namespace {

// A rectangle of radiance 1 (all wavelengths), 1 x 0.6 scene units, 3 units in front of a
// dgauss, off the axis and cut by the frame's edge.
constexpr float kHalfW = 0.5f, kHalfH = 0.3f, kCx = 0.55f, kCy = 0.1f, kZ = -3.f;

// `sensor`: the sensor's opening tag and its own properties (the frame, sampler and film follow).
std::string Scene(const std::string& sensor, int spp, int seed) {
  return fmt::format(R"(<scene version="3.0.0">
  <integrator type="path"><integer name="max_depth" value="1"/></integrator>
  {}
    <transform name="to_world"><lookat origin="0, 0, 0" target="0, 0, -1" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="{}"/><integer name="seed" value="{}"/></sampler>
    <film type="hdrfilm"><integer name="width" value="48"/><integer name="height" value="32"/><rfilter type="box"/></film>
  </sensor>
  <shape type="rectangle">
    <transform name="to_world"><scale x="{}" y="{}"/><translate x="{}" y="{}" z="{}"/></transform>
    <emitter type="area"><spectrum name="radiance" value="1"/></emitter>
  </shape>
</scene>)",
                     sensor, spp, seed, kHalfW, kHalfH, kCx, kCy, kZ);
}

// A dgauss at f/4 focused on the rectangle.
std::string Realistic(const std::string& extra) {
  return R"(<sensor type="realistic"><string name="lens" value="dgauss.50mm"/><float name="fnumber" value="4"/>
    <float name="focus_distance" value="3"/>)" + extra;
}

constexpr int kBlock = 8;  // blocks of 8 x 8 pixels: 6 x 4 of them

// Y per block: the camera rays' image.
std::vector<double> CameraBlocks(const std::string& xml) {
  RenderSetup setup = LoadSceneFromString(xml, "importance.xml", {});
  std::unique_ptr<Sampler> sampler = MakeSampler(setup.sampler);
  Film film(setup.film.width, setup.film.height, setup.film.crop, setup.film.filter);
  RenderOptions options;
  options.spp_end = sampler->spp();
  Render(*setup.camera, *setup.integrator, *sampler, film, options);
  const std::vector<float> xyz = film.Xyz();
  std::vector<double> blocks(24, 0);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 48; ++x) blocks[(y / kBlock) * 6 + x / kBlock] += xyz[3 * (y * 48 + x) + 1];
  return blocks;
}

struct LightBlocks {
  std::vector<double> sum = std::vector<double>(24, 0), se = std::vector<double>(24, 0);
  int reached = 0;
};

// The light's side: points uniform on the rectangle, each through a lens point of the camera's
// choice; one path per pixel sample (`spp` per pixel), each its own estimate of the blocks.
LightBlocks LightTraced(const std::string& xml, int spp) {
  RenderSetup setup = LoadSceneFromString(xml, "importance.xml", {});
  const Camera& camera = *setup.camera;
  const int paths = 48 * 32 * spp;
  const double area = 4 * kHalfW * kHalfH;
  std::vector<double> sum2(24, 0);
  LightBlocks out;
  PCG32 rng(11, 5);
  for (int k = 0; k < paths; ++k) {
    const Vec3f p(kCx + (2 * rng.UniformFloat() - 1) * kHalfW, kCy + (2 * rng.UniformFloat() - 1) * kHalfH, kZ);
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(rng.UniformFloat());
    const Vec2f u(rng.UniformFloat(), rng.UniformFloat());
    const std::optional<CameraImportance> imp = camera.SampleImportance(p, u, lambda);
    if (!imp) continue;
    ++out.reached;
    // Intensity toward the lens point: radiance 1 times the cosine at the rectangle (normal +z)
    // over the point's density 1 / area.
    const Vec3f to = Normalize(imp->p_lens - p);
    const SampledSpectrum J(float(to.z * area));
    const double y = SampledToXYZ(J * imp->weight, lambda).y / spp;  // the film divides splats by spp
    const int bx = int(imp->p_film.x) / kBlock, by = int(imp->p_film.y) / kBlock;
    out.sum[by * 6 + bx] += y;
    sum2[by * 6 + bx] += y * y;
  }
  // Each path adds y to one block or nothing: the sum's variance is about the sum of squares.
  for (int b = 0; b < 24; ++b) out.se[b] = std::sqrt(sum2[b]);
  return out;
}

void ExpectSameImage(const std::string& sensor) {
  // The camera's image twice (two seeds): their difference measures its noise.
  const std::vector<double> a = CameraBlocks(Scene(sensor, 64, 1)), b = CameraBlocks(Scene(sensor, 64, 2));
  const LightBlocks light = LightTraced(Scene(sensor, 1, 1), 160);
  ASSERT_GT(light.reached, 1000);
  double diff2 = 0, mean2 = 0, total_camera = 0, total_light = 0, total_var = 0;
  for (int k = 0; k < 24; ++k) {
    diff2 += (a[k] - b[k]) * (a[k] - b[k]);
    mean2 += (a[k] + b[k]) * (a[k] + b[k]) / 4;
  }
  // The camera's relative noise per block, pooled (the two images' difference has twice the
  // variance of one, four times that of their mean).
  const double camera_rel = std::sqrt(diff2 / mean2 / 4);
  int lit = 0;
  for (int k = 0; k < 24; ++k) {
    const double camera = (a[k] + b[k]) / 2;
    const double se = std::sqrt(light.se[k] * light.se[k] + camera * camera * camera_rel * camera_rel);
    EXPECT_NEAR(light.sum[k], camera, 4 * se + 1e-9) << "block " << k << " " << sensor;
    lit += camera > 0;
    total_camera += camera;
    total_light += light.sum[k];
    total_var += light.se[k] * light.se[k];
  }
  EXPECT_GE(lit, 6);
  EXPECT_NEAR(total_light, total_camera, 4 * std::sqrt(total_var) + 4 * camera_rel * total_camera / std::sqrt(24.0));
  EXPECT_LT(4 * std::sqrt(total_var), 0.03 * total_camera);  // a test that can tell a 3% error
}

TEST(CameraImportance, LightTracedImageMatchesTheCameraRays) { ExpectSameImage(Realistic("")); }

TEST(CameraImportance, FollowsExposureMaskAndOpticalVignetting) {
  ExpectSameImage(Realistic(R"(<float name="exposure_scale" value="2"/><string name="vignetting" value="aperture"/>
    <integer name="blades" value="5"/><string name="coating" value="MgF2"/>)"));
}

// The ideal cameras from the light's side: the pinhole (the rectangle cut by the frame's
// edge at a field of 36 degrees), and a thin lens focused in front of it (blurred), round and
// with five blades.
TEST(CameraImportance, PinholeAndThinLensLightTracedMatchTheirCameraRays) {
  ExpectSameImage(R"(<sensor type="perspective"><float name="fov" value="36"/>)");
  ExpectSameImage(R"(<sensor type="thinlens"><float name="fov" value="36"/><float name="aperture_radius" value="0.08"/>
    <float name="focus_distance" value="2"/>)");
  ExpectSameImage(R"(<sensor type="thinlens"><float name="fov" value="36"/><float name="aperture_radius" value="0.08"/>
    <float name="focus_distance" value="2"/><integer name="blades" value="5"/><float name="blade_rotation" value="20"/>)");
}

}  // namespace
}  // namespace objektiv
