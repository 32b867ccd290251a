// The lens hood (optics/lens_hood.h): light from the scene reaches the front element only
// through the mouth. Beams from a field angle pass whole up to the angle where the mouth's edge
// starts to cut them, tan(theta) = (mouth's half-width - front semi-diameter) / (length + the
// front rim's sag), along each side of a rectangular hood; steeper than where the mouth cuts
// them all, nothing passes.
// The batch tracer and the exact one agree with it; the pupil bounds still hold all the light
// (a rectangular hood is no figure of revolution); the scene reader's checks.
#include <gtest/gtest.h>

#include <cmath>

#include "base/rng.h"
#include "batch_agreement.h"
#include "lens_text.h"
#include "optics/glass_catalog.h"
#include "optics/lens_file.h"
#include "optics/lens_setup.h"
#include "optics/lens_tracer.h"
#include "optics/pupil_bounds.h"
#include "pupil_bound_checks.h"
#include "sanitizer_build.h"

namespace objektiv {
namespace {

LensSystem Tessar(const std::optional<LensHood>& hood) {
  LensSystem lens = AtParaxialInfinityFocus(LoadLens("tessar.brendel.100mm.lens", GlassCatalog::Default()));
  lens.SetHood(hood);
  return lens;
}

// A window: the stop (40 mm across, in air) and a plane behind it, nothing to bend or clip the
// beams but the hood.
LensSystem Window(const std::optional<LensHood>& hood) {
  LensSystem lens(test::ParseLensText("stop 1 air 20\nsurface inf 50 air 40\n"));
  lens.SetHood(hood);
  return lens;
}

// The share of a beam at angle theta in x that gets through, its rays uniform over the stop.
double BeamShare(const LensSystem& lens, double theta, PCG32& rng) {
  const Vec3d d = Normalize(Vec3d(std::tan(theta), 0, 1));
  int through = 0;
  const int count = 20000;
  for (int k = 0; k < count; ++k) {
    const double r = 20 * std::sqrt(rng.UniformFloat()), phi = 2 * M_PI * rng.UniformFloat();
    through += bool(TraceFromObject(lens, {Vec3d(r * std::cos(phi), r * std::sin(phi), 0) - d, d}, 550).ray);
  }
  return double(through) / count;
}

// The overlap of discs of radii a and b whose centres lie c apart.
double DiscOverlap(double a, double b, double c) {
  if (c >= a + b) return 0;
  if (c <= std::abs(a - b)) return M_PI * std::min(a, b) * std::min(a, b);
  return a * a * std::acos((c * c + a * a - b * b) / (2 * c * a)) + b * b * std::acos((c * c + b * b - a * a) / (2 * c * b)) -
         0.5 * std::sqrt((-c + a + b) * (c + a - b) * (c - a + b) * (c + a + b));
}

// A beam at angle theta crosses the mouth's plane L mm before the stop shifted by L tan(theta):
// what passes is the stop's disc shifted so, within the mouth (a disc; for a rectangle wide
// in x, a band |y| <= half-height, with its own closed form).
TEST(LensHood, BeamsPassWhereTheirShadowMeetsTheMouth) {
  PCG32 rng(3, 3);
  const LensSystem tube = Window(LensHood{50, 26, 0, 0});
  for (double deg : {0.0, 5.0, 15.0, 30.0, 45.0, 55.0}) {
    const double shift = 50 * std::tan(deg * M_PI / 180);
    EXPECT_NEAR(BeamShare(tube, deg * M_PI / 180, rng), DiscOverlap(20, 26, shift) / (M_PI * 400), 0.012) << deg;
  }
  // A box 200 mm wide and 30 mm high, the beam tilted in y: the disc of radius 20 shifted by
  // L tan(theta) across the band |y| <= 15: the share of a disc between two chords.
  const LensSystem box = Window(LensHood{40, 0, 100, 15});
  auto below = [](double h) {  // the share of the unit disc below the chord at height h
    h = std::clamp(h, -1.0, 1.0);
    return (h * std::sqrt(1 - h * h) + std::asin(h) + M_PI / 2) / M_PI;
  };
  for (double deg : {0.0, 3.0, 10.0, 25.0, 40.0}) {
    const double shift = 40 * std::tan(deg * M_PI / 180);
    const Vec3d d = Normalize(Vec3d(0, std::tan(deg * M_PI / 180), 1));
    int through = 0;
    for (int k = 0; k < 20000; ++k) {
      const double r = 20 * std::sqrt(rng.UniformFloat()), phi = 2 * M_PI * rng.UniformFloat();
      through += bool(TraceFromObject(box, {Vec3d(r * std::cos(phi), r * std::sin(phi), 0) - d, d}, 550).ray);
    }
    // In the mouth's plane the disc's centre lies at y = -shift: the band is y' = y + shift in [-15 + shift, 15 + shift].
    const double share = below((15 + shift) / 20) - below((-15 + shift) / 20);
    EXPECT_NEAR(through / 20000.0, share, 0.012) << deg;
  }
  // Out of the lens toward the scene, from the film, the exact tracer clips alike.
  const LensSystem bare = Tessar(std::nullopt), hooded = Tessar(LensHood{40, 0, 36, 24});
  int through = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3d o(0, 0, bare.FilmZ()), aim(rng.UniformFloat() * 40 - 20, rng.UniformFloat() * 40 - 20, bare.VertexZ(7));
    const TraceResult a = TraceFromFilm(bare, {o, Normalize(aim - o)}, 550);
    const TraceResult b = TraceFromFilm(hooded, {o, Normalize(aim - o)}, 550);
    through += bool(b.ray);
    if (b.ray) {
      ASSERT_TRUE(a.ray);
      EXPECT_TRUE(hooded.hood()->Passes(b.ray->o, b.ray->d, 0));
    } else if (a.ray) {
      EXPECT_FALSE(hooded.hood()->Passes(a.ray->o, a.ray->d, 0));
    }
  }
  EXPECT_GT(through, 100);
}

// The mouth must enclose the front element as placed and lie in front of its foremost point.
TEST(LensHood, MouthMustEncloseTheFrontElementAsPlaced) {
  const LensHood hood{10, 20, 0, 0};
  LensSurface s;
  s.radius = 40, s.semi_diameter = 18;
  EXPECT_EQ(hood.Mismatch(s), "");
  s.placement = SurfacePlacement::DecenterTilt(0, 3, 0, 0, 0);  // reaches 21 mm from the axis
  EXPECT_NE(hood.Mismatch(s).find("narrower than the front element (42 mm across as placed)"), std::string::npos);
  s.placement.reset();
  s.radius = -20;  // concave: the rim lies 11.28 mm before the vertex
  const LensHood long_hood{15, 20, 0, 0}, flat_box{10, 0, 30, 17};
  EXPECT_EQ(long_hood.Mismatch(s), "");
  EXPECT_NE(hood.Mismatch(s).find("rim reaches 11.28 mm before its vertex"), std::string::npos);
  s.radius = 40;
  EXPECT_NE(flat_box.Mismatch(s).find("(60 x 34 mm) is narrower"), std::string::npos);
}

TEST(LensHood, BatchTracerFollowsTheExactOne) {
  const test::BatchAgreement a = test::CompareTracers(Tessar(LensHood{60, 0, 30, 22}), 3000, 18, -200, 5, 2);
  test::ExpectAgreement(a, 300, 3, 1e-4);
}

TEST(LensHood, PupilBoundsHoldAllTheLight) {
  SKIP_UNDER_SANITIZERS("LensHood.BatchTracerFollowsTheExactOne");
  const LensSystem lens = Tessar(LensHood{60, 0, 30, 22});
  const PupilBounds bounds(lens, std::hypot(18.0, 12.0));
  PCG32 rng(7, 7);
  for (Vec2d film : {Vec2d(0, 0), Vec2d(15, 2), Vec2d(3, -11.5), Vec2d(17.5, 11.6)}) {
    const test::AreaEstimates a = test::PassingArea(lens, bounds, film, 25, 20000, rng, 550);
    ASSERT_TRUE(a.has_bound);
    EXPECT_NEAR(a.bound, a.brute, 4 * a.se) << film.x << ", " << film.y;
  }
}

}  // namespace
}  // namespace objektiv
