// Light sampling: the densities lights and shapes report match where their samples land.
#include <gtest/gtest.h>

#include "chi2.h"
#include "scene/analytic_shape.h"
#include "scene/infinite_light.h"
#include "scene/scene.h"
#include "scene/triangle_mesh.h"

namespace objektiv {
namespace {

constexpr double kAlpha = 1e-3;

// Chi-square of SampleFrom(ref) against PdfFrom(ref, hit), where hits come from tracing
// the direction through a scene holding only the shape.
void CheckShapeSampling(std::unique_ptr<Shape> shape, const Vec3f& ref, const char* name) {
  const Shape* raw = shape.get();
  Scene scene;
  scene.AddShape(std::move(shape), nullptr);
  scene.Commit();
  auto sampler = [&](PCG32& g) -> std::optional<Vec3f> {
    ShapeSample s = raw->SampleFrom(ref, {g.UniformFloat(), g.UniformFloat()});
    if (!(s.pdf > 0)) return std::nullopt;
    return Normalize(s.p - ref);
  };
  auto pdf = [&](const Vec3f& w) -> double {
    auto si = scene.Intersect(Ray{ref, w});
    if (!si) return 0.0;
    return raw->PdfFrom(ref, *si);
  };
  auto r = test::Chi2TestDirections(sampler, pdf, 300000, 32, 64);
  EXPECT_GT(r.p_value, kAlpha) << name << ": " << r.Describe();
  EXPECT_NEAR(r.pdf_integral, 1, 0.03) << name;
}

TEST(ShapeSampling, SphereConeFromOutside) {
  CheckShapeSampling(std::make_unique<Sphere>(Vec3f(0.3f, -0.2f, 0.9f), 0.6f, false, Transform()), Vec3f(0.f), "sphere");
}

TEST(ShapeSampling, SphereFromInside) {
  CheckShapeSampling(std::make_unique<Sphere>(Vec3f(0.1f, 0, 0), 2.f, false, Transform()), Vec3f(0.f), "inside sphere");
}

TEST(ShapeSampling, RectangleMesh) {
  Transform t = Transform::Translate({0, 0, 1}) * Transform::Rotate(30, {1, 0, 0}) * Transform::Scale({0.8, 0.5, 1});
  CheckShapeSampling(std::make_unique<TriangleMesh>(TriangleMesh::Rectangle(), t, false), Vec3f(0.f), "rectangle");
}

// Two-triangle meshes: a sheared parallelogram (sampled as one, here with repeated vertices
// as OBJ quads have, texture coordinates and the triangles' vertices in different orders)
// and a kite (not a parallelogram: sampled triangle by triangle). Besides the densities, a
// sample's uv and normal must be those of the surface point it names.
TEST(ShapeSampling, TwoTriangleMeshes) {
  auto check_attributes = [](const TriangleMesh& mesh, const Vec3f& ref) {
    Scene scene;
    scene.AddShape(std::make_unique<TriangleMesh>(mesh.data(), Transform(), false), nullptr);
    scene.Commit();
    PCG32 g;
    for (int k = 0; k < 2000; ++k) {
      ShapeSample s = mesh.SampleArea({g.UniformFloat(), g.UniformFloat()});
      auto si = scene.Intersect(Ray{ref, s.p - ref});
      ASSERT_TRUE(si);
      EXPECT_NEAR(Length(si->p - s.p), 0, 1e-5);
      EXPECT_NEAR(si->uv.x, s.uv.x, 1e-4);
      EXPECT_NEAR(si->uv.y, s.uv.y, 1e-4);
      EXPECT_NEAR(Dot(si->n, s.n), 1, 1e-6);
    }
  };
  MeshData quad;
  // R, P, Q, and S = P + Q - R, sheared; the second triangle repeats P and Q as new vertices.
  quad.positions = {{0, 0, 1}, {0.9f, 0.1f, 1.2f}, {0.3f, 0.6f, 0.8f}, {0.3f, 0.6f, 0.8f}, {1.2f, 0.7f, 1.0f}, {0.9f, 0.1f, 1.2f}};
  quad.uvs = {{0, 0}, {1, 0}, {0, 1}, {0, 1}, {1, 1}, {1, 0}};
  quad.indices = {1, 2, 0, 3, 5, 4};
  TriangleMesh q(quad, Transform(), false);
  CheckShapeSampling(std::make_unique<TriangleMesh>(quad, Transform(), false), Vec3f(0.2f, 0.3f, 0), "parallelogram");
  check_attributes(q, Vec3f(0.2f, 0.3f, 0));
  MeshData kite = quad;
  kite.positions[4] = {1.5f, 1.1f, 1.0f};
  TriangleMesh k(kite, Transform(), false);
  CheckShapeSampling(std::make_unique<TriangleMesh>(kite, Transform(), false), Vec3f(0.2f, 0.3f, 0), "kite");
  check_attributes(k, Vec3f(0.2f, 0.3f, 0));
}

TEST(ShapeSampling, DiskAndCylinder) {
  Transform t = Transform::Translate({0.2, 0, 1}) * Transform::Rotate(40, {0, 1, 0}) * Transform::Scale({0.7, 0.4, 1});
  CheckShapeSampling(std::make_unique<Disk>(t, false), Vec3f(0.f), "disk");
  // From outside, a direction crosses a cylinder twice and area sampling gives density to
  // both points; from inside each direction meets the wall once (the ends are open).
  Transform c = Transform::Translate({-0.5, 0.3, 0.6}) * Transform::Rotate(60, {1, 0, 0}) * Transform::Scale({0.3, 0.3, 1.2});
  CheckShapeSampling(std::make_unique<Cylinder>(c, false), c.Point(Vec3f(0, 0.1f, 0.5f)), "cylinder");
}

TEST(ShapeSampling, AreasAreExact) {
  EXPECT_NEAR(Sphere(Vec3f(0.f), 2, false, Transform::Scale(Vec3d(1.5))).Area(), 4 * kPi * 9, 1e-3);
  EXPECT_NEAR(Disk(Transform::Scale({2, 3, 1}), false).Area(), kPi * 6, 1e-4);
  EXPECT_NEAR(TriangleMesh(TriangleMesh::Cube(), Transform::Scale({1, 2, 3}), false).Area(), 8 * (2 + 3 + 6), 1e-3);
  EXPECT_THROW(Sphere(Vec3f(0.f), 1, false, Transform::Scale({1, 2, 1})), std::invalid_argument);
}

// Two triangles, the first degenerate with one position at two of its corners (a fuzzed OBJ,
// fuzz/regressions/mesh_obj): the quad detection matched both to one corner of the second
// triangle and read past the index buffer (AddressSanitizer: heap-buffer-overflow).
TEST(ShapeSampling, DegenerateTriangleBesideAnotherIsNoQuad) {
  MeshData m;
  m.positions = {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 1, 1}};
  m.indices = {0, 1, 2, 0, 3, 4};
  TriangleMesh mesh(m, Transform(), false);
  EXPECT_NEAR(mesh.Area(), 0.5f * std::sqrt(3.f), 1e-6f);
  for (float u : {0.1f, 0.5f, 0.9f}) {
    ShapeSample s = mesh.SampleArea({u, 0.3f});
    EXPECT_NEAR(s.p.z - s.p.x - s.p.y, 0, 1e-6f);  // on the second triangle's plane
  }
}

TEST(EnvironmentMap, SamplingMatchesPdf) {
  Image img(64, 32, {"R", "G", "B"});
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) {
      float v = 0.05f + 0.01f * x + ((x - 40) * (x - 40) + (y - 10) * (y - 10) < 20 ? 50.f : 0.f);
      img.At(x, y, 0) = v;
      img.At(x, y, 1) = 0.5f * v;
      img.At(x, y, 2) = (y > 28) ? 0.f : v;
    }
  EnvironmentMap env(img, 1, Transform::Rotate(20, {0, 1, 0}));
  Bounds3f b;
  b.Extend(Vec3f(-1.f));
  b.Extend(Vec3f(1.f));
  env.Preprocess(b);
  SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.3f);
  int samples = 0, mismatches = 0;
  auto r = test::Chi2TestDirections(
      [&](PCG32& g) -> std::optional<Vec3f> {
        auto s = env.SampleLi(Vec3f(0.f), {g.UniformFloat(), g.UniformFloat()}, lambda);
        if (!s) return std::nullopt;
        // The reported density is the one PdfLi gives for the direction, except where float
        // rounding of the direction moves it across a texel border.
        ++samples;
        if (std::abs(s->pdf - env.PdfLi(s->wi)) > 1e-3f * s->pdf) ++mismatches;
        return s->wi;
      },
      [&](const Vec3f& w) { return double(env.PdfLi(w)); }, 300000, 32, 64);
  EXPECT_GT(r.p_value, kAlpha) << r.Describe();
  EXPECT_NEAR(r.pdf_integral, 1, 0.02);
  EXPECT_LT(mismatches, samples / 1000) << mismatches << " of " << samples;
}

TEST(EnvironmentMap, NaNDirectionsGiveNaNRadianceAndNoDensity) {
  // A NaN direction reached the texel lookup's float-to-int conversion (undefined behaviour,
  // a finite texel in practice). Its radiance is NaN, which the film counts and drops.
  Image img(8, 4, {"R", "G", "B"});
  for (float& v : img.pixels) v = 1;
  EnvironmentMap env(img, 1, Transform());
  Bounds3f b;
  b.Extend(Vec3f(-1.f));
  b.Extend(Vec3f(1.f));
  env.Preprocess(b);
  SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.3f);
  Vec3f nan_dir(std::nanf(""), 0, 1);
  EXPECT_TRUE(std::isnan(env.Le(nan_dir, lambda)[0]));
  EXPECT_EQ(env.PdfLi(nan_dir), 0);
  EXPECT_GT(env.Le(Vec3f(0, 0, 1), lambda)[0], 0);
}

}  // namespace
}  // namespace objektiv
