// Decentre and tilt tolerances (optics/element_tolerances.h): the elements found, each moved as
// a rigid body within its tolerances, the draws' distribution (uniform over the decentre's disc,
// tilt angles uniform), the seed, and the reader's checks.
#include <gtest/gtest.h>

#include <cmath>

#include "base/error.h"
#include "lens_text.h"
#include "optics/element_tolerances.h"
#include "optics/lens_file.h"

namespace objektiv {
namespace {

LensPrescription Parse(const std::string& text) { return test::ParseLensText(text); }
std::string ParseError(const std::string& text) { return test::LensTextError(text); }

const char* kTessar = R"(surface  42.970    9.8        n=1.691    19.2
surface  -115.33   2.1        n=1.5487   19.2
surface  306.840   4.16       air        19.2
stop               4.0        air        15.0
surface  -59.060   1.870      n=1.6398   17.3
surface  40.930    10.640     air        17.3
surface  183.920   7.050      n=1.691    16.5
surface  -48.910   79.831     air        16.5
)";

TEST(ElementTolerances, ElementsAreRunsOfGlassBetweenAirGaps) {
  const LensPrescription tessar = Parse(kTessar);
  const auto elements = LensElements(tessar);
  ASSERT_EQ(elements.size(), 3u);
  EXPECT_EQ(elements[0], std::make_pair(size_t(0), size_t(2)));  // the cemented front pair
  EXPECT_EQ(elements[1], std::make_pair(size_t(4), size_t(5)));
  EXPECT_EQ(elements[2], std::make_pair(size_t(6), size_t(7)));
  // A stop inside a cemented group belongs to it.
  const LensPrescription in_glass = Parse("surface 50 3 n=1.5 10\nstop 3 n=1.5 8\nsurface -50 40 air 10\n");
  ASSERT_EQ(LensElements(in_glass).size(), 1u);
  EXPECT_EQ(LensElements(in_glass)[0], std::make_pair(size_t(0), size_t(2)));
}

// Lens-space vertex of surface k and its axis.
Vec3d Vertex(const LensPrescription& lens, size_t k) {
  double z = 0;
  for (size_t i = 0; i < k; ++i) z += lens.surfaces[i].thickness;
  const Vec3d on_axis(0, 0, z);
  return lens.surfaces[k].placement ? on_axis + lens.surfaces[k].placement->offset : on_axis;
}
Vec3d Axis(const LensPrescription& lens, size_t k) {
  return lens.surfaces[k].placement ? lens.surfaces[k].placement->ez : Vec3d(0, 0, 1);
}

TEST(ElementTolerances, EachElementMovesRigidlyWithinItsTolerances) {
  const LensPrescription tessar = Parse(kTessar);
  const ElementTolerances tol{0.05, 0.2, 0};
  double r2_sum = 0, angle_sum = 0;
  int count = 0;
  for (uint64_t seed = 0; seed < 1000; ++seed) {
    ElementTolerances t = tol;
    t.seed = seed;
    const LensPrescription built = WithToleranceSample(tessar, t);
    EXPECT_FALSE(built.surfaces[3].placement) << "the stop in air stays";
    for (const auto& [first, last] : LensElements(tessar)) {
      // Rigid: the vertices keep their distances along the element's turned axis, every face the same axis.
      const Vec3d axis = Axis(built, first), v0 = Vertex(built, first);
      for (size_t k = first; k <= last; ++k) {
        EXPECT_LT(Length(Axis(built, k) - axis), 1e-12);
        const double along = Vertex(tessar, k).z - Vertex(tessar, first).z;
        EXPECT_LT(Length(Vertex(built, k) - (v0 + axis * along)), 1e-12) << seed << " surface " << k;
      }
      // The first vertex moves across the axis only (the turn is about it).
      const Vec3d shift = v0 - Vertex(tessar, first);
      EXPECT_NEAR(shift.z, 0, 1e-12);
      const double r = std::hypot(shift.x, shift.y), angle = std::acos(std::min(axis.z, 1.0)) * 180 / M_PI;
      EXPECT_LE(r, 0.05 + 1e-12);
      EXPECT_LE(angle, 0.2 + 1e-9);
      r2_sum += r * r, angle_sum += angle, ++count;
    }
  }
  // Uniform over the disc: E[r^2] = R^2 / 2; tilt angles uniform: E = 0.1 degree.
  const double n = count;
  EXPECT_NEAR(r2_sum / n, 0.05 * 0.05 / 2, 4 * 0.05 * 0.05 / std::sqrt(12 * n));
  EXPECT_NEAR(angle_sum / n, 0.1, 4 * 0.2 / std::sqrt(12 * n));
}

TEST(ElementTolerances, TheSeedIsTheCopy) {
  const LensPrescription tessar = Parse(kTessar);
  auto first_shift = [&](uint64_t seed, double tilt) {
    const LensPrescription built = WithToleranceSample(tessar, {0.05, tilt, seed});
    return built.surfaces[0].placement->offset;
  };
  EXPECT_EQ(first_shift(7, 0.1).x, first_shift(7, 0.1).x);
  EXPECT_NE(first_shift(7, 0.1).x, first_shift(8, 0.1).x);
  // The decentre drawn does not depend on the tilt tolerance (four draws per element always).
  EXPECT_DOUBLE_EQ(first_shift(7, 0.0).x, first_shift(7, 0.3).x);
}

TEST(ElementTolerances, ReaderAppliesAndChecksThem) {
  const LensPrescription built = Parse(std::string("tolerance_decenter: 0.02\ntolerance_seed: 4\n") + kTessar);
  EXPECT_FALSE(built.Centred());
  EXPECT_EQ(built.surfaces[0].placement->offset.x, WithToleranceSample(Parse(kTessar), {0.02, 0, 4}).surfaces[0].placement->offset.x);
  EXPECT_TRUE(Parse(std::string("tolerance_tilt: 0\n") + kTessar).Centred());  // none
  EXPECT_NE(ParseError(std::string("tolerance_decenter: -1\n") + kTessar).find("test.lens:1: tolerance_decenter -1: from 0 to 10"),
            std::string::npos);
  EXPECT_NE(ParseError(std::string("tolerance_tilt: 45\n") + kTessar).find("from 0 to 10 (degrees)"), std::string::npos);
  EXPECT_NE(ParseError(std::string("tolerance_seed: 3\n") + kTessar).find("moves nothing"), std::string::npos);
  EXPECT_NE(ParseError(std::string("tolerance_seed: x\n") + kTessar).find("an integer"), std::string::npos);
  EXPECT_NE(ParseError("tolerance_tilt: 0.1\nsurface 50 5 n=1.5 10 rx=40\nstop 2 air 8\nsurface -50 40 air 10\n").find("toroids"),
            std::string::npos);
}

}  // namespace
}  // namespace objektiv
