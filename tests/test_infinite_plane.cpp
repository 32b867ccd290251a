// The infinite plane (<shape type="plane">): exact hits near and far, seen by the camera with
// the radiance a diffuse plane must have, casting and receiving shadows.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <functional>

#include "base/error.h"
#include "render_helpers.h"
#include "scene/analytic_shape.h"
#include "base/ray.h"
#include "scene/scene.h"

namespace objektiv {
namespace {

using test::RenderXml;

// The plane y = h facing +y (object z = 0 turned up), and one tilted 30 degrees about z.
Transform Horizontal(double h) { return Transform::Translate({0, h, 0}) * Transform::Rotate(-90, {1, 0, 0}); }
Transform Tilted() { return Transform::Translate({0.2, -0.5, 0.1}) * Transform::Rotate(30, {0, 0, 1}) * Transform::Rotate(-90, {1, 0, 0}); }
// v rounded to float as it is stored (GCC 12 may drop the rounding of a double to float when
// the float is converted back to double in the same expression chain).
Vec3f StoredFloat(const Vec3d& v) {
  volatile float x = float(v.x), y = float(v.y), z = float(v.z);
  return {x, y, z};
}

// The world normal in double (the inverse transpose applied to +z).
Vec3d PlaneNormal(const Transform& t) {
  const auto& m = t.InverseMatrix().m;
  return Normalize(Vec3d(m[2][0], m[2][1], m[2][2]));
}

// Rays from o falling toward the plane at shallower and shallower angles: hits at distances
// from 2 to 1e17, the default far clip (1e4) among them. A float direction cannot aim at a
// tilted plane more finely than its rounding (6e-8 rad): there the far hits end at 1e6.
TEST(InfinitePlane, IntersectsExactlyNearAndFar) {
  for (auto [to_world, farthest] : {std::pair{Horizontal(-0.5), 1e17}, std::pair{Tilted(), 1e6}}) {
    InfinitePlane plane(to_world, false);
    const Vec3d n = PlaneNormal(to_world);
    const Vec3d p0 = to_world.Point(Vec3d(0, 0, 0));
    Scene scene;
    scene.AddShape(std::make_unique<InfinitePlane>(to_world, false), nullptr);
    scene.Commit();
    const Vec3f o(0.3f, 1.0f, -0.2f);
    const double height = Dot(Vec3d(o) - p0, n);  // above the plane
    ASSERT_GT(height, 0);
    for (double distance : {2.0, 1e3, 1e4, 1e6, 1e8, 1e12, 1e17}) {
      if (distance > farthest) break;
      // Down the plane's normal by height / distance, the rest along the plane.
      Vec3d along = Normalize(Cross(n, Vec3d(0, 0, 1)));
      double sin_a = height / distance;
      Vec3f d = StoredFloat(along * std::sqrt(1 - sin_a * sin_a) - n * sin_a);
      // The exact answer for the float ray as given.
      double t_exact = -Dot(Vec3d(o) - p0, n) / Dot(Vec3d(d), n);
      double t;
      Vec2f param;
      ASSERT_TRUE(plane.Intersect(Vec3d(o), Vec3d(d), INFINITY, &t, &param)) << distance;
      EXPECT_NEAR(t, t_exact, 1e-12 * t_exact) << distance;
      EXPECT_FALSE(plane.Intersect(Vec3d(o), Vec3d(d), 0.99 * t_exact, &t, &param)) << distance;
      EXPECT_FALSE(plane.Intersect(Vec3d(o), -Vec3d(d), INFINITY, &t, &param)) << distance;

      // Through Embree: the hit point lies on the plane within its error bound, and a ray
      // leaving it upward does not meet the plane again.
      std::optional<SurfaceInteraction> si = scene.Intersect(Ray{o, d});
      ASSERT_TRUE(si) << "no hit at distance " << distance;
      EXPECT_NEAR(si->t, t_exact, 1e-6 * t_exact) << distance;
      Vec3d p(si->p), exact = Vec3d(o) + Vec3d(d) * t_exact;
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(p[i], exact[i], si->p_error[i] + 1e-12) << distance << " axis " << i;
      EXPECT_LE(std::abs(Dot(p - p0, n)), Dot(Abs(n), Vec3d(si->p_error)) + 1e-12) << distance;
      EXPECT_GT(Dot(Vec3d(si->n), n), 1 - 1e-6);
      Vec3f up = Normalize(Vec3f(n) + Vec3f(d));
      EXPECT_FALSE(scene.Intersect(Ray{OffsetRayOrigin(si->p, si->p_error, si->n, up), up})) << distance;
      // A shadow ray across the plane is blocked; one that stops short is not.
      EXPECT_TRUE(scene.Occluded(Ray{o, d, float(1.01 * t_exact)})) << distance;
      EXPECT_FALSE(scene.Occluded(Ray{o, d, float(0.99 * t_exact)})) << distance;
    }
  }
}

TEST(InfinitePlane, BoundsStayWithinEmbreesRange) {
  // Facing an axis (a quarter turn is exact): a thin slab; tilted: the reachable cube. Both
  // inside Embree's range.
  Bounds3f flat = InfinitePlane(Horizontal(2), false).EmbreeBounds();
  EXPECT_LE(flat.hi.y - flat.lo.y, 1e-4f);
  Bounds3f tilted = InfinitePlane(Tilted(), false).EmbreeBounds();
  for (const Bounds3f& b : {flat, tilted}) {
    for (int i = 0; i < 3; ++i) {
      EXPECT_LT(b.hi[i], 1.8e18f);
      EXPECT_GT(b.lo[i], -1.8e18f);
    }
    // Both reach the cube's faces across x and z.
    for (int i : {0, 2}) EXPECT_GE(b.hi[i] - b.lo[i], 1.99e18f) << i;
  }
  EXPECT_THROW(InfinitePlane(Transform::Translate({0, 0, 1e19}), false), std::invalid_argument);
}

// An orthographic view straight down onto the plane y = 0, centred on (cx, 0, 0), `half`
// scene units to each side; `lights` and `more` are added to the scene.
std::string TopView(double cx, double half, int res, const std::string& lights, const std::string& more,
                    double camera_y = 3) {
  return fmt::format(R"(<scene version="3.0.0">
  <integrator type="direct"/>
  <sensor type="orthographic">
    <transform name="to_world"><scale x="{1}" y="{1}"/>
      <lookat origin="{0}, {3}, 0" target="{0}, -10, 0" up="0, 0, 1"/></transform>
    <sampler type="sobol"><integer name="sample_count" value="64"/></sampler>
    <film type="hdrfilm"><integer name="width" value="{2}"/><integer name="height" value="{2}"/>
      <rfilter type="box"/></film>
  </sensor>
  {4}
  {5}
</scene>)",
                     cx, half, res, camera_y, lights, more);
}

// Compares every pixel of `img` with the radiance `expected(px, py)`: each within 5% (the
// spectral noise of one pixel), and on average within four standard errors of the
// differences plus 3e-3 for the RGB-to-spectrum round trip of the white light.
void ExpectRadiance(const Image& img, const std::function<double(int, int)>& expected) {
  double sum_diff = 0, sum_diff2 = 0, sum_l = 0;
  for (int py = 0; py < img.height; ++py)
    for (int px = 0; px < img.width; ++px) {
      const double l = expected(px, py);
      for (int c = 0; c < 3; ++c) {
        double v = img.At(px, py, c);
        ASSERT_NEAR(v, l, 0.05 * l) << "pixel " << px << "," << py << " channel " << c;
        sum_diff += v - l;
        sum_diff2 += Sqr(v - l);
        sum_l += l;
      }
    }
  const double n = 3.0 * img.width * img.height, mean = sum_diff / n;
  const double se = std::sqrt(std::max(0.0, sum_diff2 / n - mean * mean) / (n - 1));
  EXPECT_NEAR(mean, 0, 4 * se + 3e-3 * sum_l / n) << "mean radiance " << sum_l / n;
}

const char* kPlane = R"(<shape type="plane"><transform name="to_world"><rotate x="1" angle="-90"/></transform></shape>)";

// Seen from above under a point light at height h, the diffuse plane (reflectance 0.5) has the
// radiance L = 0.5 / pi * E with the irradiance E = I cos(theta) / d^2 = I h / d^3 (d from
// the light): every pixel is compared against L averaged over its footprint.
TEST(InfinitePlane, RendersWithTheRadianceOfALitDiffusePlane) {
  const double half = 2, h = 1, intensity = 1;
  const int res = 24;
  auto r = RenderXml(TopView(0, half, res, R"(<emitter type="point"><point name="position" x="0" y="1" z="0"/>
      <float name="intensity" value="1"/></emitter>)", kPlane));
  ExpectRadiance(r.image, [&](int px, int py) {
    // Averaged over the pixel's footprint on the plane (the radiance depends only on the
    // distance from the point under the light: the image's orientation does not matter).
    double l = 0;
    const int k = 16;
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b) {
        double x = half * (1 - 2 * (px + (a + 0.5) / k) / res), z = half * (1 - 2 * (py + (b + 0.5) / k) / res);
        double d = std::sqrt(x * x + z * z + h * h);
        l += 0.5 / M_PI * intensity * h / (d * d * d);
      }
    return l / (k * k);
  });
  EXPECT_EQ(r.stats.nan_count, 0u);
}

// The plane between a light and a floor below it leaves the floor dark; without it the
// floor is lit (the view is from below the plane, so camera rays never cross it).
TEST(InfinitePlane, CastsShadows) {
  const char* light = R"(<emitter type="point"><point name="position" x="0" y="1" z="0"/>
      <float name="intensity" value="1"/></emitter>)";
  const char* floor = R"(<shape type="rectangle"><transform name="to_world"><rotate x="1" angle="-90"/><scale value="5"/>
      <translate y="-1"/></transform></shape>)";
  auto without = RenderXml(TopView(0, 1, 8, light, floor, -0.5));
  auto with = RenderXml(TopView(0, 1, 8, light, std::string(floor) + kPlane, -0.5));
  double lit = 0, shadowed = 0;
  for (float v : without.image.pixels) lit += v;
  for (float v : with.image.pixels) shadowed = std::max(shadowed, double(v));
  // The floor under the light: 0.5 / pi * I h / d^3 with h = 2, about 0.04.
  EXPECT_GT(lit / without.image.pixels.size(), 0.02);
  EXPECT_EQ(shadowed, 0.0);
}

// A low sun (20 degrees up) casts a sphere's shadow on the plane far from the sphere: the
// shadow's centre lies cot(20 deg) = 2.75 from under the sphere, beyond the sphere's bounds.
// In the shadow the plane is black; out of it, it has radiance 0.5 / pi * sin(20 deg).
TEST(InfinitePlane, ReceivesLongShadowsFromADirectionalLight) {
  const double elevation = 20 * M_PI / 180;
  std::string sun = fmt::format(R"(<emitter type="directional"><vector name="direction" x="{}" y="{}" z="0"/>
      <float name="irradiance" value="1"/></emitter>)",
                                std::cos(elevation), -std::sin(elevation));
  std::string sphere = std::string(kPlane) + R"(<shape type="sphere"><point name="center" x="0" y="1" z="0"/>
      <float name="radius" value="0.25"/></shape>)";
  auto shadow = RenderXml(TopView(1 / std::tan(elevation), 0.15, 8, sun, sphere));
  auto open = RenderXml(TopView(-1, 0.15, 8, sun, sphere));
  for (size_t i = 0; i < shadow.image.pixels.size(); ++i) EXPECT_EQ(shadow.image.pixels[i], 0.f) << i;
  ExpectRadiance(open.image, [&](int, int) { return 0.5 / M_PI * std::sin(elevation); });
}

TEST(InfinitePlane, CannotBeInstanced) {
  std::string xml = TopView(0, 1, 4, "", R"(<shape type="shapegroup" id="g">)" + std::string(kPlane) + R"(</shape>
      <shape type="instance"><ref id="g"/></shape>)");
  try {
    RenderXml(xml);
    ADD_FAILURE() << "a plane in a shapegroup was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("infinite plane cannot be part of a shapegroup"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace objektiv
