// The compiled path (optics/compiled_sequence.h) against TraceSequence: every ghost path and
// the direct path of lenses with bare, coated, aspheric and absorbing surfaces and a bladed
// stop, for rays over the whole front element, oblique ones included; and what it refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <tuple>

#include "base/rng.h"
#include "optics/coating_library.h"
#include "optics/coating_tables.h"
#include "optics/compiled_sequence.h"
#include "optics/ghosts.h"
#include "optics/lens_file.h"
#include "optics/lens_setup.h"

namespace objektiv {
namespace {

LensSystem Set(const std::string& name, double fnumber, int blades) {
  return SetUpLens(LoadLens(name, GlassCatalog::Default()), {fnumber, 0, blades ? StopShape::Iris(blades, 0.1, 0) : StopShape()},
                   {INFINITY, FocusRequest::From::kFilm, false})
      .lens;
}

void ExpectSameAsTraceSequence(const LensSystem& lens, std::span<const SurfaceVisit> path, double lambda, PCG32& rng,
                               int& alive) {
  const std::optional<CompiledSequence> compiled = CompiledSequence::Compile(lens, path, lambda);
  ASSERT_TRUE(compiled);
  const double reach = lens.surface(0).semi_diameter * 1.1, z = lens.VertexZ(0) - 5;
  for (int k = 0; k < 200; ++k) {
    const double angle = 0.4 * rng.UniformFloat();  // up to 23 degrees off the axis
    const Vec3d o(reach * (2 * rng.UniformFloat() - 1), reach * (2 * rng.UniformFloat() - 1), z);
    const Vec3d d = Normalize(Vec3d(std::sin(angle), 0.3 * std::sin(angle), std::cos(angle)));
    std::vector<Vec3d> points, stop_points;
    const TraceResult want = TraceSequence(lens, {o, d}, lambda, path, &points);
    const CompiledSequence::Result got = compiled->Trace({o, d}, &stop_points);
    ASSERT_EQ(got.alive, want.ray.has_value()) << o.x << " " << o.y << " " << angle;
    if (!got.alive) continue;
    ++alive;
    EXPECT_NEAR(got.ray.o.x, want.ray->o.x, 1e-11);
    EXPECT_NEAR(got.ray.o.y, want.ray->o.y, 1e-11);
    EXPECT_NEAR(got.ray.o.z, want.ray->o.z, 1e-11);
    EXPECT_NEAR(got.ray.d.x, want.ray->d.x, 1e-13);
    EXPECT_NEAR(got.ray.d.y, want.ray->d.y, 1e-13);
    EXPECT_NEAR(got.surface_transmittance, want.surface_transmittance, 1e-13 * want.surface_transmittance);
    EXPECT_NEAR(got.internal_transmittance, want.internal_transmittance, 1e-13);
    std::vector<Vec3d> want_stop;
    for (size_t i = 0; i < path.size(); ++i)
      if (path[i].surface == lens.StopIndex()) want_stop.push_back(points[i]);
    ASSERT_EQ(stop_points.size(), want_stop.size());
    for (size_t i = 0; i < want_stop.size(); ++i) EXPECT_NEAR(Length(stop_points[i] - want_stop[i]), 0, 1e-11);
  }
}

TEST(CompiledSequence, TracesEveryPathAsTraceSequence) {
  PCG32 rng(7, 11);
  // Bare (the double Gauss), coated and absorbing (the Tessar's catalog glasses, MgF2 by
  // default), an even asphere, a bladed stop.
  for (const auto& [name, fnumber, blades] :
       {std::tuple{"dgauss.50mm", 2.8, 6}, std::tuple{"tessar.brendel.100mm", 0.0, 5}, std::tuple{"asphere.50mm", 0.0, 0}}) {
    SCOPED_TRACE(name);
    const LensSystem lens = Set(name, fnumber, blades);
    int alive = 0, paths = 0;
    for (double lambda : {450.0, 587.6}) {
      for (const Ghost& g : TwoReflectionGhosts(lens)) {
        ExpectSameAsTraceSequence(lens, GhostPath(lens, g), lambda, rng, alive);
        ++paths;
      }
      std::vector<SurfaceVisit> direct;
      for (int i = 0; i < lens.SurfaceCount(); ++i) direct.push_back({i, false, true});
      ExpectSameAsTraceSequence(lens, direct, lambda, rng, alive);
    }
    EXPECT_GT(alive, 20 * paths) << "too few rays got through to compare";
  }
}

TEST(CompiledSequence, RefusesWhatItDoesNotTrace) {
  for (const char* name : {"anamorphic.250mm", "fresnel.50mm", "grin.50mm", "catadioptric.1000mm"}) {
    const LensSystem lens = Set(name, 0, 0);
    std::vector<SurfaceVisit> direct;
    for (int i = 0; i < lens.SurfaceCount(); ++i) direct.push_back({i, false, true});
    EXPECT_FALSE(CompiledSequence::Compile(lens, direct, 550)) << name;
  }
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

// The coating tables against the thin-film stacks they tabulate: every coated surface of the
// multi-coated and the MgF2-coated double Gauss, both directions, at three wavelengths, over
// every angle of incidence.
TEST(CoatingTables, FollowTheStacksWithin1e4) {
  for (const char* coating : {"multi", "MgF2"}) {
    LensPrescription p = LoadLens("dgauss.50mm", GlassCatalog::Default());
    Recoat(p, *FindBuiltInCoating(coating));
    const LensSystem lens = SetUpLens(std::move(p), {}, {INFINITY, FocusRequest::From::kFilm, false}).lens;
    const std::vector<double> bands = {446.7, 580, 713.3};
    const CoatingTables tables(lens, bands);
    int coated = 0;
    double worst = 0;
    for (int i = 0; i < lens.SurfaceCount(); ++i) {
      EXPECT_EQ(tables.Has(i), lens.Coated(i) != nullptr);
      if (!tables.Has(i)) continue;
      ++coated;
      for (bool toward_film : {true, false})
        for (int b = 0; b < 3; ++b)
          for (double cos_i = 0.0005; cos_i <= 1; cos_i += 0.00731)
            worst = std::max(worst, std::abs(tables.Reflectance(i, toward_film, b, cos_i) -
                                             lens.SurfaceReflectance(i, bands[b], cos_i, toward_film)));
    }
    EXPECT_EQ(coated, 8) << coating;  // the air-glass surfaces (two of the ten are cemented)
    EXPECT_LT(worst, 1e-4) << coating;
  }
}

// The tables keep their own coated interfaces: they answer as the stacks do after the lens
// they were made for is gone, they fit another set-up of the same lens (another focus and
// f-number) and another loading of its coating (an equal stack), and Shared gives them back for
// it; another coating or other wavelengths get other tables.
TEST(CoatingTables, OutliveTheirLensAndServeItsOtherSetUps) {
  const std::vector<double> wavelengths = {421, 555, 689};
  auto set_up = [](const char* coating, double fnumber, double focus_mm) {
    LensPrescription p = LoadLens("dgauss.50mm", GlassCatalog::Default());
    Recoat(p, *FindBuiltInCoating(coating));  // a new Coating object each time
    return SetUpLens(std::move(p), {fnumber, 0, StopShape()}, {focus_mm, FocusRequest::From::kFilm, false}).lens;
  };
  std::shared_ptr<const CoatingTables> shared;
  {
    const LensSystem far = set_up("multi", 2.8, INFINITY);
    shared = CoatingTables::Shared(far, wavelengths);
    EXPECT_EQ(CoatingTables::Shared(far, wavelengths), shared);
  }
  const LensSystem near = set_up("multi", 8, 1500);
  EXPECT_TRUE(shared->Fits(near, wavelengths));
  EXPECT_EQ(CoatingTables::Shared(near, wavelengths), shared);
  // Every coated surface, both ways, at every angle (the stacks' kink where total internal
  // reflection begins included: answered by the kept interfaces, not the lens gone).
  double worst = 0;
  for (int i = 0; i < near.SurfaceCount(); ++i)
    if (shared->Has(i))
      for (bool toward_film : {true, false})
        for (int b = 0; b < 3; ++b)
          for (double cos_i = 0.0003; cos_i <= 1; cos_i += 0.00173)
            worst = std::max(worst, std::abs(shared->Reflectance(i, toward_film, b, cos_i) -
                                             near.SurfaceReflectance(i, wavelengths[size_t(b)], cos_i, toward_film)));
  EXPECT_LT(worst, 1e-4);
  const LensSystem other = set_up("MgF2", 2.8, INFINITY);
  EXPECT_FALSE(shared->Fits(other, wavelengths));
  EXPECT_NE(CoatingTables::Shared(other, wavelengths), shared);
  EXPECT_FALSE(shared->Fits(near, std::vector<double>{421, 555}));
  EXPECT_FALSE(shared->Fits(near, std::vector<double>{421, 555, 690}));
}

}  // namespace
}  // namespace objektiv
