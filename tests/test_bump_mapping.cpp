// Bump and normal mapping: every shape's dp/du and dp/dv against its own (u, v), the frames
// that height and normal maps give against their closed forms, the wrapped BSDFs against the
// checks every BSDF passes, and the loader's errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

#include "base/sampling.h"
#include "chi2.h"
#include "io/image_io.h"
#include "log_capture.h"
#include "render_helpers.h"
#include "scene/analytic_shape.h"
#include "scene/normal_mapping.h"
#include "scene/scene.h"
#include "scene/triangle_mesh.h"

namespace objektiv {
namespace {

std::shared_ptr<Material> Diffuse(float r = 0.7f) {
  return std::make_shared<DiffuseMaterial>(std::make_shared<ConstantTexture>(Spectrum(r)));
}

// --- dp/du, dp/dv ---------------------------------------------------------------------

// For hits near the one on the ray origin -> target: the hit points differ by what dpdu and
// dpdv predict from the uv they differ by, to first order (the shape's own uv, as reported).
// Also: the normal is perpendicular to both, the frame's tangent follows dpdu, and
// dpdu x dpdv points along the normal (orientation +1) or against it (-1).
void CheckDerivatives(const Scene& scene, Vec3f origin, Vec3f target, float orientation, const std::string& name) {
  const Vec3f d = Normalize(target - origin);
  const auto base = scene.Intersect(Ray{origin, d});
  ASSERT_TRUE(base) << name;
  const SurfaceInteraction& si = *base;
  const float lu = Length(si.dpdu), lv = Length(si.dpdv);
  ASSERT_GT(lu, 0) << name;
  ASSERT_GT(lv, 0) << name;
  EXPECT_LT(std::abs(Dot(si.n, si.dpdu)), 1e-4f * lu) << name;
  EXPECT_LT(std::abs(Dot(si.n, si.dpdv)), 1e-4f * lv) << name;
  EXPECT_GT(Dot(si.shading.s, si.dpdu), 0.9999f * lu) << name;
  EXPECT_GT(orientation * Dot(Cross(si.dpdu, si.dpdv), si.n), 0.999f * Length(Cross(si.dpdu, si.dpdv))) << name;
  const Frame f = Frame::FromZ(d);
  int checked = 0;
  for (int k = 0; k < 8; ++k) {
    const float a = 0.3f + k * kPi / 4;
    const Vec3f dk = Normalize(d + (f.s * std::cos(a) + f.t * std::sin(a)) * 1.5e-4f);
    const auto h = scene.Intersect(Ray{origin, dk});
    ASSERT_TRUE(h) << name;
    const Vec2f duv = h->uv - si.uv;
    if (std::abs(duv.x) > 0.25f || std::abs(duv.y) > 0.25f) continue;  // across a seam of the uv
    const Vec3f dp = h->p - si.p, predicted = si.dpdu * duv.x + si.dpdv * duv.y;
    EXPECT_LT(Length(dp - predicted), 0.01f * Length(dp)) << name << " probe " << k;
    ++checked;
  }
  EXPECT_GE(checked, 6) << name;
}

struct ShapeCase {
  std::string name;
  std::function<std::unique_ptr<Shape>()> make;
  std::vector<std::pair<Vec3f, Vec3f>> rays;  // origin, target
  float orientation;                          // of dpdu x dpdv against the normal
};

std::vector<ShapeCase> ShapeCases() {
  const Transform rot = Transform::Rotate(35, {1, 2, 0.5});
  std::vector<ShapeCase> c;
  for (bool flip : {false, true}) {
    const std::string f = flip ? " (flipped)" : "";
    const float o = flip ? -1.f : 1.f;
    c.push_back({"sphere" + f,
                 [=] { return std::make_unique<Sphere>(Vec3f(0.2f, 0, 0), 0.7f, flip, Transform::Translate({0.1, 0.3, 0}) * rot * Transform::Scale({1.5, 1.5, 1.5})); },
                 {{{3, 4, 5}, {0.3f, 0.3f, 0}}, {{-4, 1, 2}, {0.3f, 0.3f, 0}}, {{1, -5, -2}, {0.3f, 0.3f, 0}}},
                 -o});
    c.push_back({"disk" + f,
                 [=] { return std::make_unique<Disk>(Transform::Translate({0, 0.5, 0}) * rot * Transform::Scale({2, 1, 1}), flip); },
                 {{{2, 3, 6}, {0.6f, 0.7f, 0.1f}}, {{-3, 1, 5}, {-0.5f, 0.2f, 0}}},
                 o});
    c.push_back({"cylinder" + f,
                 [=] { return std::make_unique<Cylinder>(rot * Transform::Scale({0.5, 0.5, 2}), flip); },
                 {{{4, 0.5f, 1}, {0, 0, 0.9f}}, {{-3, 3, 0.5f}, {0, 0, 0.7f}}},
                 o});
    c.push_back({"plane" + f,
                 [=] { return std::make_unique<InfinitePlane>(Transform::Translate({0.2, -0.5, 0.1}) * rot, flip); },
                 {{{3, 4, 5}, {1, 0, 0}}, {{-3, -4, -5}, {0, 1, 0}}},
                 o});
    c.push_back({"rectangle" + f,
                 [=] { return std::make_unique<TriangleMesh>(TriangleMesh::Rectangle(), rot * Transform::Scale({1.5, 0.5, 1}), flip); },
                 {{{2, 3, 6}, {0.3f, 0.1f, 0}}, {{-2, -3, -6}, {-0.2f, 0.1f, 0}}},
                 o});
    c.push_back({"cube" + f,
                 [=] { return std::make_unique<TriangleMesh>(TriangleMesh::Cube(), rot * Transform::Scale({1, 0.6, 0.4}), flip); },
                 {{{5, 0.3f, 0.2f}, {0, 0.1f, 0}}, {{-4, 3, 1}, {0, 0.1f, 0}}, {{0.5f, 0.2f, -6}, {0, 0.1f, 0}},
                  {{0.3f, 6, -1}, {0, 0.1f, 0}}, {{1, -6, 2}, {0, 0.1f, 0}}, {{1, 2, 6}, {0, 0.1f, 0}}},
                 o});
  }
  // A triangle whose uvs are sheared and scaled, and one with no uvs (barycentric uv).
  MeshData sheared;
  sheared.positions = {{-1, -1, 0}, {2, -1, 0.5f}, {0, 2, -0.3f}};
  sheared.uvs = {{0.1f, 0.2f}, {0.9f, 0.4f}, {0.3f, 1.1f}};
  sheared.indices = {0, 1, 2};
  c.push_back({"mesh with sheared uvs", [=] { return std::make_unique<TriangleMesh>(sheared, rot, false); },
               {{{1, 2, 6}, {0.2f, 0.1f, 0}}}, 1});
  MeshData bare = sheared;
  bare.uvs.clear();
  c.push_back({"mesh without uvs", [=] { return std::make_unique<TriangleMesh>(bare, rot, true); },
               {{{1, 2, 6}, {0.2f, 0.1f, 0}}}, -1});
  return c;
}

TEST(BumpMapping, EveryShapesDerivativesFollowItsUv) {
  for (const ShapeCase& c : ShapeCases()) {
    Scene scene;
    scene.AddShape(c.make(), Diffuse());
    scene.Commit();
    for (const auto& [o, t] : c.rays) CheckDerivatives(scene, o, t, c.orientation, c.name);
  }
}

TEST(BumpMapping, InstancesCarryTheirDerivativesIntoTheWorld) {
  Scene scene;
  const int g = scene.AddShapeGroup();
  scene.AddShapeToGroup(g, std::make_unique<Sphere>(Vec3f(0.f), 1.f, false, Transform()), Diffuse());
  scene.AddShapeToGroup(g, std::make_unique<Cylinder>(Transform::Translate({3, 0, 0}), false), Diffuse());
  scene.AddInstance(g, Transform::Translate({0.5, 0, 0}) * Transform::Rotate(40, {0, 1, 1}) * Transform::Scale({2, 2, 2}));
  scene.Commit();
  CheckDerivatives(scene, {1, 3, 8}, {0.6f, 0.2f, 0}, -1, "instanced sphere");
  const Vec3f cyl = (Transform::Translate({0.5, 0, 0}) * Transform::Rotate(40, {0, 1, 1}) * Transform::Scale({2, 2, 2})).Point(Vec3f(3, 0, 0.5f));
  CheckDerivatives(scene, cyl + Vec3f(0, -1, 0) * 9.f + Vec3f(0, 0, 0.3f), cyl, 1, "instanced cylinder");
}

TEST(BumpMapping, DegenerateUvsFallBackToAFrameAroundTheNormal) {
  MeshData m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.uvs = {{0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}};
  m.indices = {0, 1, 2};
  Scene scene;
  scene.AddShape(std::make_unique<TriangleMesh>(m, Transform(), false), Diffuse());
  scene.Commit();
  const auto si = scene.Intersect(Ray{{0.2f, 0.3f, 2}, {0, 0, -1}});
  ASSERT_TRUE(si);
  EXPECT_GT(Length(si->dpdu), 0.5f);
  EXPECT_GT(Length(si->dpdv), 0.5f);
  EXPECT_NEAR(Dot(si->dpdu, si->n), 0, 1e-6);
  EXPECT_NEAR(Dot(si->dpdv, si->n), 0, 1e-6);
  EXPECT_GT(Dot(Cross(si->dpdu, si->dpdv), si->n), 0);
  const Frame f = BumpedFrame(*si, {3, -2});  // finite, and tilted
  EXPECT_TRUE(std::isfinite(f.n.x) && std::isfinite(f.n.y) && std::isfinite(f.n.z));
  EXPECT_LT(f.n.z, 0.99f);
}

// --- texture gradients ----------------------------------------------------------------

Image RampImage(int w, int h, float step_x, float step_y) {
  Image img(w, h, {"R", "G", "B"});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) img.At(x, y, c) = 0.1f + step_x * x + step_y * (h - 1 - y);  // v up
  return img;
}

TEST(BumpMapping, BitmapGradientIsTheBilinearPatchsSlope) {
  // Random texels, a rotated and scaled to_uv: the analytic gradient against central
  // differences (exact for the bilinear patch, a quadratic, where no texel edge intervenes).
  Image img(7, 5, {"R", "G", "B"});
  PCG32 g(3, 4);
  for (float& v : img.pixels) v = g.UniformFloat();
  const Transform to_uv = Transform::Rotate(25, {0, 0, 1}) * Transform::Scale({1.7, 0.8, 1});
  for (WrapMode wrap : {WrapMode::kRepeat, WrapMode::kMirror, WrapMode::kClamp}) {
    BitmapTexture tex(img, SpectrumUsage::kData, FilterMode::kBilinear, wrap, to_uv);
    int compared = 0;
    for (int i = 0; i < 200; ++i) {
      const Vec2f uv(g.UniformFloat() * 3 - 1, g.UniformFloat() * 3 - 1);
      const Vec2f grad = tex.LuminanceGradient(uv);
      const float h = 1e-3f;
      auto L = [&](float du, float dv) { return double(Luminance(tex.Rgb({uv.x + du, uv.y + dv}))); };
      const double fu = (L(h, 0) - L(0, 0)) / h, bu = (L(0, 0) - L(-h, 0)) / h;
      const double fv = (L(0, h) - L(0, 0)) / h, bv = (L(0, 0) - L(0, -h)) / h;
      if (std::abs(fu - bu) > 0.05 || std::abs(fv - bv) > 0.05) continue;  // a texel edge within h
      EXPECT_NEAR(grad.x, 0.5 * (fu + bu), 0.02) << int(wrap) << " at " << uv.x << "," << uv.y;
      EXPECT_NEAR(grad.y, 0.5 * (fv + bv), 0.02) << int(wrap) << " at " << uv.x << "," << uv.y;
      ++compared;
    }
    EXPECT_GT(compared, 150);
  }
  // Flat textures have no slope.
  BitmapTexture nearest(img, SpectrumUsage::kData, FilterMode::kNearest, WrapMode::kRepeat, to_uv);
  EXPECT_TRUE(nearest.IsPiecewiseConstant());
  EXPECT_EQ(nearest.LuminanceGradient({0.3f, 0.4f}).x, 0);
  EXPECT_FALSE(BitmapTexture(img, SpectrumUsage::kData, FilterMode::kBilinear, WrapMode::kRepeat, to_uv).IsPiecewiseConstant());
}

// --- frames -------------------------------------------------------------------------

// The hit at the centre of a shape seen along -z from above, for frame tests.
SurfaceInteraction HitFromAbove(std::unique_ptr<Shape> shape, Vec3f origin, Vec3f target) {
  Scene scene;
  scene.AddShape(std::move(shape), Diffuse());
  scene.Commit();
  auto si = scene.Intersect(Ray{origin, Normalize(target - origin)});
  EXPECT_TRUE(si);
  return *si;
}

// The angle between two unit vectors, accurate for small angles too (acos of a float is not).
float AngleDeg(const Vec3f& a, const Vec3f& b) { return Degrees(std::atan2(Length(Cross(a, b)), Dot(a, b))); }

TEST(BumpMapping, ConstantHeightsChangeNothing) {
  Image flat(4, 4, {"R", "G", "B"});
  for (float& v : flat.pixels) v = 0.37f;
  auto bitmap = std::make_shared<BitmapTexture>(flat, SpectrumUsage::kData, FilterMode::kBilinear, WrapMode::kRepeat, Transform());
  for (const ShapeCase& c : ShapeCases()) {
    const SurfaceInteraction si = HitFromAbove(c.make(), c.rays[0].first, c.rays[0].second);
    for (std::shared_ptr<const SpectrumTexture> tex : {std::shared_ptr<const SpectrumTexture>(bitmap),
                                                       std::shared_ptr<const SpectrumTexture>(std::make_shared<ConstantTexture>(Spectrum(0.8f)))}) {
      BumpMapMaterial bump(Diffuse(), tex, 3.f);
      const Frame f = bump.ShadingFrame(si);
      EXPECT_EQ(f.n.x, si.shading.n.x) << c.name;
      EXPECT_EQ(f.n.y, si.shading.n.y) << c.name;
      EXPECT_EQ(f.n.z, si.shading.n.z) << c.name;
      EXPECT_EQ(f.s.x, si.shading.s.x) << c.name;
    }
  }
}

TEST(BumpMapping, LinearRampTiltsTheNormalByTheClosedFormAngle) {
  // Heights rising 0.05 per texel over 16 texels in u: dh/du = 0.8 in the texels' middle.
  auto ramp = std::make_shared<BitmapTexture>(RampImage(16, 4, 0.05f, 0), SpectrumUsage::kData, FilterMode::kBilinear,
                                              WrapMode::kClamp, Transform());
  EXPECT_NEAR(ramp->LuminanceGradient({0.5f, 0.5f}).x, 0.8f, 1e-4);
  EXPECT_NEAR(ramp->LuminanceGradient({0.5f, 0.5f}).y, 0, 1e-6);
  // The rectangle [-1,1]^2 has dp/du = (2, 0, 0): scale s tilts the normal by atan(0.8 s / 2)
  // toward -u (uphill faces away from the rise).
  const float target = 30, s = std::tan(Radians(target)) * 2 / 0.8f;
  BumpMapMaterial bump(Diffuse(), ramp, s);
  const SurfaceInteraction rect = HitFromAbove(std::make_unique<TriangleMesh>(TriangleMesh::Rectangle(), Transform(), false),
                                               {0.1f, -0.2f, 5}, {0.1f, -0.2f, 0});
  const Vec3f n = bump.ShadingFrame(rect).n;
  EXPECT_NEAR(AngleDeg(n, {0, 0, 1}), target, 0.01);
  EXPECT_NEAR(n.y, 0, 1e-6);
  EXPECT_LT(n.x, 0);
  // Curved shapes (orthogonal dpdu, dpdv): n' = normalize(n - dh/du dpdu / |dpdu|^2).
  for (int which = 0; which < 2; ++which) {
    const SurfaceInteraction si =
        which == 0 ? HitFromAbove(std::make_unique<Sphere>(Vec3f(0.f), 1.f, false, Transform::Rotate(20, {1, 0, 0})), {3, 1, 2}, {0, 0, 0})
                   : HitFromAbove(std::make_unique<Cylinder>(Transform::Scale({0.5, 0.5, 2}), false), {3, 1, 1}, {0, 0, 1});
    const float dh = 0.8f * 0.3f;
    BumpMapMaterial b(Diffuse(), ramp, 0.3f);
    const Vec3f expected = Normalize(si.n - si.dpdu * (dh / LengthSquared(si.dpdu)));
    const Vec3f got = b.ShadingFrame(si).n;
    EXPECT_LT(AngleDeg(got, expected), 0.01f) << which;
    EXPECT_GT(AngleDeg(got, si.n), 1.f) << which;  // a visible tilt
  }
}

TEST(BumpMapping, NormalMapsTiltByTheEncodedAngle) {
  const SurfaceInteraction si = HitFromAbove(
      std::make_unique<TriangleMesh>(TriangleMesh::Rectangle(), Transform::Rotate(90, {0, 0, 1}), false), {0.1f, 0.2f, 5},
      {0.1f, 0.2f, 0});
  auto constant = [](Vec3f rgb) { return std::make_shared<ConstantTexture>(Spectrum(0.5f), rgb); };
  NormalMapMaterial flat(Diffuse(), constant({0.5f, 0.5f, 1}));
  EXPECT_LT(AngleDeg(flat.ShadingFrame(si).n, si.shading.n), 1e-3f);
  // 30 degrees toward the tangent s (dp/du, here +y after the rotation), then toward t.
  const float a = Radians(30);
  NormalMapMaterial along_s(Diffuse(), constant({(std::sin(a) + 1) / 2, 0.5f, (std::cos(a) + 1) / 2}));
  const Vec3f ns = along_s.ShadingFrame(si).n;
  EXPECT_NEAR(AngleDeg(ns, si.shading.n), 30, 0.01);
  EXPECT_NEAR(ns.y, std::sin(a), 1e-5);
  NormalMapMaterial along_t(Diffuse(), constant({0.5f, (std::sin(a) + 1) / 2, (std::cos(a) + 1) / 2}));
  const Vec3f nt = along_t.ShadingFrame(si).n;
  EXPECT_NEAR(AngleDeg(nt, si.shading.n), 30, 0.01);
  EXPECT_NEAR(Dot(nt, si.shading.t), std::sin(a), 1e-5);
  // A normal pointing into the surface is mirrored out of it.
  NormalMapMaterial inward(Diffuse(), constant({0.5f, 0.5f, 0.2f}));
  EXPECT_GE(Dot(inward.ShadingFrame(si).n, si.n), 0);
}

// --- the wrapped BSDF ----------------------------------------------------------------

TEST(BumpMapping, SteepNormalsAreBentTowardTheViewerNotBlack) {
  // A normal map tilted 70 degrees: seen at a grazing angle from the side it turns away
  // from, the plain perturbed normal faces away from the viewer.
  const float a = Radians(70);
  auto tilted = std::make_shared<ConstantTexture>(Spectrum(0.5f), Vec3f((std::sin(a) + 1) / 2, 0.5f, (std::cos(a) + 1) / 2));
  NormalMapMaterial m(Diffuse(0.8f), tilted);
  SurfaceInteraction si =
      HitFromAbove(std::make_unique<TriangleMesh>(TriangleMesh::Rectangle(), Transform(), false), {-4, 0, 1}, {0, 0, 0});
  ASSERT_LT(Dot(NormalMappedFrame(si, Vec3f(std::sin(a), 0, std::cos(a))).n, si.wo), 0);  // black without the bend
  SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.3f);
  const BSDF bsdf = m.GetBSDF(si, lambda);
  EXPECT_GT(Dot(bsdf.frame().n, si.wo), 0);
  // Its mirror direction lies above the surface; its albedo is positive and at most one.
  const Vec3f r = bsdf.frame().n * (2 * Dot(si.wo, bsdf.frame().n)) - si.wo;
  EXPECT_GE(Dot(r, si.n), 0.0099f);
  PCG32 g(1, 2);
  double sum = 0;
  for (int i = 0; i < 20000; ++i)
    if (auto s = bsdf.Sample(si.wo, g.UniformFloat(), {g.UniformFloat(), g.UniformFloat()}))
      sum += s->f[0] * AbsDot(s->wi, bsdf.frame().n) / s->pdf;
  EXPECT_GT(sum / 20000, 0.2);
  EXPECT_LE(sum / 20000, 0.8 * 1.001);
}

TEST(BumpMapping, WrappedBsdfsStayReciprocalEnergyBoundedAndSampleTheirPdf) {
  auto ramp = std::make_shared<BitmapTexture>(RampImage(16, 16, 0.05f, -0.03f), SpectrumUsage::kData, FilterMode::kBilinear,
                                              WrapMode::kClamp, Transform());
  const SurfaceInteraction si = HitFromAbove(std::make_unique<Sphere>(Vec3f(0.f), 1.f, false, Transform()), {2, 1, 4}, {0, 0, 0});
  auto rough = std::make_shared<ConductorMaterial>(Spectrum(0.2f), Spectrum(3.f), 0.3f, 0.3f,
                                                   std::make_shared<ConstantTexture>(Spectrum(1.f)));
  std::vector<std::pair<std::string, std::shared_ptr<Material>>> cases = {
      {"bumped diffuse", std::make_shared<BumpMapMaterial>(Diffuse(0.9f), ramp, 1.f)},
      {"bumped rough conductor", std::make_shared<BumpMapMaterial>(rough, ramp, 1.f)},
      {"normal-mapped diffuse",
       std::make_shared<NormalMapMaterial>(Diffuse(0.9f), std::make_shared<ConstantTexture>(Spectrum(0.5f), Vec3f(0.8f, 0.35f, 0.8f)))}};
  for (const auto& [name, m] : cases) {
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    const BSDF bsdf = m->GetBSDF(si, lambda);
    EXPECT_GT(AngleDeg(bsdf.frame().n, si.shading.n), 5) << name;  // perturbed indeed
    // Reciprocal: f(a, b) = f(b, a) for any pair (those across the unperturbed normal: both 0).
    PCG32 g(7, 8);
    for (int i = 0; i < 500; ++i) {
      const Vec3f a = SampleUniformSphere({g.UniformFloat(), g.UniformFloat()});
      const Vec3f b = SampleUniformSphere({g.UniformFloat(), g.UniformFloat()});
      const float fab = bsdf.f(a, b)[0], fba = bsdf.f(b, a)[0];
      EXPECT_NEAR(fab, fba, 1e-4f * std::max(fab, fba) + 1e-6f) << name;
      // Nothing leaks: directions on opposite sides of the unperturbed normal scatter nothing.
      if (Dot(a, si.shading.n) * Dot(b, si.shading.n) < 0) {
        EXPECT_EQ(fab, 0) << name;
      }
    }
    // Sampling matches the pdf; energy at most one for views from grazing to head-on.
    const Frame& sh = si.shading;
    for (float deg : {10.f, 45.f, 80.f}) {
      const Vec3f wo = sh.FromLocal(Vec3f(std::sin(Radians(deg)), 0.2f * std::sin(Radians(deg)), std::cos(Radians(deg))));
      SurfaceInteraction at = si;
      at.wo = Normalize(wo);
      SampledWavelengths l2 = lambda;
      const BSDF b = m->GetBSDF(at, l2);
      auto sampler = [&](PCG32& rng) -> std::optional<Vec3f> {
        auto s = b.Sample(at.wo, rng.UniformFloat(), {rng.UniformFloat(), rng.UniformFloat()});
        if (!s) return std::nullopt;
        return s->wi;
      };
      auto pdf = [&](const Vec3f& wi) { return double(b.Pdf(at.wo, wi)); };
      const auto r = test::Chi2TestDirections(sampler, pdf, 200000, 16, 32);
      EXPECT_GT(r.p_value, 1e-3) << name << " at " << deg << ": " << r.Describe();
      EXPECT_LE(r.pdf_integral, 1.02) << name;
      double sum = 0;
      for (int i = 0; i < 50000; ++i)
        if (auto s = b.Sample(at.wo, g.UniformFloat(), {g.UniformFloat(), g.UniformFloat()}))
          sum += s->f[0] * AbsDot(s->wi, b.frame().n) / s->pdf;
      EXPECT_LE(sum / 50000, 1.01) << name << " at " << deg;
    }
  }
}

// --- scenes ---------------------------------------------------------------------------

std::string BumpScene(const std::string& bsdf) {
  return R"(<scene version="3.0.0">
  <integrator type="path"><integer name="max_depth" value="3"/></integrator>
  <sensor type="perspective">
    <float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0, -3, 4" target="0, 0, 0" up="0, 0, 1"/></transform>
    <sampler type="independent"><integer name="sample_count" value="4"/></sampler>
    <film type="hdrfilm"><integer name="width" value="24"/><integer name="height" value="16"/><rfilter type="box"/></film>
  </sensor>
  <shape type="rectangle"><transform name="to_world"><scale x="3" y="3"/></transform>)" +
         bsdf + R"(</shape>
  <shape type="sphere"><point name="center" x="0" y="0" z="0.6"/><float name="radius" value="0.6"/>)" +
         bsdf + R"(</shape>
  <emitter type="point"><point name="position" x="1" y="-1" z="3"/><rgb name="intensity" value="10"/></emitter>
  <emitter type="constant"><rgb name="radiance" value="0.2"/></emitter>
</scene>)";
}

TEST(BumpMapping, ConstantHeightMapRendersTheSameImage) {
  const Image plain = test::RenderXml(BumpScene(R"(<bsdf type="diffuse"/>)"), 2).image;
  const Image bumped =
      test::RenderXml(BumpScene(R"(<bsdf type="bumpmap"><float name="arg" value="0.5"/><bsdf type="diffuse"/></bsdf>)"), 2).image;
  EXPECT_EQ(plain.pixels, bumped.pixels);
  const Image normal = test::RenderXml(
      BumpScene(R"(<bsdf type="normalmap"><rgb name="normalmap" value="0.5, 0.5, 1"/><bsdf type="diffuse"/></bsdf>)"), 2).image;
  ASSERT_EQ(plain.pixels.size(), normal.pixels.size());
  for (size_t i = 0; i < plain.pixels.size(); ++i) EXPECT_NEAR(plain.pixels[i], normal.pixels[i], 1e-4f + 1e-4f * plain.pixels[i]);
}

TEST(BumpMapping, BitmapsForDataAreReadWithoutSrgbDecoding) {
  namespace fs = std::filesystem;
  const fs::path png = fs::temp_directory_path() / "objektiv_flat_normals.png";
  Image img(2, 2, {"R", "G", "B"});
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) img.At(x, y, 0) = img.At(x, y, 1) = 0.5f, img.At(x, y, 2) = 1;
  WritePng(png.string(), img);
  auto normal_of = [&](const std::string& raw) {
    RenderSetup setup = LoadSceneFromString(
        BumpScene(R"(<bsdf type="normalmap"><texture name="normalmap" type="bitmap"><string name="filename" value=")" + png.string() +
              "\"/>" + raw + R"(</texture><bsdf type="diffuse"/></bsdf>)"),
        "normals.xml", {});
    auto si = setup.scene->Intersect(Ray{{0.5f, -2.5f, 3}, {0, 0, -1}});
    EXPECT_TRUE(si);
    return AngleDeg(si->shape->material->ShadingFrame(*si).n, si->n);
  };
  EXPECT_LT(normal_of(""), 0.5f);  // (128, 128, 255) is (0.004, 0.004, 1): flat
  EXPECT_LT(normal_of(R"(<boolean name="raw" value="true"/>)"), 0.5f);
  EXPECT_GT(normal_of(R"(<boolean name="raw" value="false"/>)"), 30.f);  // decoded as sRGB: 0.216 -> tilted
  fs::remove(png);
}

// Mid-grey, or a colour whose 2 c - 1 points into the surface, stores no normal: the loader says
// how many texels of the map do (the surface keeps its own normal there).
TEST(BumpMapping, NormalMapTexelsWithoutANormalAreWarned) {
  namespace fs = std::filesystem;
  const fs::path png = fs::temp_directory_path() / "objektiv_grey_normals.png";
  Image img(2, 2, {"R", "G", "B"});
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) img.At(x, y, 0) = img.At(x, y, 1) = 0.5f, img.At(x, y, 2) = 1;
  img.At(1, 0, 2) = 0.5f;  // grey: (0, 0, 0)
  img.At(0, 1, 2) = 0.2f;  // (0, 0, -0.6): into the surface
  WritePng(png.string(), img);
  auto warnings = [&](const std::string& normals) {
    test::LogCapture log;
    LoadSceneFromString(BumpScene(R"(<bsdf type="normalmap">)" + normals + R"(<bsdf type="diffuse"/></bsdf>)"),
                        "normals.xml", {});
    return log.Text();
  };
  const std::string bitmap = warnings(R"(<texture name="normalmap" type="bitmap"><string name="filename" value=")" +
                                      png.string() + R"("/></texture>)");
  EXPECT_NE(bitmap.find("normals.xml:"), std::string::npos) << bitmap;
  EXPECT_NE(bitmap.find("2 of 4 texels decode to no outward normal"), std::string::npos) << bitmap;
  const std::string grey = warnings(R"(<rgb name="normalmap" value="0.5, 0.5, 0.5"/>)");
  EXPECT_NE(grey.find("1 of 1 texels decode to no outward normal"), std::string::npos) << grey;
  EXPECT_EQ(warnings(R"(<rgb name="normalmap" value="0.5, 0.5, 1"/>)").find("normalmap:"), std::string::npos);
  fs::remove(png);
}

void ExpectLoadError(const std::string& bsdf, const std::string& part) {
  try {
    LoadSceneFromString(BumpScene(bsdf), "bad.xml", {});
    ADD_FAILURE() << "no error for " << bsdf;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.xml:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(BumpMapping, LoaderErrorsNameTheLine) {
  const std::string tex = R"(<texture name="arg" type="checkerboard"/>)";
  ExpectLoadError(R"(<bsdf type="bumpmap">)" + tex + "</bsdf>", "exactly one nested <bsdf>");
  ExpectLoadError(R"(<bsdf type="bumpmap">)" + tex + R"(<bsdf type="diffuse"/><bsdf type="diffuse"/></bsdf>)",
                  "exactly one nested <bsdf> to wrap, got 2");
  ExpectLoadError(R"(<bsdf type="bumpmap"><bsdf type="diffuse"/></bsdf>)", "needs a texture of heights");
  ExpectLoadError(R"(<bsdf type="bumpmap">)" + tex + R"(<texture type="checkerboard"/><bsdf type="diffuse"/></bsdf>)",
                  "one texture of heights, got 2");
  ExpectLoadError(R"(<bsdf type="bumpmap"><texture name="arg" type="marble"/><bsdf type="diffuse"/></bsdf>)", "marble");
  ExpectLoadError(R"(<bsdf type="bumpmap"><spectrum name="arg" value="400:0.1, 700:0.9"/><bsdf type="diffuse"/></bsdf>)",
                  "not a spectrum");
  ExpectLoadError(R"(<bsdf type="bumpmap">)" + tex + R"(<string name="scale" value="big"/><bsdf type="diffuse"/></bsdf>)",
                  "scale");
  ExpectLoadError(R"(<bsdf type="normalmap"><bsdf type="diffuse"/></bsdf>)", "needs its texture of normals");
  ExpectLoadError(R"(<bsdf type="normalmap"><rgb name="normalmap" value="0.5, 0.5, 1"/></bsdf>)", "exactly one nested <bsdf>");
  ExpectLoadError(R"(<bsdf type="normalmap"><texture name="normalmap" type="bitmap"><string name="filename" value="/nonexistent.png"/></texture><bsdf type="diffuse"/></bsdf>)",
                  "nonexistent.png");
}

}  // namespace
}  // namespace objektiv
