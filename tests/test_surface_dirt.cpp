// Dust and scratches (optics/surface_dirt.h): the grid lookup against a brute-force test of
// every particle and stroke, the share of the aperture drawn dust covers (1 - exp(-coverage)),
// seeds, the shadow a particle near the film casts (its darkening, the particle's area over the
// converging cone's footprint there, against the working f-number), the batch tracer against
// the exact one and the reader's checks.
#include <gtest/gtest.h>

#include <cmath>

#include "base/rng.h"
#include "batch_agreement.h"
#include "lens_text.h"
#include "optics/lens_system.h"
#include "optics/lens_tracer.h"
#include "optics/paraxial.h"
#include "optics/surface_dirt.h"

namespace objektiv {
namespace {

LensPrescription Parse(const std::string& text) { return test::ParseLensText(text); }
std::string ParseError(const std::string& text) { return test::LensTextError(text); }

TEST(SurfaceDirt, GridFindsEveryParticleAndStroke) {
  PCG32 rng(2, 7);
  std::vector<SurfaceDirt::Particle> particles;
  for (int k = 0; k < 300; ++k)
    particles.push_back({rng.UniformFloat() * 8.0 - 4, rng.UniformFloat() * 8.0 - 4, 0.005 + 0.07 * rng.UniformFloat()});
  std::vector<SurfaceDirt::Scratch> strokes;
  for (int k = 0; k < 20; ++k)
    strokes.push_back({rng.UniformFloat() * 8.0 - 4, rng.UniformFloat() * 8.0 - 4, rng.UniformFloat() * 8.0 - 4,
                       rng.UniformFloat() * 8.0 - 4, 0.02});
  const SurfaceDirt dirt(particles, strokes, 4);
  int blocked = 0;
  for (int k = 0; k < 50000; ++k) {
    const double x = rng.UniformFloat() * 8.4 - 4.2, y = rng.UniformFloat() * 8.4 - 4.2;
    bool inside = false;
    for (const auto& p : particles) inside |= std::hypot(x - p.x, y - p.y) <= p.r;
    for (const auto& s : strokes) {
      const double ex = s.x1 - s.x0, ey = s.y1 - s.y0;
      const double t = std::clamp(((x - s.x0) * ex + (y - s.y0) * ey) / (ex * ex + ey * ey), 0.0, 1.0);
      inside |= std::hypot(x - s.x0 - t * ex, y - s.y0 - t * ey) <= s.half_width;
    }
    ASSERT_EQ(dirt.Transmittance(x, y), inside ? 0.0 : 1.0) << x << ", " << y;
    blocked += inside;
  }
  EXPECT_GT(blocked, 250);  // the test met the dirt often
}

TEST(SurfaceDirt, DrawnDustCoversItsShare) {
  for (double coverage : {0.003, 0.05, 0.3}) {
    double blocked = 0;
    const int seeds = 5, points = 100000;
    PCG32 rng(9, 1);
    for (int seed = 1; seed <= seeds; ++seed) {
      const SurfaceDirt dirt(coverage, 0, uint64_t(seed), 6);
      for (int k = 0; k < points; ++k) {
        const double r = 6 * std::sqrt(rng.UniformFloat()), phi = 2 * M_PI * rng.UniformFloat();
        blocked += 1 - dirt.Transmittance(r * std::cos(phi), r * std::sin(phi));
      }
    }
    EXPECT_NEAR(blocked / (seeds * points), 1 - std::exp(-coverage), 0.1 * (1 - std::exp(-coverage))) << coverage;
  }
  // The clear share the grids use is the drawn dust's.
  const SurfaceDirt mean(0.05, 0, 9, 6);
  EXPECT_NEAR(mean.MeanTransmittance(), std::exp(-0.05), 0.1 * 0.05);
  // A seed is a pattern.
  const SurfaceDirt a(0.05, 10, 3, 6), b(0.05, 10, 3, 6), c(0.05, 10, 4, 6);
  int same = 0, differ = 0;
  PCG32 rng(1, 1);
  for (int k = 0; k < 50000; ++k) {
    const double x = rng.UniformFloat() * 12 - 6, y = rng.UniformFloat() * 12 - 6;
    same += a.Transmittance(x, y) == b.Transmittance(x, y);
    differ += a.Transmittance(x, y) != c.Transmittance(x, y);
  }
  EXPECT_EQ(same, 50000);
  EXPECT_GT(differ, 1000);
  EXPECT_EQ(a.scratch_count(), 10);
}

// A particle of radius a on a plane d mm in front of the film, where the cone converging on a
// film point has the footprint radius rho = d / (2 N_w) (N_w the working f-number: the image
// side's 1 / (2 sin u')): the point directly behind it loses (a / rho)^2 of its light, a point
// farther off than rho + a none.
TEST(SurfaceDirt, ParticleNearTheFilmCastsItsShadow) {
  // The singlet at f/2 stopped to f/8, a clean plane 3 mm before the film carrying the dust.
  LensPrescription rx = Parse("stop 0.5 air 3.125\nsurface 25.84 6.0 n=1.5168 13.5\nsurface inf 43.0443 air 13.5\n"
                              "surface inf 3 air 13.5\n");
  const double a = 0.04, d = 3;
  rx.surfaces[3].dirt = std::make_shared<const SurfaceDirt>(std::vector<SurfaceDirt::Particle>{{0, 0, a}},
                                                            std::vector<SurfaceDirt::Scratch>{}, 13.5);
  const LensSystem lens(rx);
  // Light reaching the film point from a uniform sampling of the stop (object side), with and
  // without the particle: rays aimed from a distant axial point through the stop.
  const ParaxialData p = ComputeParaxial(rx, 587.56);
  const double rho = d / (2 * p.efl / p.entrance_pupil_diameter);
  double through = 0, clean = 0;
  PCG32 rng(4, 4);
  for (int k = 0; k < 200000; ++k) {
    const double r = 3.12 * std::sqrt(rng.UniformFloat()), phi = 2 * M_PI * rng.UniformFloat();
    const TraceResult t = TraceFromObject(lens, {Vec3d(r * std::cos(phi), r * std::sin(phi), -0.001), Vec3d(0, 0, 1)}, 587.56);
    if (!t.ray) continue;
    clean += 1;
    through += t.dirt > 0 ? 1 : 0;
  }
  EXPECT_NEAR(1 - through / clean, (a / rho) * (a / rho), 0.08 * (a / rho) * (a / rho));
  // Off the shadow: a beam from a field angle whose footprint misses the particle loses nothing.
  const double angle = std::atan((rho + a + 0.2) / (p.efl - d)) ;
  int lost = 0;
  for (int k = 0; k < 5000; ++k) {
    const double r = 3.0 * std::sqrt(rng.UniformFloat()), phi = 2 * M_PI * rng.UniformFloat();
    const Vec3d dir = Normalize(Vec3d(std::tan(angle), 0, 1));
    const TraceResult t = TraceFromObject(lens, {Vec3d(r * std::cos(phi), r * std::sin(phi), 0) - dir * 0.001, dir}, 587.56);
    if (t.ray) lost += t.dirt == 0;
  }
  EXPECT_EQ(lost, 0);
}

TEST(SurfaceDirt, BatchTracerFollowsTheExactOne) {
  const LensSystem lens(Parse("stop 2 air 7\nsurface 25 5 N-BK7 8 dust=0.2 scratches=30\n"
                              "surface -60 1.5 N-SF5 8 decenter=0.2,0\nsurface -200 38 air 8 dust=0.1 dirt_seed=4\n"));
  const test::BatchAgreement a = test::CompareTracers(lens, 4000, 8, -60, 8, 1);
  test::ExpectAgreement(a, 800, 3, 1e-4);  // the transmittances, 0 where dust is, agree ray by ray
}

TEST(SurfaceDirt, ReaderChecksTheDirt) {
  const std::string head = "stop 1 air 5\n";
  auto error = [&](const std::string& options) { return ParseError(head + "surface 40 5 n=1.6 6 " + options + "\nsurface -40 30 air 6\n"); };
  EXPECT_EQ(error("dust=0.01 scratches=3 dirt_seed=7"), "accepted");
  const LensPrescription ok = Parse(head + "surface 40 5 n=1.6 6 dust=0.01\nsurface -40 30 air 6 scratches=2\n");
  ASSERT_TRUE(ok.surfaces[1].dirt && ok.surfaces[2].dirt);
  EXPECT_EQ(ok.surfaces[1].dirt->seed(), 2u);  // the row's number by default
  EXPECT_EQ(ok.surfaces[2].dirt->scratch_count(), 2);
  EXPECT_NE(error("dust=0").find("test.lens:2: dust=0: the share"), std::string::npos);
  EXPECT_NE(error("dust=0.6").find("at most 0.5"), std::string::npos);
  EXPECT_NE(error("scratches=0").find("a count from 1 to 1000"), std::string::npos);
  EXPECT_NE(error("dirt_seed=3").find("without dust= or scratches="), std::string::npos);
  EXPECT_NE(ParseError(head + "surface 40 5 n=1.6 6000 dust=0.5\nsurface -40000 30 air 6000\n").find("particles; at most"),
            std::string::npos);
  EXPECT_NE(ParseError("stop 1 air 5 dust=0.1\nsurface 40 30 n=1.6 6\nsurface -40 30 air 6\n").find("the stop takes no options"),
            std::string::npos);
}

}  // namespace
}  // namespace objektiv
