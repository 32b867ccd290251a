// Ghosts: the two-reflection paths, their bundles' irradiance against light tracing, and
// their brightness against the surfaces' reflectances.
#include <gtest/gtest.h>

#include <cmath>

#include "base/rng.h"
#include "optics/coating_library.h"
#include "optics/ghosts.h"
#include "optics/lens_file.h"
#include "optics/lens_setup.h"

namespace objektiv {
namespace {

LensSystem Set(LensPrescription lens, double fnumber) {
  return SetUpLens(std::move(lens), {fnumber, 0, {}}, {INFINITY, FocusRequest::From::kFilm, false}).lens;
}

TEST(Ghosts, EveryPairOfReflectingSurfaces) {
  const LensSystem lens = AtParaxialInfinityFocus(LoadLens("dgauss.50mm", GlassCatalog::Default()));
  const std::vector<Ghost> ghosts = TwoReflectionGhosts(lens);
  // 11 rows: the stop in air, and 10 surfaces (2 of them cemented) that each change the index.
  EXPECT_EQ(lens.SurfaceCount(), 11);
  EXPECT_EQ(ghosts.size(), 10u * 9 / 2);
  for (const Ghost& g : ghosts) {
    EXPECT_GT(g.first, g.second);
    EXPECT_FALSE(lens.surface(g.first).is_stop);
    EXPECT_FALSE(lens.surface(g.second).is_stop);
    const std::vector<SurfaceVisit> path = GhostPath(lens, g);
    EXPECT_EQ(int(path.size()), lens.SurfaceCount() + 2 * (g.first - g.second));
    int reflections = 0;
    for (const SurfaceVisit& v : path) reflections += v.reflect;
    EXPECT_EQ(reflections, 2);
  }
}

TEST(Ghosts, GlassPlateGhostCarriesTwoReflections) {
  // A plate of index 1.5 at normal incidence: in (1 - R), reflected at the back (R) and the
  // front (R) inside, out (1 - R), with R = 0.04; it lands on the axis, travelling on.
  LensPrescription plate = ParseNativeLens("surface inf 10 n=1.5 10\nstop 5 air 10\nsurface inf 20 air 10\n", "p.lens",
                                           GlassCatalog::Default());
  // Surfaces: 0 (air to glass), the stop inside the glass... the plate's back is surface 2.
  const LensSystem lens(plate);
  const std::vector<Ghost> ghosts = TwoReflectionGhosts(lens);
  ASSERT_EQ(ghosts.size(), 1u);
  const std::vector<SurfaceVisit> path = GhostPath(lens, ghosts[0]);
  TraceResult r = TraceSequence(lens, {{0.5, 0, -1}, {0, 0, 1}}, 550, path);
  ASSERT_TRUE(r.ray);
  const double R = 0.04;
  EXPECT_NEAR(r.surface_transmittance, (1 - R) * R * R * (1 - R), 1e-15);
  EXPECT_NEAR(r.ray->o.x, 0.5, 1e-12);
  EXPECT_GT(r.ray->d.z, 0.999999);
}

TEST(Ghosts, BundleIrradianceMatchesLightTracing) {
  // The two estimators of the issue: the bundle's irradiance from its change of cross-section,
  // and rays shot at random over the front element, traced along the same path and binned.
  // On an 18 x 12 grid of 2 mm bins over the sensor, and in total, they agree within the light
  // tracer's noise.
  const LensSystem lens = Set(LoadLens("dgauss.50mm", GlassCatalog::Default()), 4);
  const PointSource source = PointSource::Distant(Normalize(Vec3d(-std::sin(0.2), 0.05, std::cos(0.2))));
  const double lambda = 550;
  FilmRaster bins{18, 12, -18, -12, 2, 2};
  for (const Ghost& g : {Ghost{2, 0}, Ghost{10, 9}, Ghost{8, 4}}) {
    std::vector<float> bundle(216, 0.f);
    Splat(GhostBundle(lens, g, source, lambda, 256), bins, 1, bundle.data());
    // Light tracing: N rays uniform over a square on the plane the bundles start from, wide
    // enough for all the light that gets in.
    const LensSurface& front = lens.surface(0);
    const double s = 2 * front.semi_diameter, start_z = std::min(0.0, front.Sag(front.semi_diameter)) - 1;
    const std::vector<SurfaceVisit> path = GhostPath(lens, g);
    PCG32 rng(7, uint64_t(g.first * 16 + g.second));
    const int n = 400000;
    std::vector<double> sum(216, 0), sum2(216, 0);
    double one_ray = 0;  // the most one ray adds to a bin: the light tracer's granularity
    const double cell_flux = 4 * s * s * source.direction.z / n;  // each ray's share of the irradiance 1 beam
    for (int i = 0; i < n; ++i) {
      const Vec3d o((2 * rng.UniformFloat() - 1) * s, (2 * rng.UniformFloat() - 1) * s, start_z);
      TraceResult r = TraceSequence(lens, {o, source.direction}, lambda, path);
      if (!r.ray || r.ray->d.z <= 0) continue;
      const double t = (lens.FilmZ() - r.ray->o.z) / r.ray->d.z;
      const double x = r.ray->o.x + t * r.ray->d.x, y = r.ray->o.y + t * r.ray->d.y;
      const int bx = int(std::floor((x + 18) / 2)), by = int(std::floor((y + 12) / 2));
      if (bx < 0 || by < 0 || bx >= 18 || by >= 12) continue;
      const double e = cell_flux * r.surface_transmittance * r.internal_transmittance / 4;  // irradiance in the bin
      sum[by * 18 + bx] += e;
      one_ray = std::max(one_ray, e);
      sum2[by * 18 + bx] += e * e;
    }
    double total_bundle = 0, total_traced = 0, total_variance = 0;
    int compared = 0;
    for (int b = 0; b < 216; ++b) {
      total_bundle += bundle[b];
      total_traced += sum[b];
      total_variance += sum2[b];
      if (sum[b] == 0 && bundle[b] == 0) continue;
      // The standard error of the bin's sum (each ray adds e or 0), and one ray's worth where
      // the bin got few.
      const double se = std::sqrt(sum2[b]);
      EXPECT_NEAR(bundle[b], sum[b], 4 * se + one_ray) << "ghost " << g.first << "/" << g.second << " bin " << b;
      ++compared;
    }
    EXPECT_GE(compared, 4) << g.first << "/" << g.second;
    // The totals over the sensor: within 4 standard errors of the light tracer's.
    EXPECT_NEAR(total_bundle, total_traced, 4 * std::sqrt(total_variance)) << g.first << "/" << g.second;
    EXPECT_LT(4 * std::sqrt(total_variance), 0.05 * total_traced);  // a test that can tell
  }
}

TEST(Ghosts, CoatingsDimGhostsByTheirReflectances) {
  // A narrow beam on the axis (f/22) meets every surface nearly square on: each ghost's flux,
  // coated over bare, is what the surfaces' reflectances at normal incidence predict (R_a R_b
  // and the other surfaces' 1 - R along its path), within 10% (the reflectance changes a
  // little over the beam's angles; a multi-layer stack near its minimum most).
  const LensPrescription bare = LoadLens("dgauss.50mm", GlassCatalog::Default());
  const PointSource axial = PointSource::Distant({0, 0, 1});
  for (const auto& [coating, wavelength] : {std::pair{"MgF2", 550.0}, std::pair{"multi", 450.0}, std::pair{"multi", 650.0}}) {
    // Plain copies: a structured binding cannot be captured by the lambdas below (clang).
    const char* name = coating;
    const double lambda = wavelength;
    LensPrescription coated_lens = bare;
    Recoat(coated_lens, *FindBuiltInCoating(name));
    const LensSystem b = Set(bare, 22), c = Set(coated_lens, 22);
    auto flux = [&](const std::vector<FilmTriangle>& ts) {
      double f = 0;
      for (const FilmTriangle& t : ts) f += t.flux;
      return f;
    };
    // The normal-incidence model: a path's transmittance is the product over its visits.
    auto model = [&](const LensSystem& lens, std::span<const SurfaceVisit> path) {
      double t = 1;
      for (const SurfaceVisit& v : path) {
        const double r = lens.SurfaceReflectance(v.surface, lambda, 1, v.toward_film);
        t *= v.reflect ? r : 1 - r;
      }
      return t;
    };
    std::vector<SurfaceVisit> direct;
    for (int i = 0; i < b.SurfaceCount(); ++i) direct.push_back({i, false, true});
    const double direct_ratio = flux(DirectBundle(c, axial, lambda)) / flux(DirectBundle(b, axial, lambda));
    EXPECT_NEAR(direct_ratio, model(c, direct) / model(b, direct), 0.01 * direct_ratio) << name;
    for (const Ghost& g : TwoReflectionGhosts(b)) {
      const double fb = flux(GhostBundle(b, g, axial, lambda, 24)), fc = flux(GhostBundle(c, g, axial, lambda, 24));
      if (fb == 0) continue;
      const std::vector<SurfaceVisit> path = GhostPath(b, g);
      const double predicted = model(c, path) / model(b, path);
      EXPECT_NEAR(fc / fb, predicted, 0.1 * predicted) << name << " " << lambda << " nm ghost " << g.first << "/" << g.second;
    }
  }
}

// Splatting gives each pixel the triangle's flux times the share of its area inside the
// pixel: against point sampling 256 x 256 points per pixel, for random triangles inside the
// image, across its edges (their parts outside pressed onto the edges), thin and tiny ones.
TEST(Ghosts, SplatGivesEachPixelItsShareOfTheTriangle) {
  const FilmRaster raster{24, 16, -1.2, -0.4, 0.1, 0.05};  // pixels of 0.1 x 0.05 mm
  PCG32 rng(11, 3);
  auto point = [&](double spread) {
    return Vec2d(raster.x0 + raster.w * (-spread + (raster.width + 2 * spread) * rng.UniformFloat()),
                 raster.y0 + raster.h * (-spread + (raster.height + 2 * spread) * rng.UniformFloat()));
  };
  for (int trial = 0; trial < 24; ++trial) {
    // Inside (spread 0) or reaching past the edges (spread 6 pixels); every fourth one thin.
    const double spread = trial % 2 ? 6 : 0;
    FilmTriangle t{point(spread), point(spread), point(spread), 1.0};
    if (trial % 4 == 3) t.c = t.a + (t.b - t.a) * 0.3 + Vec2d(raster.w * 0.05, 0);
    // Every third one with an irradiance varying across it.
    if (trial % 3 == 1) t.ea = 1, t.eb = 3, t.ec = 0.5;
    const double mean_e = (t.ea + t.eb + t.ec) / 3;
    if (t.Area() < 1e-4 * raster.w * raster.h) continue;
    std::vector<float> image(size_t(raster.width) * raster.height, 0.f);
    Splat(std::span(&t, 1), raster, 2.0, image.data());
    const int n = 256;
    for (int y = 0; y < raster.height; ++y)
      for (int x = 0; x < raster.width; ++x) {
        // The relative irradiance summed over the sample points inside the triangle.
        double inside = 0;
        const double twice = (t.b.x - t.a.x) * (t.c.y - t.a.y) - (t.b.y - t.a.y) * (t.c.x - t.a.x);
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i) {
            const Vec2d p(raster.x0 + raster.w * (x + (i + 0.5) / n), raster.y0 + raster.h * (y + (j + 0.5) / n));
            auto side = [&](Vec2d a, Vec2d b) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); };
            const double s0 = side(t.a, t.b), s1 = side(t.b, t.c), s2 = side(t.c, t.a);
            if (!((s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0))) continue;
            // Barycentric weights: each corner's from the opposite edge's side.
            inside += (s1 * t.ea + s2 * t.eb + s0 * t.ec) / twice / mean_e;
          }
        // Irradiance: the flux over the triangle's area times the mean relative irradiance
        // over the pixel (the points outside counting 0).
        const double expected = 2.0 * t.flux / t.Area() * inside / (n * n);
        // Point sampling errs by about the perimeter's share of a sample row: 4 / 256 of a
        // pixel, at the largest relative irradiance (3 / mean).
        EXPECT_NEAR(image[size_t(y) * raster.width + x], expected, 4.0 / n * 2.0 / t.Area() * std::max(t.eb, 1.0) / mean_e)
            << "trial " << trial << " pixel " << x << "," << y;
      }
  }
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

TEST(Ghosts, SplatTakesSliversWithFlatEdges) {
  // An edge whose height is a denormal (its slope overflows to infinity: a lamp on the axis
  // focuses ghosts into such slivers) wrote outside the coverage buffer: heap corruption, a
  // crash in the starburst scene with ghosts on. Its flux lands inside the image, all of it,
  // and nothing beyond the image changes.
  const FilmRaster raster{8, 8, 0, 0, 1, 1};
  for (const double dy : {1e-310, 1e-300, 1e-17, 0.0}) {
    std::vector<float> image(64 + 8, 0.f);  // 8 guard values after the image
    const FilmTriangle t{{0.5, 0.0}, {5.999999999999999, dy}, {3.0, 3.0}, 1.0};
    Splat(std::span(&t, 1), raster, 1, image.data());
    double total = 0;
    for (int i = 0; i < 64; ++i) {
      ASSERT_TRUE(std::isfinite(image[i])) << dy;
      total += image[i];
    }
    EXPECT_NEAR(total, 1.0, 1e-5) << dy;
    for (int i = 64; i < 72; ++i) EXPECT_EQ(image[i], 0.f) << dy;
  }
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

// A preview's region search (grid 8, narrowed by a second) finds every ghost's light as the
// full search (grid 32) does, and its bundles with one level of edge cells carry the same
// flux within 2%.
TEST(Ghosts, PreviewSearchAndEdgesKeepTheLight) {
  const LensSystem lens = Set(LoadLens("dgauss.50mm", GlassCatalog::Default()), 2.8);
  const PointSource source = PointSource::Distant({-std::sin(0.2), 0.05, std::cos(0.2)});
  int compared = 0;
  for (const Ghost& g : TwoReflectionGhosts(lens)) {
    const std::optional<BundleRegion> full = GhostRegion(lens, g, source, 550), preview = GhostRegion(lens, g, source, 550, 8);
    ASSERT_EQ(full.has_value(), preview.has_value()) << g.first << " " << g.second;
    if (!full) continue;
    BundleOptions o;
    o.grid = 32, o.region = &*full;
    double want = 0, got = 0;
    for (const FilmTriangle& t : GhostBundle(lens, g, source, 550, o)) want += t.flux;
    o.grid = 16, o.region = &*preview, o.edge_levels = 1;
    for (const FilmTriangle& t : GhostBundle(lens, g, source, 550, o)) got += t.flux;
    EXPECT_NEAR(got, want, 0.02 * want) << g.first << " " << g.second;
    ++compared;
  }
  EXPECT_GT(compared, 35);
}

// Taking a varying irradiance at pixel centres (a preview's splat) keeps each ghost's total
// and changes its pixels little.
TEST(Ghosts, SplatAtPixelCentresKeepsTheFlux) {
  const LensSystem lens = Set(LoadLens("dgauss.50mm", GlassCatalog::Default()), 2.8);
  const PointSource source = PointSource::Distant({-std::sin(0.17), 0, std::cos(0.17)});
  const FilmRaster raster{320, 240, -18, -13.5, 36.0 / 320, 27.0 / 240};
  const std::vector<Ghost> ghosts = TwoReflectionGhosts(lens);
  for (const Ghost& g : {ghosts[3], ghosts[17], ghosts[40]}) {
    const std::vector<FilmTriangle> bundle = GhostBundle(lens, g, source, 550, 16);
    std::vector<float> exact(size_t(320) * 240 * 3, 0.f), centres = exact;
    SplatColour(bundle, raster, Vec3d(1, 1, 1), exact.data());
    SplatColour(bundle, raster, Vec3d(1, 1, 1), centres.data(), true);
    double sum_exact = 0, sum_centres = 0, peak = 0, worst = 0;
    for (size_t i = 0; i < exact.size(); i += 3) sum_exact += exact[i], sum_centres += centres[i], peak = std::max<double>(peak, exact[i]);
    for (size_t i = 0; i < exact.size(); i += 3) worst = std::max<double>(worst, std::abs(centres[i] - exact[i]));
    EXPECT_GT(sum_exact, 0);
    EXPECT_NEAR(sum_centres, sum_exact, 0.01 * sum_exact) << g.first << " " << g.second;
    EXPECT_LT(worst, 0.1 * peak) << g.first << " " << g.second;
  }
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

// A preview's coarse splat of a large ghost whose irradiance rises little above its mean
// (FilmRaster at half the resolution, then upsampled into the full image) keeps its flux, and
// inside the ghost its irradiance within 12% of its level (the exact splat's 99th
// percentile; 2-11% here, where the preview's grid facets by more). Near its edges the edge
// becomes a ramp, and a focused core (a contrast above 4) would be blurred: such ghosts stay
// at full resolution (render/lens_flare.cpp). An odd width and height: the half raster's last
// column and row reach past the image.
TEST(Ghosts, HalfResolutionKeepsTheLightOfLargeSmoothGhosts) {
  const LensSystem lens = Set(LoadLens("dgauss.50mm", GlassCatalog::Default()), 2.8);
  const PointSource source = PointSource::Distant({-std::sin(0.17), 0, std::cos(0.17)});
  const int width = 321, height = 241;
  const FilmRaster raster{width, height, -18, -13.5, 36.0 / width, 27.0 / height};
  const FilmRaster half = HalfResolution(raster);
  ASSERT_EQ(half.width, 161);
  ASSERT_EQ(half.height, 121);
  int compared = 0, focused = 0;
  for (const Ghost& g : TwoReflectionGhosts(lens)) {
    const std::vector<FilmTriangle> bundle = GhostBundle(lens, g, source, 550, 16);
    std::vector<float> full(size_t(width) * height * 3, 0.f), coarse = full, at_half(size_t(half.width) * half.height * 3, 0.f);
    SplatColour(bundle, raster, Vec3d(1, 1, 1), full.data());
    SplatColour(bundle, half, Vec3d(1, 1, 1), at_half.data(), true);
    // Upsampled in two bands of rows, as RenderFlare does by bands.
    AddUpsampled(at_half.data(), width, height, 0, 100, coarse.data());
    AddUpsampled(at_half.data(), width, height, 100, height, coarse.data());
    std::vector<float> sorted;
    double sum_full = 0, sum_coarse = 0;
    for (size_t i = 0; i < full.size(); i += 3) {
      sum_full += full[i], sum_coarse += coarse[i];
      sorted.push_back(full[i]);
      EXPECT_EQ(coarse[i], coarse[i + 2]);
    }
    std::sort(sorted.begin(), sorted.end());
    if (sorted[sorted.size() - 64 * 64] <= 0.01 * sorted.back()) continue;  // lit over less than 64 x 64 pixels
    if (IrradianceContrast(bundle) > 4) {
      ++focused;
      continue;
    }
    ++compared;
    EXPECT_NEAR(sum_coarse, sum_full, 0.005 * sum_full) << g.first << " " << g.second;
    const double level = sorted[sorted.size() * 99 / 100];
    // Inside: 3 pixels or more from a pixel darker than 1% of the level, and from the image's edge.
    auto inside = [&](int x, int y) {
      if (x < 3 || y < 3 || x >= width - 3 || y >= height - 3) return false;
      for (int dy = -3; dy <= 3; ++dy)
        for (int dx = -3; dx <= 3; ++dx)
          if (full[(size_t(y + dy) * width + x + dx) * 3] < 0.01 * level) return false;
      return true;
    };
    double worst = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        if (inside(x, y)) {
          const size_t i = (size_t(y) * width + x) * 3;
          worst = std::max<double>(worst, std::abs(coarse[i] - full[i]));
        }
    EXPECT_LT(worst, 0.12 * level) << g.first << " " << g.second;
  }
  EXPECT_GT(compared, 30);
  EXPECT_GE(focused, 2);  // ghosts with a focused core, which half the resolution would blur
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

// A bundle's edge cells spread their light over the part of the cell the straight-edge model
// lights, placed on the film by their blocked corners followed past the openings: at a
// preview's grid (16, one level of edge cells, whose finest cells span pixels) their light
// made a bright dot each along every ghost's outline, up to 84 times the ghost's level (its
// 99th percentile; 1.12 now).
TEST(Ghosts, EdgeCellsLeaveNoBrightDotsAlongTheOutline) {
  const LensSystem lens = Set(LoadLens("dgauss.50mm", GlassCatalog::Default()), 2.8);
  const PointSource source = PointSource::Distant({-std::sin(0.17), 0, std::cos(0.17)});
  const int width = 320, height = 240;
  const FilmRaster raster{width, height, -18, -13.5, 36.0 / width, 27.0 / height};
  int compared = 0;
  for (const Ghost& g : TwoReflectionGhosts(lens)) {
    BundleOptions o;
    o.grid = 16, o.edge_levels = 1;
    const std::vector<FilmTriangle> bundle = GhostBundle(lens, g, source, 550, o);
    if (IrradianceContrast(bundle) > 4) continue;  // a focused core has its own peak
    std::vector<float> image(size_t(width) * height, 0.f);
    Splat(bundle, raster, 1, image.data());
    std::vector<float> lit;
    for (float v : image)
      if (v > 0) lit.push_back(v);
    if (lit.size() < 1000) continue;
    std::sort(lit.begin(), lit.end());
    const double level = lit[lit.size() * 99 / 100];
    EXPECT_LT(lit.back(), 2 * level) << g.first << " " << g.second;
    ++compared;
  }
  EXPECT_GT(compared, 20);
}

}  // namespace
}  // namespace objektiv
