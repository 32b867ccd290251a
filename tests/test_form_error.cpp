// Surface form error (optics/form_error.h): the shape's peak-to-valley, seed and scale, its
// gradient; a plate's rough face bends a ray as Snell's law at the shape's normal says; the
// batch tracer against the exact one; the pupil bounds of a lens no longer rotationally
// symmetric (pass rate, all the light); the reader's checks and the paraxial models' refusal.
#include <gtest/gtest.h>

#include <cmath>

#include "base/error.h"
#include "base/rng.h"
#include "batch_agreement.h"
#include "lens_text.h"
#include "pupil_bound_checks.h"
#include "camera/lens_camera_setup.h"
#include "optics/form_error.h"
#include "optics/lens_file.h"
#include "optics/lens_setup.h"
#include "optics/lens_tracer.h"
#include "optics/pupil_bounds.h"
#include "sanitizer_build.h"

namespace objektiv {
namespace {

LensPrescription Parse(const std::string& text) { return test::ParseLensText(text); }
std::string ParseError(const std::string& text) { return test::LensTextError(text); }

TEST(FormError, PeakToValleyIsAsAsked) {
  for (uint64_t seed : {1u, 2u, 77u}) {
    const FormError e(0.002, seed, 20);
    // Polar samples (another grid than the shape's own), the rim included.
    double lo = INFINITY, hi = -INFINITY;
    for (int a = 0; a < 720; ++a)
      for (int k = 0; k <= 200; ++k) {
        const double r = 20.0 * k / 200, phi = 2 * M_PI * a / 720;
        const double h = e.Height(r * std::cos(phi), r * std::sin(phi));
        lo = std::min(lo, h), hi = std::max(hi, h);
      }
    EXPECT_NEAR(hi - lo, 0.002, 0.002 * 0.01) << seed;
    // No piston, no tilt: zero height and slope at the vertex.
    double gx, gy;
    EXPECT_EQ(e.Height(0, 0, &gx, &gy), 0);
    EXPECT_EQ(gx, 0);
    EXPECT_EQ(gy, 0);
  }
}

TEST(FormError, ASeedIsAShapeAtAnySize) {
  const FormError a(0.001, 5, 10), again(0.001, 5, 10), other(0.001, 6, 10);
  const FormError twice = a.Scaled(2);
  double differs = 0;
  for (double x : {-7.0, -2.5, 0.5, 6.0})
    for (double y : {-6.0, 1.0, 4.5}) {
      EXPECT_EQ(a.Height(x, y), again.Height(x, y));
      EXPECT_NEAR(twice.Height(2 * x, 2 * y), 2 * a.Height(x, y), 1e-15);
      differs = std::max(differs, std::abs(a.Height(x, y) - other.Height(x, y)));
      // The gradient against central differences.
      double gx, gy;
      a.Height(x, y, &gx, &gy);
      const double h = 1e-4;
      EXPECT_NEAR(gx, (a.Height(x + h, y) - a.Height(x - h, y)) / (2 * h), 1e-10);
      EXPECT_NEAR(gy, (a.Height(x, y + h) - a.Height(x, y - h)) / (2 * h), 1e-10);
    }
  EXPECT_GT(differs, 1e-4);  // another seed, another shape
}

TEST(FormError, APlatesRoughFaceBendsARayAsSnellSays) {
  // A plate of index 1.5 whose front has a 20 um form error; a ray parallel to the axis meets
  // it at (x, y) + e(x, y) and refracts at the normal (-grad e, 1); then the flat back.
  const LensSystem plate(Parse("stop 1 air 20\nsurface inf 5 n=1.5 20 form_error_um=20 form_seed=3\nsurface inf 40 air 20\n"));
  const FormError& e = *plate.prescription().surfaces[1].form_error;
  for (Vec2d at : {Vec2d(3, 4), Vec2d(-12, 7.5), Vec2d(15, -9)}) {
    const Vec3d o(at.x, at.y, -5);
    const TraceResult t = TraceFromObject(plate, {o, Vec3d(0, 0, 1)}, 550);
    ASSERT_TRUE(t.ray);
    double gx, gy;
    const double h = e.Height(at.x, at.y, &gx, &gy);
    // Snell's law in vector form at the normal facing the ray, -(-grad e, 1) / |.|, air to
    // 1.5; then 1.5 to air at the flat back.
    const Vec3d n = -Normalize(Vec3d(-gx, -gy, 1));
    const double eta = 1 / 1.5, cos_i = -n.z, k = 1 - eta * eta * (1 - cos_i * cos_i);
    const Vec3d inside = Vec3d(0, 0, 1) * eta + n * (eta * cos_i - std::sqrt(k));
    const Vec3d out_xy(inside.x * 1.5, inside.y * 1.5, 0);
    EXPECT_NEAR(t.ray->d.x, out_xy.x, 1e-12) << at.x;
    EXPECT_NEAR(t.ray->d.y, out_xy.y, 1e-12) << at.x;
    EXPECT_GT(std::hypot(out_xy.x, out_xy.y), 1e-6);  // the slope bends it measurably
    // Where it left the plate: from the rough face's point, straight through the glass.
    const Vec3d front(at.x, at.y, plate.VertexZ(1) + h);
    const double s = (plate.VertexZ(2) - front.z) / inside.z;
    EXPECT_NEAR(t.ray->o.x, front.x + s * inside.x, 1e-9);
    EXPECT_NEAR(t.ray->o.y, front.y + s * inside.y, 1e-9);
  }
}

// The Tessar with two rough faces (the front 30 um, the rear 15 um, peak to valley).
LensSystem RoughTessar() {
  return AtParaxialInfinityFocus(Parse(R"(
surface  42.970    9.8        n=1.691    19.2   form_error_um=30
surface  -115.33   2.1        n=1.5487   19.2
surface  306.840   4.16       air        19.2
stop               4.0        air        15.0
surface  -59.060   1.870      n=1.6398   17.3
surface  40.930    10.640     air        17.3
surface  183.920   7.050      n=1.691    16.5
surface  -48.910   79.831     air        16.5   form_error_um=15 form_seed=9
)"),
                                 kLambdad);
}

TEST(FormError, BatchTracerFollowsTheExactOne) {
  const LensSystem lens = RoughTessar();
  EXPECT_FALSE(lens.prescription().RotationallySymmetric());
  const test::BatchAgreement a = test::CompareTracers(lens, 4000, 20, -100, 2, 8);
  test::ExpectAgreement(a, 400, 8, 5e-3);
}

TEST(FormError, PupilBoundsPassMostRaysAndHoldAllTheLight) {
  SKIP_UNDER_SANITIZERS("FormError.BatchTracerFollowsTheExactOne");
  const LensSystem lens = RoughTessar();  // round stop (a bladed iris on the x-y table: Anamorphic's tests)
  const PupilBounds bounds(lens, std::hypot(18.0, 12.0));
  EXPECT_EQ(bounds.MaxAzimuthColumns(), 0);  // the x-y table: no symmetry left
  PCG32 rng(3, 3);
  const test::PassRate pass = test::CameraPassRate(lens, bounds, 20000, rng, [](PCG32& g) {
    return Vec2d((2 * g.UniformFloat() - 1) * 18, (2 * g.UniformFloat() - 1) * 12);
  }, kLambdad);
  EXPECT_GE(pass.Rate(), 0.94);
  for (Vec2d film : {Vec2d(0, 0), Vec2d(-11.0, 6.3), Vec2d(16.4, -10.9)}) {
    const test::AreaEstimates a = test::PassingArea(lens, bounds, film, 35, 30000, rng, kLambdad);
    ASSERT_TRUE(a.has_bound);
    EXPECT_NEAR(a.bound, a.brute, 4 * a.se) << film.x << ", " << film.y;
  }
}

TEST(FormError, ReaderChecksItAndTheParaxialModelsRefuseIt) {
  const std::string head = "stop 5 air 10\n";
  const LensPrescription ok = Parse(head + "surface 50 5 n=1.5 12 form_error_um=0.5\nsurface -50 40 air 12 form_error_um=1 form_seed=4\n");
  ASSERT_TRUE(ok.surfaces[1].form_error);
  EXPECT_DOUBLE_EQ(ok.surfaces[1].form_error->peak_to_valley(), 0.0005);
  EXPECT_EQ(ok.surfaces[1].form_error->seed(), 2u);  // the row's number
  EXPECT_EQ(ok.surfaces[2].form_error->seed(), 4u);
  EXPECT_DOUBLE_EQ(ok.surfaces[1].form_error->radius(), 12);
  auto error = [&](const std::string& options) {
    return ParseError(head + "surface 50 5 n=1.5 12 " + options + "\nsurface -50 40 air 12\n");
  };
  EXPECT_NE(error("form_error_um=0").find("test.lens:2: form_error_um=0: a peak-to-valley in micrometres"), std::string::npos);
  EXPECT_NE(error("form_error_um=2000").find("at most 1000"), std::string::npos);
  EXPECT_NE(error("form_seed=3").find("form_seed= without form_error_um="), std::string::npos);
  EXPECT_NE(error("form_error_um=1 form_seed=-1").find("an integer from 0"), std::string::npos);
  EXPECT_NE(error("form_error_um=1 zones=0.5").find("Fresnel"), std::string::npos);
  LensCameraSpec spec;
  spec.lens = ok;
  spec.model = LensModel::kThin;
  try {
    MakeLensCamera(Transform(), 64, 32, spec);
    ADD_FAILURE() << "the thin model took a lens with form errors";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("form errors"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace objektiv
