// The stereo rig (camera/stereo_camera.h, <sensor type="stereo">): the eyes' geometry in closed
// form for every kind of camera (the zero-parallax plane, the parallel frusta's disparity f b / Z,
// the eyes' places), the film's layouts, the left half of a render against a mono render from
// the left eye, the real lens's eyes, light tracing through the rig against the path tracer,
// Dubois' anaglyph, and the scene errors.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include <fmt/format.h>

#include "base/error.h"
#include "camera/stereo_camera.h"
#include "io/anaglyph.h"
#include "image_estimates.h"
#include "render_helpers.h"
#include "sanitizer_build.h"

namespace objektiv {
namespace {

using test::Estimate;
using test::ExpectSameImage;
using test::RenderXml;

constexpr double kSeparation = 0.065, kConvergence = 3;
const Transform kRig = Transform::LookAt(Vec3d(0.3, 1.2, 3), Vec3d(0.1, 1.0, 0), Vec3d(0, 1, 0));
const char* kRigLookAt = R"(<lookat origin="0.3, 1.2, 3" target="0.1, 1.0, 0" up="0, 1, 0"/>)";

// A scene of a stereo sensor (its own properties `rig`) around `inner` (its type and
// properties; to_world is the rig's), with a film of one eye's `w` x `h` pixels.
std::string StereoScene(const std::string& rig, const std::string& inner, int w = 64, int h = 48) {
  return fmt::format(R"(<scene version="3.0.0">
  <sensor type="stereo">{}
    <sensor {}<transform name="to_world">{}</transform></sensor>
    <film type="hdrfilm"><integer name="width" value="{}"/><integer name="height" value="{}"/></film>
  </sensor>
</scene>)",
                     rig, inner, kRigLookAt, w, h);
}

struct Rig {
  RenderSetup setup;
  const StereoCamera& camera() const { return dynamic_cast<const StereoCamera&>(*setup.camera); }
};
Rig LoadRig(const std::string& xml) { return {LoadSceneFromString(xml, "test.xml", {})}; }

std::string OffAxis(const char* layout = "side-by-side") {
  return fmt::format(R"(<float name="eye_separation" value="{}"/><float name="convergence_distance" value="{}"/>
    <string name="layout" value="{}"/>)", kSeparation, kConvergence, layout);
}
std::string Parallel() {
  return fmt::format(R"(<float name="eye_separation" value="{}"/><string name="frustum" value="parallel"/>)", kSeparation);
}

// Where eye `e` images world point p, in that eye's pixel coordinates, through its lens point u
// (the lens's centre by default), by the camera's importance.
std::optional<Vec2f> EyePixel(const StereoCamera& rig, int e, const Vec3f& p, Vec2f u = Vec2f(0.5f, 0.5f)) {
  SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
  const Vec2f ur(e == 0 ? u.x / 2 : 0.5f + u.x / 2, u.y);
  std::optional<CameraImportance> imp = rig.SampleImportance(p, ur, lambda);
  if (!imp) return std::nullopt;
  const Vec2i o = rig.EyeOrigin(e);
  // The eye's part of the film.
  EXPECT_EQ(rig.EyeOf(Vec2i(int(imp->p_film.x), int(imp->p_film.y))), e);
  return Vec2f(imp->p_film.x - float(o.x), imp->p_film.y - float(o.y));
}

Vec3f RigPoint(double x, double y, double z) { return kRig.Point(Vec3f(float(x), float(y), float(z))); }

TEST(Stereo, FilmLayouts) {
  const Rig sbs = LoadRig(StereoScene(OffAxis(), R"(type="perspective">)"));
  EXPECT_EQ(sbs.setup.film.width, 128);
  EXPECT_EQ(sbs.setup.film.height, 48);
  EXPECT_EQ(sbs.camera().EyeOrigin(1), Vec2i(64, 0));
  const Rig ou = LoadRig(StereoScene(OffAxis("over-under"), R"(type="perspective">)"));
  EXPECT_EQ(ou.setup.film.width, 64);
  EXPECT_EQ(ou.setup.film.height, 96);
  EXPECT_EQ(ou.camera().EyeOrigin(1), Vec2i(0, 48));
  const Rig ana = LoadRig(StereoScene(OffAxis("anaglyph"), R"(type="perspective">)"));
  EXPECT_EQ(ana.setup.film.width, 128);  // rendered side by side, combined when written
  EXPECT_EQ(ana.camera().layout(), StereoLayout::kAnaglyph);
}

// Off-axis frusta: every point of the plane at the convergence distance images to the same
// pixel in both eyes (pinhole, thin lens focused there, both layouts); a point beyond it lies
// further right in the right eye's image by f b (1/C - 1/Z) pixels, a nearer one further left.
TEST(Stereo, OffAxisConvergencePlaneHasZeroParallax) {
  for (const char* layout : {"side-by-side", "over-under"})
    for (const std::string& inner : {std::string(R"(type="perspective"><float name="fov" value="45"/>)"),
                                    fmt::format(R"(type="thinlens"><float name="fov" value="45"/>
                                    <float name="aperture_radius" value="0.02"/><float name="focus_distance" value="{}"/>)",
                                                kConvergence)}) {
      const Rig rig = LoadRig(StereoScene(OffAxis(layout), inner));
      const StereoCamera& cam = rig.camera();
      for (const Vec2f xy : {Vec2f(0, 0), Vec2f(0.5f, 0.3f), Vec2f(-0.7f, -0.4f)}) {
        const Vec3f p = RigPoint(xy.x, xy.y, kConvergence);
        for (const Vec2f u : {Vec2f(0.5f, 0.5f), Vec2f(0.1f, 0.8f)}) {  // any lens point: the plane is in focus
          const auto l = EyePixel(cam, 0, p, u), r = EyePixel(cam, 1, p, u);
          ASSERT_TRUE(l && r) << layout << " " << inner;
          EXPECT_NEAR(l->x, r->x, 2e-3) << layout << " " << inner;
          EXPECT_NEAR(l->y, r->y, 2e-3) << layout << " " << inner;
        }
      }
      const double f = 64 / (2 * std::tan(Radians(22.5)));  // focal length, pixels
      for (const double z : {1.5, 6.0}) {
        const auto l = EyePixel(cam, 0, RigPoint(0.2, 0.1, z)), r = EyePixel(cam, 1, RigPoint(0.2, 0.1, z));
        ASSERT_TRUE(l && r);
        EXPECT_NEAR(r->x - l->x, f * kSeparation * (1 / kConvergence - 1 / z), 3e-3) << z;
        EXPECT_NEAR(r->y, l->y, 2e-3);
      }
    }
}

// Parallel frusta: the disparity of a point at depth Z is f b / Z pixels, the left eye's image
// of it further right; no vertical disparity.
TEST(Stereo, ParallelFrustaDisparityIsFocalLengthTimesBaseOverDepth) {
  const Rig rig = LoadRig(StereoScene(Parallel(), R"(type="perspective"><float name="fov" value="45"/>)"));
  const double f = 64 / (2 * std::tan(Radians(22.5)));
  for (const double z : {0.8, 2.0, 7.5})
    for (const Vec2f xy : {Vec2f(0, 0), Vec2f(-0.2f, 0.15f)}) {
      const Vec3f p = RigPoint(xy.x * z, xy.y * z, z);
      const auto l = EyePixel(rig.camera(), 0, p), r = EyePixel(rig.camera(), 1, p);
      ASSERT_TRUE(l && r);
      EXPECT_NEAR(l->x - r->x, f * kSeparation / z, 2e-3) << z;
      EXPECT_NEAR(l->y, r->y, 2e-3) << z;
    }
}

// Each eye's rays leave from the rig's place moved by +-b/2 along the camera's x axis (+x: the
// camera's left, the left eye's side).
TEST(Stereo, EyesSitHalfTheSeparationLeftAndRight) {
  for (const std::string& props : {Parallel(), OffAxis(), OffAxis("over-under")}) {
    const Rig rig = LoadRig(StereoScene(props, R"(type="perspective"><float name="fov" value="45"/>)"));
    const StereoCamera& cam = rig.camera();
    const Vec3f origin = kRig.Point(Vec3f(0.f)), left_axis = Normalize(kRig.Vector(Vec3f(1, 0, 0)));
    for (int e = 0; e < 2; ++e) {
      const Vec3f eye = origin + left_axis * float(e == 0 ? kSeparation / 2 : -kSeparation / 2);
      const Vec2i o = cam.EyeOrigin(e);
      for (const Vec2f p : {Vec2f(32, 24), Vec2f(3.5f, 40.2f)}) {
        SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
        CameraSample s{Vec2f(p.x + float(o.x), p.y + float(o.y)), Vec2f(0.5f, 0.5f)};
        const std::optional<CameraRay> ray = cam.GenerateRay(s, lambda);
        ASSERT_TRUE(ray);
        // The ray's line passes through the eye, and it starts in front of it.
        EXPECT_LT(Length(Cross(ray->ray.o - eye, ray->ray.d)), 1e-5) << props << " eye " << e;
        EXPECT_GT(Dot(ray->ray.o - eye, ray->ray.d), 0);
      }
    }
  }
}

// Orthographic eyes turn toward the convergence plane: points on it keep their pixel in both
// eyes, points beyond it move apart as through the pinhole (further right in the right eye).
Vec2f OrthographicPixel(const Camera& eye, const Vec3f& p) {
  auto ray = [&](Vec2f film) {
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    return eye.GenerateRay(CameraSample{film, Vec2f(0.5f, 0.5f)}, lambda)->ray;
  };
  // The ray's origin is affine in the film point and its direction fixed: solve p = o + a ex + b ey + t d.
  const Ray r0 = ray(Vec2f(0, 0)), rx = ray(Vec2f(1, 0)), ry = ray(Vec2f(0, 1));
  const Vec3f ex = rx.o - r0.o, ey = ry.o - r0.o, q = p - r0.o;
  const float det = Dot(ex, Cross(ey, r0.d));
  return {Dot(q, Cross(ey, r0.d)) / det, Dot(ex, Cross(q, r0.d)) / det};
}

TEST(Stereo, OrthographicEyesTurnTowardTheConvergencePlane) {
  const Rig rig = LoadRig(StereoScene(OffAxis(), R"(type="orthographic">)"));
  const StereoCamera& cam = rig.camera();
  for (const Vec2f xy : {Vec2f(0, 0), Vec2f(0.4f, -0.3f), Vec2f(-0.6f, 0.2f)}) {
    const Vec2f l = OrthographicPixel(cam.eye(0), RigPoint(xy.x, xy.y, kConvergence));
    const Vec2f r = OrthographicPixel(cam.eye(1), RigPoint(xy.x, xy.y, kConvergence));
    EXPECT_NEAR(l.x, r.x, 1e-3);
    EXPECT_NEAR(l.y, r.y, 1e-3);
  }
  // Depth z - C shows as the disparity 2 (z - C) sin(theta) (camera-space units: the film spans
  // 2 across its 64 pixels), sin(theta) = b / 2 over the eye's distance from the pivot.
  const double sin_theta = (kSeparation / 2) / std::hypot(kConvergence, kSeparation / 2);
  for (const double z : {1.0, 5.0}) {
    const Vec2f l = OrthographicPixel(cam.eye(0), RigPoint(0.1, 0.1, z));
    const Vec2f r = OrthographicPixel(cam.eye(1), RigPoint(0.1, 0.1, z));
    EXPECT_NEAR(r.x - l.x, 2 * (z - kConvergence) * sin_theta * 64 / 2, 1e-2) << z;
    EXPECT_NEAR(r.y, l.y, 1e-3);
  }
}

// The real lens's eyes: the sensor shifted sideways as a shift lens, so that a point on the
// convergence plane lands on the same pixel in both (its blur's centroid, over the front element).
TEST(Stereo, RealLensEyesConvergeBySensorShift) {
  const Rig rig = LoadRig(StereoScene(OffAxis(), fmt::format(R"(type="realistic"><string name="lens" value="dgauss.50mm"/>
      <float name="fnumber" value="8"/><float name="focus_distance" value="{}"/>)", kConvergence + 0.1), 320, 240));
  const StereoCamera& cam = rig.camera();
  for (const Vec2f xy : {Vec2f(0, 0), Vec2f(0.3f, 0.2f)}) {
    const Vec3f p = RigPoint(xy.x, xy.y, kConvergence);
    Vec2f mean[2];
    for (int e = 0; e < 2; ++e) {
      Vec2f sum(0, 0);
      int n = 0;
      // Over the front element: at f/8 about 1 point in 16 gets through the stop.
      for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j)
          if (auto px = EyePixel(cam, e, p, Vec2f((i + 0.5f) / 64, (j + 0.5f) / 64))) sum = sum + *px, ++n;
      ASSERT_GT(n, 100);
      mean[e] = sum * (1.f / float(n));
    }
    // The unshifted eyes would see it 2 f b / (2 C) = 1.1 mm (about 10 pixels) apart.
    EXPECT_NEAR(mean[0].x, mean[1].x, 0.25) << xy.x;
    EXPECT_NEAR(mean[0].y, mean[1].y, 0.25) << xy.x;
  }
}

// A scene symmetric about the plane x = 0, the rig on it looking down -z (its x axis along -x).
std::string SymmetricRoom(const std::string& stereo_props, const std::string& inner, int w, int h, int spp, int seed,
                          const char* integrator = "path") {
  return fmt::format(R"(<scene version="3.0.0">
  <integrator type="{}"/>
  <sensor type="stereo">{}
    <sensor {}<transform name="to_world"><lookat origin="0, 1, 3.2" target="0, 1, 0" up="0, 1, 0"/></transform></sensor>
    <sampler type="independent"><integer name="sample_count" value="{}"/><integer name="seed" value="{}"/></sampler>
    <film type="hdrfilm"><integer name="width" value="{}"/><integer name="height" value="{}"/><rfilter type="box"/></film>
  </sensor>
  <bsdf type="diffuse" id="white"><rgb name="reflectance" value="0.7, 0.7, 0.7"/></bsdf>
  <bsdf type="diffuse" id="red"><rgb name="reflectance" value="0.7, 0.1, 0.1"/></bsdf>
  <shape type="rectangle"><transform name="to_world"><scale value="2"/><rotate x="1" angle="-90"/></transform><ref id="white"/></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="2"/><translate y="1" z="-1"/></transform><ref id="white"/></shape>
  <shape type="sphere"><point name="center" x="0" y="0.35" z="-0.2"/><float name="radius" value="0.35"/><ref id="white"/></shape>
  <shape type="sphere"><point name="center" x="-0.6" y="0.25" z="0.3"/><float name="radius" value="0.25"/><ref id="red"/></shape>
  <shape type="sphere"><point name="center" x="0.6" y="0.25" z="0.3"/><float name="radius" value="0.25"/><ref id="red"/></shape>
  <emitter type="point"><point name="position" x="0" y="1.8" z="0.6"/><rgb name="intensity" value="3, 3, 3"/></emitter>
</scene>)",
                     integrator, stereo_props, inner, spp, seed, w, h);
}

// Y summed per block of 8 x 8 pixels of a region of an image (`mirror`: columns reversed).
std::vector<double> Blocks(const Image& img, Vec2i origin, int w, int h, bool mirror = false) {
  std::vector<double> b(size_t(w / 8) * (h / 8), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int sx = origin.x + (mirror ? w - 1 - x : x), sy = origin.y + y;
      const double Y = 0.2126 * img.At(sx, sy, 0) + 0.7152 * img.At(sx, sy, 1) + 0.0722 * img.At(sx, sy, 2);
      b[size_t(y / 8) * (w / 8) + x / 8] += Y;
    }
  return b;
}

// The real lens in a rig renders: nearly every camera ray passes, and the symmetric scene's
// left image is the right one mirrored (within the noise).
TEST(Stereo, RealLensRigRendersSymmetricImages) {
  SKIP_UNDER_SANITIZERS("Stereo.LightTracingThroughTheRigMatchesThePathTracer and Stereo.RealLensEyesConvergeBySensorShift");
  const std::string inner = R"(type="realistic"><string name="lens" value="dgauss.50mm"/><float name="fnumber" value="5.6"/>
      <float name="focus_distance" value="3"/><float name="sensor_width" value="24"/><float name="sensor_height" value="24"/>)";
  const std::string props = R"(<float name="convergence_distance" value="3.2"/>)";
  double pass_rate = 0;
  auto eye = [&](int e) {
    return test::EstimatedBlocks([&, e](int seed) {
      const test::RenderResult r = RenderXml(SymmetricRoom(props, inner, 32, 32, 16, seed));
      pass_rate = *r.stats.CameraPassRate();
      return Blocks(r.image, Vec2i(e == 0 ? 0 : 32, 0), 32, 32, e == 1);
    });
  };
  const Estimate left = eye(0), right_mirrored = eye(1);
  EXPECT_GT(pass_rate, 0.95);
  ExpectSameImage(left, right_mirrored, 0.05, "left eye against the right eye mirrored");
}

// The left half of a side-by-side render is the render of a mono camera at the left eye's place:
// the same pixels draw the same numbers, so bit for bit (a wide filter's samples beyond the seam
// look through the left eye, as the mono camera's beyond its film's edge do); the right half,
// whose pixels draw other numbers, equals the right eye's mono render within the noise.
std::string MonoOrStereo(const std::string& sensor_open, const std::string& transform, const std::string& sensor_close,
                         int width) {
  return fmt::format(R"(<scene version="3.0.0">
  {}
    <sensor type="perspective"><float name="fov" value="40"/>
      <transform name="to_world">{}<lookat origin="0, 1, 3.2" target="0, 1, 0" up="0, 1, 0"/></transform>{}
    <sampler type="independent"><integer name="sample_count" value="8"/></sampler>
    <film type="hdrfilm"><integer name="width" value="{}"/><integer name="height" value="24"/></film>
  </sensor>
  <bsdf type="diffuse" id="white"><rgb name="reflectance" value="0.7, 0.7, 0.7"/></bsdf>
  <shape type="rectangle"><transform name="to_world"><scale value="2"/><rotate x="1" angle="-90"/></transform><ref id="white"/></shape>
  <shape type="sphere"><point name="center" x="-0.2" y="0.5" z="-0.2"/><float name="radius" value="0.5"/><ref id="white"/></shape>
  <shape type="sphere"><point name="center" x="0.5" y="1.5" z="-1"/><float name="radius" value="0.3"/>
    <emitter type="area"><rgb name="radiance" value="8, 8, 8"/></emitter></shape>
</scene>)",
                     sensor_open, transform, sensor_close, width);
}

TEST(Stereo, LeftHalfIsTheMonoRenderFromTheLeftEye) {
  // Separation 0.5: the eyes' offsets 0.25 are exact in binary, as the mono scene's translations.
  const Image stereo = RenderXml(MonoOrStereo(R"(<sensor type="stereo"><float name="eye_separation" value="0.5"/>
    <string name="frustum" value="parallel"/>)", "", "</sensor>", 32)).image;
  const Image left = RenderXml(MonoOrStereo("", R"(<translate x="0.25"/>)", "", 32)).image;
  ASSERT_EQ(stereo.width, 64);
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) ASSERT_EQ(stereo.At(x, y, c), left.At(x, y, c)) << x << "," << y;
  const Image right = RenderXml(MonoOrStereo("", R"(<translate x="-0.25"/>)", "", 32)).image;
  Image right_half(32, 24, {"R", "G", "B"});
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) right_half.At(x, y, c) = stereo.At(x + 32, y, c);
  bool differs = false;
  for (int c = 0; c < 3; ++c) {
    const test::MeanSe a = test::ChannelMean(right_half, c), b = test::ChannelMean(right, c);
    EXPECT_NEAR(a.mean, b.mean, 4 * std::hypot(a.se, b.se));
    differs = differs || a.mean != b.mean;
  }
  EXPECT_TRUE(differs);  // other random numbers: not the same image by accident of the seed
}

// Light paths reach the rig's film through either eye: the light tracer's image equals the path
// tracer's (side by side and over-under).
TEST(Stereo, LightTracingThroughTheRigMatchesThePathTracer) {
  for (const char* layout : {"side-by-side", "over-under"}) {
    const std::string props = fmt::format(R"(<float name="convergence_distance" value="3"/>
      <string name="layout" value="{}"/>)", layout);
    const char* inner = R"(type="perspective"><float name="fov" value="50"/>)";
    const int w = std::string(layout) == "over-under" ? 32 : 64, h = std::string(layout) == "over-under" ? 64 : 32;
    const Estimate path = test::EstimatedBlocks([&](int seed) {
      return Blocks(RenderXml(SymmetricRoom(props, inner, 32, 32, 16, seed)).image, Vec2i(0, 0), w, h);
    });
    const Estimate light = test::EstimatedBlocks([&](int seed) {
      return Blocks(RenderXml(SymmetricRoom(props, inner, 32, 32, 32, seed, "ptracer")).image, Vec2i(0, 0), w, h);
    });
    ExpectSameImage(path, light, 0.03, layout);
  }
}

TEST(Stereo, DuboisMatricesMapKnownColours) {
  auto expect = [](Vec3f l, Vec3f r, Vec3f want) {
    const Vec3f a = DuboisRedCyan(l, r);
    EXPECT_NEAR(a.x, want.x, 1e-6);
    EXPECT_NEAR(a.y, want.y, 1e-6);
    EXPECT_NEAR(a.z, want.z, 1e-6);
  };
  // White to the left eye alone: red (0.437 + 0.449 + 0.164 = 1.05, clipped; the rest negative).
  expect(Vec3f(1, 1, 1), Vec3f(0, 0, 0), Vec3f(1, 0, 0));
  // White to the right eye alone: cyan (green 1.147, blue 1.115 clipped; red -0.05 clipped).
  expect(Vec3f(0, 0, 0), Vec3f(1, 1, 1), Vec3f(0, 1, 1));
  // Each primary of one eye: the matrices' columns, clipped below at 0.
  expect(Vec3f(0, 1, 0), Vec3f(0, 0, 0), Vec3f(0.449f, 0, 0));
  expect(Vec3f(0, 0, 0), Vec3f(0, 0, 1), Vec3f(0, 0.009f, 1));
  expect(Vec3f(0, 0, 0), Vec3f(0, 1, 0), Vec3f(0, 0.761f, 0));
  // Unclipped: the sums of both products, worked by hand.
  expect(Vec3f(0.2f, 0.3f, 0.4f), Vec3f(0.1f, 0.2f, 0.3f), Vec3f(0.2781f, 0.1520f, 0.3176f));
}

TEST(Stereo, AnaglyphImageCombinesTheEyesAndKeepsThemAsLayers) {
  // A 2 x 1 side-by-side image: an HDR white left (the clamp tone curve takes it to 1), black right.
  Image sbs(2, 1, {"R", "G", "B", "depth"});
  for (int c = 0; c < 3; ++c) sbs.At(0, 0, c) = 4, sbs.At(1, 0, c) = 0;
  sbs.At(0, 0, 3) = 2.5f, sbs.At(1, 0, 3) = 3.5f;
  const Image a = AnaglyphImage(sbs, ColorSpace::Rec709(), ToneMap::kClamp);
  ASSERT_EQ(a.width, 1);
  const std::vector<std::string> names = {"R", "G", "B", "left.R", "left.G", "left.B", "left.depth",
                                          "right.R", "right.G", "right.B", "right.depth"};
  EXPECT_EQ(a.channels, names);
  EXPECT_EQ(a.Rgb(0, 0), Vec3f(1, 0, 0));
  EXPECT_EQ(a.At(0, 0, 3), 4);  // the eyes' linear values, unclipped
  EXPECT_EQ(a.At(0, 0, 6), 2.5f);
  EXPECT_EQ(a.At(0, 0, 10), 3.5f);
  // An ACEScg film's white is white in Rec.709 too: the same anaglyph.
  Image aces(2, 1, {"R", "G", "B"});
  for (int c = 0; c < 3; ++c) aces.At(0, 0, c) = 0.5f, aces.At(1, 0, c) = 0.5f;
  const Vec3f want = DuboisRedCyan(Vec3f(0.5f), Vec3f(0.5f));
  const Vec3f got = AnaglyphImage(aces, ColorSpace::ACEScg(), ToneMap::kClamp).Rgb(0, 0);
  EXPECT_NEAR(got.x, want.x, 1e-3);
  EXPECT_NEAR(got.y, want.y, 1e-3);
  EXPECT_NEAR(got.z, want.z, 1e-3);
}

struct BadCase {
  std::string rig, inner;
  int line;  // in StereoScene's text: 2 the stereo sensor, 3 + the rig's lines the inner one
  std::string message_part;
};

TEST(Stereo, BadRigsNameFileAndLine) {
  const char* persp = R"(type="perspective">)";
  const std::vector<BadCase> cases = {
      {R"(<float name="eye_separation" value="-0.065"/><float name="convergence_distance" value="3"/>)", persp, 2,
       "eye_separation must be a distance above 0"},
      {R"(<float name="eye_separation" value="0"/><float name="convergence_distance" value="3"/>)", persp, 2,
       "eye_separation must be a distance above 0"},
      {R"(<float name="convergence_distance" value="0"/>)", persp, 2, "convergence_distance must be a distance above 0"},
      {R"(<float name="convergence_distance" value="-2"/>)", persp, 2, "convergence_distance must be a distance above 0"},
      {R"(<float name="eye_separation" value="1e6"/><float name="convergence_distance" value="3"/>)", persp, 2,
       "below 1e6 (metres), got 1000000"},
      {R"(<string name="layout" value="top-bottom"/>)", persp, 2, "is not one of: side-by-side, over-under, anaglyph"},
      {R"(<string name="frustum" value="toe-in"/>)", persp, 2, "is not one of: offaxis, parallel"},
      {"", persp, 2, "needs convergence_distance"},
      {R"(<string name="frustum" value="parallel"/>)", R"(type="orthographic">)", 2, "no depth"},
      {R"(<float name="convergence_distance" value="3"/>)", R"(type="stereo">)", 3, "cannot wrap another stereo"},
      {R"(<float name="convergence_distance" value="3"/>)",
       R"(type="perspective"><film type="hdrfilm"/>)", 3, "belongs in the stereo sensor"},
      {R"(<float name="convergence_distance" value="3"/>)",
       R"(type="realistic"><string name="lens" value="dgauss.50mm"/>
         <boolean name="ghosts" value="true"/>)", 4, "ghosts in a stereo rig"},
      {R"(<float name="convergence_distance" value="3"/>)",
       R"(type="realistic"><string name="lens" value="dgauss.50mm"/>
         <string name="diffraction" value="emitters"/>)", 4, "diffraction in a stereo rig"},
  };
  for (const BadCase& c : cases) {
    const std::string xml = StereoScene(c.rig, c.inner);
    try {
      LoadSceneFromString(xml, "bad.xml", {});
      ADD_FAILURE() << "no error for:\n" << xml;
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind("bad.xml:" + std::to_string(c.line) + ":", 0), 0u) << msg;
      EXPECT_NE(msg.find(c.message_part), std::string::npos) << msg;
    }
  }
}

TEST(Stereo, MissingOrMisplacedPartsAreErrors) {
  auto expect_error = [](const std::string& xml, int line, const std::string& part) {
    try {
      LoadSceneFromString(xml, "bad.xml", {});
      ADD_FAILURE() << "no error for:\n" << xml;
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind("bad.xml:" + std::to_string(line) + ":", 0), 0u) << msg;
      EXPECT_NE(msg.find(part), std::string::npos) << msg;
    }
  };
  expect_error(R"(<scene version="3.0.0">
  <sensor type="stereo"><float name="convergence_distance" value="3"/></sensor>
</scene>)", 2, "exactly one nested <sensor>, got 0");
  expect_error(R"(<scene version="3.0.0">
  <sensor type="stereo"><float name="convergence_distance" value="3"/>
    <sensor type="perspective"/><sensor type="perspective"/></sensor>
</scene>)", 2, "exactly one nested <sensor>, got 2");
  expect_error(R"(<scene version="3.0.0">
  <sensor type="stereo"><float name="convergence_distance" value="3"/>
    <transform name="to_world"><translate x="1"/></transform>
    <sensor type="perspective"/></sensor>
</scene>)", 3, "give to_world to the nested <sensor>");
  expect_error(R"(<scene version="3.0.0">
  <sensor type="stereo"><float name="convergence_distance" value="3"/>
    <sensor type="perspective"/>
    <film type="hdrfilm"><integer name="crop_width" value="10"/></film></sensor>
</scene>)", 4, "cannot be cropped");
}

}  // namespace
}  // namespace objektiv
