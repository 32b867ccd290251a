// Fresnel surfaces (optics/fresnel_zones.h): the zoned sag against its definition, the
// crossing against a brute-force walk along the ray, the risers' blocking against a ray built
// to meet one, the batch tracer against the exact one, the pupil bounds (they hold all the
// light where the risers cut thin rings out of the beam), the shipped Fresnel lens's focus and
// the reader's checks.
#include <gtest/gtest.h>

#include <cmath>

#include "base/error.h"
#include "base/rng.h"
#include "batch_agreement.h"
#include "lens_text.h"
#include "pupil_bound_checks.h"
#include "optics/fresnel_zones.h"
#include "optics/lens_file.h"
#include "optics/lens_setup.h"
#include "optics/lens_tracer.h"
#include "optics/paraxial.h"
#include "optics/pupil_bounds.h"
#include "optics/real_ray_analysis.h"
#include "sanitizer_build.h"

namespace objektiv {
namespace {

LensPrescription Parse(const std::string& text) { return test::ParseLensText(text); }
std::string ParseError(const std::string& text) { return test::LensTextError(text); }

// A strong zoned surface: the profile of radius -10 mm (k -0.5), zones 1 mm wide, 6 mm across.
LensSurface Zoned() {
  LensSurface s;
  s.radius = -10;
  s.conic = -0.5;
  s.semi_diameter = 6;
  s.fresnel = std::make_shared<const FresnelZones>(s, 1.0);
  return s;
}

TEST(FresnelZones, SagIsTheProfileLoweredInEachZone) {
  const LensSurface s = Zoned();
  for (double r : {0.0, 0.4, 0.999, 1.0, 2.5, 3.7, 5.99}) {
    const int k = int(std::floor(r));
    double z, gx, gy;
    ASSERT_TRUE(s.SagAt(0.6 * r, 0.8 * r, z, &gx, &gy));
    EXPECT_NEAR(z, s.Sag(r) - s.Sag(k), 1e-14) << r;
    EXPECT_NEAR(std::hypot(gx, gy), std::abs(s.SagSlope(r)), 1e-12) << r;  // the profile's slope
    EXPECT_GE(z, s.fresnel->slab_lo()) << r;
    EXPECT_LE(z, s.fresnel->slab_hi()) << r;
  }
  // Concave toward the film: each facet runs from the vertex plane toward the object.
  EXPECT_LT(s.fresnel->slab_lo(), -0.5);
  EXPECT_GT(s.fresnel->slab_hi(), -1e-3);
}

TEST(FresnelZones, CrossingIsTheFirstOneAlongTheRay) {
  // Random rays through the slab from the glass side (z < facet): the crossing found lies on
  // the facet, and a fine walk along the ray finds no crossing or riser before it.
  const LensSurface s = Zoned();
  PCG32 rng(4, 1);
  int hits = 0, risers = 0;
  for (int i = 0; i < 2000; ++i) {
    // Within the clear aperture (6 mm) all the way through the slab.
    const Vec3d o((2 * rng.UniformFloat() - 1) * 2.8, (2 * rng.UniformFloat() - 1) * 2.8, -3);
    const Vec3d d = Normalize(Vec3d((2 * rng.UniformFloat() - 1) * 0.35, (2 * rng.UniformFloat() - 1) * 0.35, 1));
    const std::optional<FresnelZones::Hit> hit = s.fresnel->Intersect(s, o, d);
    ASSERT_TRUE(hit) << i;  // every ray leaves the slab through a facet or a riser
    const Vec3d p = o + d * hit->t;
    double z;
    s.SagAt(p.x, p.y, z);
    if (hit->riser) {
      ++risers;
      const double r = std::hypot(p.x, p.y);
      EXPECT_NEAR(r, std::round(r), 1e-9) << i;  // on a zone's radius
    } else {
      ++hits;
      EXPECT_NEAR(p.z, z, 1e-9) << i;
    }
    // Brute force: below the surface (in the glass) at every step up to the crossing.
    for (int j = 1; j < 4000; ++j) {
      const Vec3d q = o + d * (hit->t * j / 4000.0);
      double zq;
      s.SagAt(q.x, q.y, zq);
      ASSERT_LT(q.z, zq + 1e-9) << i << " step " << j;
    }
  }
  EXPECT_GT(hits, 1500);
  EXPECT_GT(risers, 5);  // steep rays meet the risers of the outer zones (13 of these)
}

TEST(FresnelZones, ARayMeetsTheRiserOnlyWithinItsHeight) {
  const LensSurface s = Zoned();
  const double h2 = s.Sag(3) - s.Sag(2);  // the riser at r = 3 runs from h2 (< 0) to 0
  ASSERT_LT(h2, -0.2);
  // In the air over facet 2, heading outward nearly level: it meets the riser at r = 3.
  const Vec3d out = Normalize(Vec3d(0, 1, 1e-4));
  const std::optional<FresnelZones::Hit> blocked = s.fresnel->Intersect(s, Vec3d(0, 2.9, 0.5 * h2), out);
  ASSERT_TRUE(blocked);
  EXPECT_TRUE(blocked->riser);
  EXPECT_NEAR(2.9 + blocked->t * out.y, 3, 1e-9);
  // Above the riser's top it passes over it (and over zone 3's facet, which starts below it).
  const std::optional<FresnelZones::Hit> over = s.fresnel->Intersect(s, Vec3d(0, 2.9, 0.02), out);
  EXPECT_TRUE(!over || !over->riser);
}

TEST(FresnelZones, OneZoneWiderThanTheApertureIsTheProfile) {
  // One zone: the facet is the profile itself (lowered by its height at the centre, 0).
  const std::string front = "stop 0.5 air 10\nsurface 30 5 n=1.5 11";
  const LensSystem zoned(Parse(front + " zones=1000\nsurface inf 50 air 11\n"));
  const LensSystem plain(Parse(front + "\nsurface inf 50 air 11\n"));
  PCG32 rng(9, 9);
  for (int i = 0; i < 200; ++i) {
    const Vec3d o((2 * rng.UniformFloat() - 1) * 12, (2 * rng.UniformFloat() - 1) * 8, plain.FilmZ());
    const Vec3d d = Normalize(Vec3d((2 * rng.UniformFloat() - 1) * 10, (2 * rng.UniformFloat() - 1) * 10, 0) - o);
    const TraceResult a = TraceFromFilm(zoned, {o, d}, 550), b = TraceFromFilm(plain, {o, d}, 550);
    ASSERT_EQ(bool(a.ray), bool(b.ray)) << i;
    if (a.ray) {
      EXPECT_LT(Length(a.ray->d - b.ray->d), 1e-12) << i;
    }
  }
}

LensSystem FresnelLens() {
  return AtParaxialInfinityFocus(LoadLens("fresnel.50mm", GlassCatalog::Default()), kLambdad);
}

TEST(FresnelZones, ShippedLensFocusesWhereItsProfileDoes) {
  const LensSystem lens = FresnelLens();
  // The profile's slopes were fitted for a point focus 50 mm behind the back plane; the facets'
  // own heights (up to 0.3 mm) move the best focus a little toward the lens.
  EXPECT_NEAR(ComputeParaxial(lens.prescription(), kLambdad).efl, 50, 1e-3);
  const double back = RealBackFocus(lens, kLambdad);
  EXPECT_NEAR(back, 50, 0.2);
  // The lens is as thin as its plate: 2 mm from the stop to the back.
  EXPECT_NEAR(lens.prescription().TotalTrack(), 2.0, 1e-12);
}

TEST(FresnelZones, BatchTracerFollowsTheExactOne) {
  const test::BatchAgreement a = test::CompareTracers(FresnelLens(), 4000, 14, -100, 6, 3);
  test::ExpectAgreement(a, 400, 8, 5e-3);  // zone edges and rims grazed in single precision
}

TEST(FresnelZones, PupilBoundsHoldAllTheLight) {
  SKIP_UNDER_SANITIZERS("FresnelZones.BatchTracerFollowsTheExactOne");
  const LensSystem lens = FresnelLens();
  const PupilBounds bounds(lens, std::hypot(18.0, 12.0));
  PCG32 rng(6, 6);
  const test::PassRate pass = test::CameraPassRate(lens, bounds, 20000, rng, [](PCG32& g) {
    return Vec2d((2 * g.UniformFloat() - 1) * 18, (2 * g.UniformFloat() - 1) * 12);
  }, kLambdad);
  EXPECT_GE(pass.Rate(), 0.9);
  // Off the axis the risers cut thin rings out of the beam (rays that enter a zone's air pocket
  // near its riser); the bound holds what passes.
  for (Vec2d film : {Vec2d(0, 0), Vec2d(9.1, -4.4), Vec2d(17.5, 11.6)}) {
    const test::AreaEstimates a = test::PassingArea(lens, bounds, film, 25, 30000, rng, kLambdad);
    ASSERT_TRUE(a.has_bound);
    EXPECT_NEAR(a.bound, a.brute, 4 * a.se) << film.x << ", " << film.y;
  }
}

TEST(FresnelZones, ReaderChecksTheZones) {
  const std::string head = "stop 1 air 10\nsurface inf 2 n=1.49 11\n";
  const LensPrescription ok = Parse(head + "surface -25 50 air 11 zones=0.5 k=-2.2\n");
  ASSERT_TRUE(ok.surfaces[2].fresnel);
  EXPECT_DOUBLE_EQ(ok.surfaces[2].fresnel->pitch(), 0.5);
  // Scaled: the zones scale with the lens.
  EXPECT_DOUBLE_EQ(ok.Scaled(2).surfaces[2].fresnel->pitch(), 1.0);
  auto error = [&](const std::string& options) { return ParseError(head + "surface -25 50 air 11 " + options + "\n"); };
  EXPECT_NE(error("zones=0").find("test.lens:3: zones=0: the zones' radial width (mm) must be positive"), std::string::npos);
  EXPECT_NE(error("zones=1e-5").find("at most 100000"), std::string::npos);
  EXPECT_NE(error("zones=0.5 rx=30").find("no rx="), std::string::npos);
  EXPECT_NE(ParseError(head + "surface inf 50 air 11 zones=0.5\n").find("zones= on a plane"), std::string::npos);
}

}  // namespace
}  // namespace objektiv
