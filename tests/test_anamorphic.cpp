// Toroidal and cylindrical surfaces and anamorphic lenses: the toroid's sag and the exact
// tracer against the torus's and the cylinder's closed forms, the batch tracer against the
// exact one, the principal sections' paraxial data (squeeze) against thin-lens optics, the
// pupil bounds of a lens without rotational symmetry (pass rate and unbiasedness), and the
// readers (native rx=, Zemax TOROIDAL) and the scene's desqueeze.
#include <gtest/gtest.h>

#include <cmath>

#include "base/error.h"
#include "base/rng.h"
#include "base/sampling.h"
#include "camera/lens_camera_setup.h"
#include "camera/realistic_camera.h"
#include "batch_agreement.h"
#include "lens_text.h"
#include "pupil_bound_checks.h"
#include "log_capture.h"
#include "render_helpers.h"
#include "optics/anamorphic.h"
#include "optics/batch_tracer.h"
#include "optics/lens_file.h"
#include "optics/lens_setup.h"
#include "optics/lens_tracer.h"
#include "optics/paraxial.h"
#include "optics/pupil_bounds.h"
#include "optics/real_ray_analysis.h"
#include "optics/zemax_lens.h"
#include "sanitizer_build.h"

namespace objektiv {
namespace {

LensPrescription Parse(const std::string& text) { return test::ParseLensText(text); }
std::string ParseError(const std::string& text) { return test::LensTextError(text); }

TEST(Toroid, SagIsTheTorusOfItsTwoRadii) {
  // Profile: a circle of radius Ry = 60 (z_y = Ry - sqrt(Ry^2 - y^2)); turned about the axis
  // parallel to y through z = R = -80: the torus whose points lie at distance |R - z_y(y)| from
  // that axis, z = R + sqrt((R - z_y)^2 - x^2) (R < 0: the sheet through the vertex).
  LensSurface s;
  s.radius = 60;
  s.toroidal = true;
  s.curvature_x = 1 / -80.0;
  const double Ry = 60, R = -80;
  for (double x : {0.0, 3.0, -17.5, 25.0})
    for (double y : {0.0, 4.0, -20.0, 29.0}) {
      const double zy = Ry - std::sqrt(Ry * Ry - y * y);
      const double expected = R + std::sqrt((R - zy) * (R - zy) - x * x);
      double z, gx, gy;
      ASSERT_TRUE(s.SagAt(x, y, z, &gx, &gy)) << x << " " << y;
      EXPECT_NEAR(z, expected, 1e-12 * (1 + std::abs(expected))) << x << " " << y;
      // The gradient against central differences.
      const double h = 1e-5;
      double zp, zm;
      s.SagAt(x + h, y, zp), s.SagAt(x - h, y, zm);
      EXPECT_NEAR(gx, (zp - zm) / (2 * h), 1e-7) << x << " " << y;
      s.SagAt(x, y + h, zp), s.SagAt(x, y - h, zm);
      EXPECT_NEAR(gy, (zp - zm) / (2 * h), 1e-7) << x << " " << y;
    }
  // Beyond the x-z circle the surface ends.
  double z;
  EXPECT_FALSE(s.SagAt(81, 0, z));
}

TEST(Toroid, ExactTracerRefractsAtTheCylinderAsSnellSays) {
  // A cylinder curved in x (radius 40, flat in y) from air into n = 1.6: a skew ray's crossing
  // from the circle's quadratic in x and z alone, its normal (-x, 0, R - z) / R, then Snell.
  const LensSystem lens(Parse("surface inf 5 n=1.6 20 rx=40\nstop 5 n=1.6 10\nsurface inf 50 air 20\n"));
  const double R = 40, eta = 1 / 1.6;
  PCG32 rng(3, 9);
  for (int k = 0; k < 200; ++k) {
    const Vec3d o(rng.UniformFloat() * 30 - 15, rng.UniformFloat() * 30 - 15, -10);
    const Vec3d d = Normalize(Vec3d(rng.UniformFloat() * 0.4 - 0.2, rng.UniformFloat() * 0.4 - 0.2, 1));
    // (x, z - R) on the circle of radius R: (ox + t dx)^2 + (oz - R + t dz)^2 = R^2, nearer root.
    const double a = d.x * d.x + d.z * d.z, b = 2 * (o.x * d.x + (o.z - R) * d.z),
                 c = o.x * o.x + (o.z - R) * (o.z - R) - R * R;
    const double t = (-b - std::sqrt(b * b - 4 * a * c)) / (2 * a);
    const Vec3d p = o + d * t;
    if (p.x * p.x + p.y * p.y > 20 * 20) continue;
    Vec3d n = Vec3d(-p.x, 0, R - p.z) / R;  // toward +z at the vertex; faces the incoming ray
    if (Dot(n, d) > 0) n = -n;
    const double cos_i = -Dot(n, d), cos_t = std::sqrt(1 - eta * eta * (1 - cos_i * cos_i));
    const Vec3d expected = d * eta + n * (eta * cos_i - cos_t);
    const SurfaceCrossing cross = CrossSurface(lens, 0, {o, d}, 550, true);
    ASSERT_EQ(cross.failure, TraceFailure::kNone);
    EXPECT_NEAR(Length(cross.p - p), 0, 1e-10);
    std::optional<LensRay> out = Refracted(cross, d);
    ASSERT_TRUE(out);
    EXPECT_NEAR(Length(out->d - expected), 0, 1e-12);
    EXPECT_NEAR(out->d.y, eta * d.y, 1e-12);  // the normal has no y: Snell keeps n d_y
  }
}

TEST(Toroid, ExactTracerMeetsTheTorusOnItsImplicitSurface) {
  // A toroid of both curvatures (profile radius 50 with a conic, rotation radius -70): every
  // crossing lies on the surface, and the normal is the implicit form's gradient.
  LensPrescription p = Parse("surface 50 4 n=1.5 18 rx=-70\nstop 5 n=1.5 10\nsurface inf 40 air 20\n");
  const LensSystem lens(p);
  PCG32 rng(7, 1);
  int met = 0;
  for (int k = 0; k < 300; ++k) {
    const Vec3d o(rng.UniformFloat() * 36 - 18, rng.UniformFloat() * 36 - 18, -5);
    const Vec3d d = Normalize(Vec3d(rng.UniformFloat() * 0.6 - 0.3, rng.UniformFloat() * 0.6 - 0.3, 1));
    const SurfaceCrossing c = CrossSurface(lens, 0, {o, d}, 550, true);
    if (c.failure != TraceFailure::kNone) continue;
    ++met;
    // sqrt(x^2 + (z - R)^2) is the distance from the axis of rotation: |R - z_y(y)|.
    const double R = -70, Ry = 50;
    const double zy = Ry - std::sqrt(Ry * Ry - c.p.y * c.p.y);
    EXPECT_NEAR(std::hypot(c.p.x, c.p.z - R), std::abs(R - zy), 1e-9);
    // The normal is perpendicular to both tangent directions of the parametrisation.
    double z0, gx, gy;
    ASSERT_TRUE(p.surfaces[0].SagAt(c.p.x, c.p.y, z0, &gx, &gy));
    EXPECT_NEAR(Dot(c.normal, Vec3d(1, 0, gx)), 0, 1e-12);
    EXPECT_NEAR(Dot(c.normal, Vec3d(0, 1, gy)), 0, 1e-12);
  }
  EXPECT_GT(met, 200);
}

// The shipped anamorphic set up as a camera would have it, focused at infinity.
LensSystem Anamorphic() {
  return AtParaxialInfinityFocus(LoadLens("anamorphic.250mm", GlassCatalog::Default()), kLambdad);
}

TEST(Anamorphic, SectionsFollowThinLensOptics) {
  // The adapter: a Galilean telescope of a -100 mm and a +200 mm cylinder, afocal in x,
  // plates in y: the lens's y-z section is the prime's, and its x-z section has the prime's
  // focal length over the telescope's magnification, 2 (thick lenses: within 2%).
  const LensSystem lens = Anamorphic();
  const LensPrescription prime = LoadLens("telephoto.250mm", GlassCatalog::Default());
  const ParaxialData y = lens.paraxial(), py = ComputeParaxial(prime);
  EXPECT_NEAR(y.efl, py.efl, 1e-9);
  EXPECT_NEAR(y.bfl, py.bfl, 1e-9);
  const Anamorphosis a = ComputeAnamorphosis(lens.prescription(), y);
  EXPECT_NEAR(a.squeeze, 2, 0.04);
  EXPECT_NEAR(a.x.efl, py.efl / a.squeeze, 1e-9);
  EXPECT_LT(std::abs(a.focus_split), 0.05);  // spaced so that both sections focus together
  // A rotationally symmetric lens: squeeze 1 exactly.
  EXPECT_DOUBLE_EQ(ComputeAnamorphosis(prime, py).squeeze, 1);
  // The horizontal field is twice the prime's, the vertical the same.
  const FieldOfView f = SensorFieldOfView(lens, 36, 24, kLambdad);
  const FieldOfView fp = SensorFieldOfView(AtParaxialInfinityFocus(prime, kLambdad), 36, 24, kLambdad);
  EXPECT_NEAR(std::tan(f.horizontal / 2 * M_PI / 180) / std::tan(fp.horizontal / 2 * M_PI / 180), a.squeeze, 0.03);
  EXPECT_NEAR(f.vertical, fp.vertical, 1e-6);
  EXPECT_TRUE(std::isnan(f.diagonal));
}

TEST(Anamorphic, XSectionIsTheLensTurnedAQuarter) {
  // Any ray through the lens, turned a quarter about the axis ((x, y) -> (-y, x)), is the ray
  // through the x-section's system, turned the same; its paraxial data are the x-z section's.
  const LensSystem lens = Anamorphic(), x = XSectionSystem(lens);
  auto turn = [](const Vec3d& v) { return Vec3d(-v.y, v.x, v.z); };
  PCG32 rng(4, 4);
  int through = 0;
  for (int k = 0; k < 200; ++k) {
    const Vec3d o(rng.UniformFloat() * 40 - 20, rng.UniformFloat() * 40 - 20, -20);
    const Vec3d d = Normalize(Vec3d(rng.UniformFloat() * 0.2 - 0.1, rng.UniformFloat() * 0.2 - 0.1, 1));
    const TraceResult a = TraceFromObject(lens, {o, d}, kLambdad);
    const TraceResult b = TraceFromObject(x, {turn(o), turn(d)}, kLambdad);
    ASSERT_EQ(bool(a.ray), bool(b.ray)) << k;
    if (!a.ray) continue;
    ++through;
    EXPECT_NEAR(Length(turn(a.ray->o) - b.ray->o), 0, 1e-9);
    EXPECT_NEAR(Length(turn(a.ray->d) - b.ray->d), 0, 1e-12);
  }
  EXPECT_GT(through, 50);
  // Paraxially: Euler's curvature of each turned cylinder in the y-z plane is its x curvature.
  const ParaxialData px = x.paraxial();
  const Anamorphosis a = ComputeAnamorphosis(lens.prescription(), lens.paraxial());
  EXPECT_NEAR(px.efl, a.x.efl, 1e-9);
  EXPECT_NEAR(px.efl, 123.578, 1e-3);
  // One on-axis spot, whichever section it is analysed in (sampled over the whole oval pupil).
  const Spot sy = SpotDiagram(lens, 0, kLambdad), sx = SpotDiagram(x, 0, kLambdad);
  EXPECT_NEAR(sy.rms_radius, sx.rms_radius, 1e-9);
  EXPECT_NEAR(sy.transmitted, sx.transmitted, 1e-12);
}

TEST(Anamorphic, BatchTracerFollowsTheExactOne) {
  // Carried to the plane 100 mm in front of the first vertex.
  const test::BatchAgreement a = test::CompareTracers(Anamorphic(), 4000, 20, -100, 1, 2);
  // Within 5 um 100 mm in front of the lens (directions to about 5e-5); a few rays in a
  // thousand graze a rim.
  test::ExpectAgreement(a, 400, 8, 5e-3);
}

// A 1.5x anamorphic on the double Gauss at f/2 whose rims cut the beams into cat's eyes that
// change across the film in x and y (through the shipped 250 mm the stop alone shapes them, the
// same everywhere, and any bound would pass). Film points uniform over full frame.
LensSystem Vignetting() {
  return AtParaxialInfinityFocus(
      LoadLens(std::string(OBJEKTIV_TEST_DATA_DIR) + "/anamorphic-dgauss.lens", GlassCatalog::Default()), kLambdad);
}
constexpr double kHalfWidth = 18, kHalfHeight = 12;
Vec2d FilmPoint(PCG32& rng) {
  return {(2 * rng.UniformFloat() - 1) * kHalfWidth, (2 * rng.UniformFloat() - 1) * kHalfHeight};
}

TEST(Anamorphic, PupilBoundsPassMostRaysWithoutRotationalSymmetry) {
  SKIP_UNDER_SANITIZERS("Anamorphic.DesqueezedTheBallIsRound and Anamorphic.DesqueezeIsChecked (round and bladed)");
  for (int blades : {0, 5}) {
    LensSystem lens = Vignetting();
    lens.SetStopShape(StopShape::Iris(blades, 0, 0.3));
    const PupilBounds bounds(lens, std::hypot(kHalfWidth, kHalfHeight));
    PCG32 rng(11, 3);
    const test::PassRate pass = test::CameraPassRate(lens, bounds, 20000, rng, FilmPoint, kLambdad);
    EXPECT_GT(pass.launched, 19500) << blades;
    // 94.5% (the radial tables of the shipped lenses: 95% or more; the shipped anamorphic 99.3%).
    EXPECT_GE(pass.Rate(), 0.94) << blades << " blades: " << pass.passed << "/" << pass.launched;
  }
}

TEST(Anamorphic, PupilBoundsHoldAllTheLight) {
  SKIP_UNDER_SANITIZERS("Anamorphic.DesqueezedTheBallIsRound and Anamorphic.DesqueezeIsChecked (round and bladed)");
  // The passing area on the sampling plane estimated two ways, as in PupilBounds'
  // TheBoundContainsAllTheLight: uniformly over a square that holds the whole rear element's
  // light, and through the bound; off both axes, where only the x-y table serves.
  for (int blades : {0, 5}) {
    LensSystem lens = Vignetting();
    lens.SetStopShape(StopShape::Iris(blades, 0, 0.3));
    const PupilBounds bounds(lens, std::hypot(kHalfWidth, kHalfHeight));
    PCG32 rng(5, 1);
    for (Vec2d film : {Vec2d(0, 0), Vec2d(9.3, 5.1), Vec2d(-16.7, 11.2), Vec2d(17.9, -8.3), Vec2d(-1.1, -11.7)}) {
      // 30 mm: wider than the rear element's light on the exit pupil's plane.
      const test::AreaEstimates a = test::PassingArea(lens, bounds, film, 30, 40000, rng, kLambdad);
      ASSERT_TRUE(a.has_bound);
      EXPECT_NEAR(a.bound, a.brute, 4 * a.se) << blades << " blades at " << film.x << ", " << film.y;
    }
  }
}

TEST(Anamorphic, TheEntrancePupilIsHalfAsWideAsItIsTall) {
  // Why its bokeh is oval: the widest parallel beams along the axis that get through, in x and
  // in y, differ by the adapter's magnification.
  const LensSystem lens = Anamorphic();
  auto widest = [&](Vec2d dir) {
    double lo = 0, hi = 40;
    for (int it = 0; it < 50; ++it) {
      const double mid = 0.5 * (lo + hi);
      (TraceFromObject(lens, {{mid * dir.x, mid * dir.y, -10}, {0, 0, 1}}, kLambdad).ray ? lo : hi) = mid;
    }
    return lo;
  };
  const double rx = widest({1, 0}), ry = widest({0, 1});
  EXPECT_NEAR(ry, lens.paraxial().entrance_pupil_diameter / 2, 0.05 * ry);
  EXPECT_NEAR(ry / rx, ComputeAnamorphosis(lens.prescription(), lens.paraxial()).squeeze, 0.05);
}

TEST(Anamorphic, NativeReaderChecksTheToroid) {
  const LensPrescription p = Parse("surface inf 5 n=1.5 10 rx=-30\nstop 5 air 8\nsurface 40 3 n=1.5 10 rx=inf\n"
                                   "surface -40 30 air 10\n");
  EXPECT_TRUE(p.surfaces[0].toroidal);
  EXPECT_NEAR(p.surfaces[0].curvature_x, -1 / 30.0, 1e-15);
  EXPECT_TRUE(p.surfaces[2].toroidal);
  EXPECT_EQ(p.surfaces[2].curvature_x, 0);
  EXPECT_FALSE(p.RotationallySymmetric());
  EXPECT_NE(ParseError("surface inf 5 n=1.5 10 rx=0\nstop 5 air 8\n").find("test.lens:1: rx=0"), std::string::npos);
  // A semi-diameter beyond the x-z circle, and beyond where the profile reaches the axis of rotation.
  EXPECT_NE(ParseError("surface inf 5 n=1.5 10 rx=8\nstop 5 air 8\n").find("test.lens:1: semi-diameter 10 is larger than the toroid"),
            std::string::npos);
  EXPECT_NE(ParseError("surface 12 5 n=1.5 10 rx=9\nstop 5 air 8\n").find("test.lens:1: semi-diameter 10 is larger than the toroid"),
            std::string::npos);
}

TEST(Anamorphic, ZemaxToroidalIsTheNativeToroid) {
  auto zmx = [](const std::string& toroid) {
    return "MODE SEQ\nUNIT MM X W X CM MR CPMM\n"
           "SURF 0\n  TYPE STANDARD\n  CURV 0.0\n  DISZ INFINITY\n"
           "SURF 1\n  TYPE TOROIDAL\n  CURV 0.02\n  CONI -0.5\n" + toroid + "  GLAS ___BLANK 1 0 1.5 60\n  DISZ 5\n  DIAM 10\n"
           "SURF 2\n  STOP\n  TYPE STANDARD\n  CURV 0.0\n  DISZ 30\n  DIAM 8\n"
           "SURF 3\n  TYPE STANDARD\n  CURV 0.0\n  DISZ 0\n  DIAM 10\n";
  };
  test::LogCapture log;
  const LensPrescription z = ParseZemaxLens(zmx("  PARM 1 -40\n  PARM 2 1e-4\n  PARM 3 2e-6\n"), "t.zmx", GlassCatalog::Default());
  EXPECT_EQ(log.Text(), "");
  const LensPrescription n = Parse("surface 50 5 n=1.5 10 k=-0.5 rx=-40 a4=2e-6\nstop 30 air 8\n");
  const LensSurface &a = z.surfaces[0], &b = n.surfaces[0];
  ASSERT_TRUE(a.toroidal);
  EXPECT_NEAR(a.curvature_x, b.curvature_x, 1e-15);
  EXPECT_NEAR(a.a2, 1e-4, 1e-18);
  EXPECT_NEAR(a.aspheric[0], 2e-6, 1e-20);
  // The same surface but for the y^2 term: the sags differ by it alone.
  double za, zb;
  ASSERT_TRUE(a.SagAt(0, 7, za));
  ASSERT_TRUE(b.SagAt(0, 7, zb));
  EXPECT_NEAR(za - zb, 1e-4 * 49, 1e-9);
  // PARM 1 = 0: infinite, a cylinder flat in x.
  EXPECT_EQ(ParseZemaxLens(zmx("  PARM 1 0\n"), "t.zmx", GlassCatalog::Default()).surfaces[0].curvature_x, 0);
  // Zernike terms on the toroid are refused, a parameter the type does not read is warned about.
  EXPECT_THROW(ParseZemaxLens(zmx("  PARM 13 4\n"), "t.zmx", GlassCatalog::Default()), InputError);
  std::string standard = zmx("  PARM 1 -40\n");
  standard.replace(standard.find("TYPE TOROIDAL"), 13, "TYPE STANDARD");
  ParseZemaxLens(standard, "t.zmx", GlassCatalog::Default());
  EXPECT_NE(log.Text().find("t.zmx:11: PARM 1 = -40 means nothing to a STANDARD surface"), std::string::npos) << log.Text();
}

TEST(Anamorphic, ParaxialModelsRefuseIt) {
  LensCameraSpec spec;
  spec.lens = LoadLens("anamorphic.250mm", GlassCatalog::Default());
  spec.model = LensModel::kThin;
  try {
    MakeLensCamera(Transform(), 64, 32, spec);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("anamorphic"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

// A glowing ball 100 m away, in focus, through the shipped anamorphic.
std::string BallScene(const std::string& desqueeze) {
  return R"(<scene version="3.0.0">
  <integrator type="path"><integer name="max_depth" value="1"/></integrator>
  <sensor type="realistic">
    <string name="lens" value="anamorphic.250mm"/>
    <string name="sensor" value="full_frame"/>
    )" + desqueeze + R"(
    <float name="focus_distance" value="100"/>
    <transform name="to_world"><lookat origin="0, 0, 0" target="0, 0, -1" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="8"/></sampler>
    <film type="hdrfilm"><integer name="width" value="300"/><integer name="height" value="100"/>
      <rfilter type="box"/></film>
  </sensor>
  <shape type="sphere"><point name="center" x="0" y="0" z="-100"/><float name="radius" value="1.9"/>
    <emitter type="area"><rgb name="radiance" value="1"/></emitter></shape>
</scene>)";
}

// The ball's extent in pixels across and up: the columns and rows whose brightest pixel is
// above half the image's brightest.
Vec2d Extent(const Image& img) {
  float peak = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) peak = std::max(peak, img.At(x, y, 1));
  int cols = 0, rows = 0;
  for (int x = 0; x < img.width; ++x) {
    bool lit = false;
    for (int y = 0; y < img.height; ++y) lit |= img.At(x, y, 1) > 0.5f * peak;
    cols += lit;
  }
  for (int y = 0; y < img.height; ++y) {
    bool lit = false;
    for (int x = 0; x < img.width; ++x) lit |= img.At(x, y, 1) > 0.5f * peak;
    rows += lit;
  }
  return {double(cols), double(rows)};
}

TEST(Anamorphic, DesqueezedTheBallIsRound) {
  // Squeezed on the film: half as wide as tall (pixels as wide as tall on the film); desqueezed
  // by the lens's squeeze: round (pixels 2.02 times taller than wide on the film).
  const Vec2d squeezed = Extent(test::RenderXml(BallScene("")).image);
  const Vec2d round = Extent(test::RenderXml(BallScene(R"(<string name="desqueeze" value="lens"/>)")).image);
  EXPECT_NEAR(round.y, 2 * 250 * 1.9 / 100 / 0.24, 2);  // 39.6 rows of 0.24 mm
  EXPECT_NEAR(round.x / round.y, 1, 0.06) << round.x << " x " << round.y;
  EXPECT_NEAR(squeezed.y / squeezed.x, 2.02, 0.15) << squeezed.x << " x " << squeezed.y;
  const RenderSetup setup = LoadSceneFromString(BallScene(R"(<string name="desqueeze" value="lens"/>)"), "test.xml", {});
  const auto* camera = dynamic_cast<const RealisticCamera*>(setup.camera.get());
  ASSERT_TRUE(camera);
  EXPECT_NEAR(camera->PixelSize().y / camera->PixelSize().x, 2.0195, 1e-3);
}

TEST(Anamorphic, DesqueezeIsChecked) {
  auto scene_error = [](const std::string& xml) {
    try {
      LoadSceneFromString(xml, "test.xml", {});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  std::string symmetric = BallScene(R"(<string name="desqueeze" value="lens"/>)");
  symmetric.replace(symmetric.find("anamorphic.250mm"), 16, "dgauss.50mm");
  EXPECT_NE(scene_error(symmetric).find("is not anamorphic"), std::string::npos) << scene_error(symmetric);
  const std::string bad = scene_error(BallScene(R"(<string name="desqueeze" value="2x"/>)"));
  EXPECT_NE(bad.find("test.xml:6: desqueeze '2x'"), std::string::npos) << bad;
  // A number, with an iris of blades (the x-y table over the whole film, no mirror symmetry).
  EXPECT_EQ(scene_error(BallScene(R"(<string name="desqueeze" value="1.33"/><integer name="blades" value="5"/>)")), "accepted");
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

// Where thin fans from an axial object point `distance` mm in front of the film cross the axis
// in x and in y, relative to the film.
Vec2d SectionFoci(const LensSystem& lens, double distance) {
  const Vec3d object(0, 0, lens.FilmZ() - distance);
  double foci[2];
  for (int axis = 0; axis < 2; ++axis) {
    const Vec3d aim(axis == 0 ? 0.5 : 0, axis == 1 ? 0.5 : 0, 0);
    const Vec3d d = Normalize(aim - object);
    const TraceResult t = TraceFromObject(lens, {aim - d * 10, d}, kLambdad);
    EXPECT_TRUE(t.ray);
    if (!t.ray) return {NAN, NAN};
    const double c = axis == 0 ? t.ray->o.x : t.ray->o.y, dc = axis == 0 ? t.ray->d.x : t.ray->d.y;
    foci[axis] = t.ray->o.z - c * t.ray->d.z / dc - lens.FilmZ();
  }
  return {foci[0], foci[1]};
}

TEST(Anamorphic, ItsOwnFocusingBringsBothSectionsTogether) {
  // Focused at 8 m: the adapter's gap set for that distance brings both sections' paraxial foci
  // together (the film then goes to the best real-ray focus, which the aberrations put about
  // 1.7 mm in front); without it (the whole lens moved alone) they lie 6 mm apart.
  FocusRequest at8m;
  at8m.distance_mm = 8000;
  const LensPrescription shipped = LoadLens("anamorphic.250mm", GlassCatalog::Default());
  ASSERT_EQ(shipped.focus_gap, 1);
  const LensSetup focused = SetUpLens(shipped, {}, at8m);
  const Vec2d with = SectionFoci(focused.lens, 8000);
  EXPECT_LT(std::abs(with.x - with.y), 0.02) << with.x << " " << with.y;
  EXPECT_NE(focused.report.find("anamorphic focusing: the gap after row 2"), std::string::npos) << focused.report;
  LensPrescription fixed = shipped;
  fixed.focus_gap = -1;
  test::LogCapture log;
  const Vec2d without = SectionFoci(SetUpLens(fixed, {}, at8m).lens, 8000);
  EXPECT_GT(std::abs(without.x - without.y), 3) << without.x << " " << without.y;
  EXPECT_NE(log.Text().find("its horizontal and vertical sections focus"), std::string::npos) << log.Text();
  // At infinity the gap is the design's.
  EXPECT_EQ(SetUpLens(shipped, {}, {}).lens.prescription().surfaces[1].thickness, shipped.surfaces[1].thickness);
}

TEST(Anamorphic, FocusGapIsChecked) {
  const std::string adapter = "surface inf 3 n=1.5 20 rx=-50\nsurface inf 50 air 20 rx=50\nstop 10 air 8\n";
  EXPECT_EQ(ParseError("focus_gap: 2\n" + adapter), "accepted");
  EXPECT_NE(ParseError("focus_gap: 3\n" + adapter).find("test.lens:1: focus_gap 3"), std::string::npos);
  EXPECT_NE(ParseError("focus_gap: x\n" + adapter).find("test.lens:1: focus_gap 'x'"), std::string::npos);
  EXPECT_NE(ParseError("focus_gap: 1\nsurface 50 5 n=1.5 20\nsurface inf 50 air 20\nstop 10 air 8\n").find("no toroidal"),
            std::string::npos);
}

}  // namespace
}  // namespace objektiv
