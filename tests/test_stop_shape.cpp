// The stop's opening: containment, area, uniform sampling and symmetry of round stops, straight
// and curved irises, and irises cut by a polygon.
#include <gtest/gtest.h>

#include <cmath>

#include "base/rng.h"
#include "chi2.h"
#include "optics/stop_shape.h"

namespace objektiv {
namespace {

// The opening's area by counting a fine grid over the unit square.
double GridArea(const StopShape& s, int n = 1000) {
  int in = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) in += s.Contains(2.0 * (i + 0.5) / n - 1, 2.0 * (j + 0.5) / n - 1);
  return 4.0 * in / (double(n) * n);
}

TEST(StopShape, IrisAreasAreExact) {
  EXPECT_DOUBLE_EQ(StopShape().IrisArea(), M_PI);
  // A straight iris is the regular polygon: n/2 sin(2 pi / n).
  for (int n : {3, 5, 6, 9}) EXPECT_NEAR(StopShape::Iris(n, 0, 0.3).IrisArea(), 0.5 * n * std::sin(2 * M_PI / n), 1e-12);
  // Curved blades: polygon plus circular segments, between the polygon and the circle; the
  // grid count agrees to its resolution (a 1000^2 grid: ~1e-3 of the perimeter's cells).
  for (int n : {3, 5, 6, 9})
    for (double c : {0.0, 0.02, 0.3, 0.7, 0.999}) {
      StopShape s = StopShape::Iris(n, c, 0.3);
      EXPECT_NEAR(s.IrisArea(), GridArea(s), 2e-3) << n << " blades, curvature " << c;
      EXPECT_LE(s.IrisArea(), M_PI);
    }
  // Fully curved blades are the round stop.
  EXPECT_TRUE(StopShape::Iris(6, 1, 0).IsRound());
  EXPECT_TRUE(StopShape::Iris(2, 0, 0).IsRound());
}

TEST(StopShape, IrisSamplesAreUniform) {
  for (int n : {3, 6})
    for (double c : {0.0, 0.4}) {
      const StopShape s = StopShape::Iris(n, c, 0.5);
      auto r = test::Chi2TestPoints(
          [&](PCG32& g) {
            Vec2d p = s.SampleIris({g.UniformFloat(), g.UniformFloat()});
            return Vec2f(float(p.x), float(p.y));
          },
          [&](Vec2f p) { return s.Contains(p.x, p.y) ? 1 / s.IrisArea() : 0.0; }, {-1, -1}, {1, 1}, 1600000, 24);
      EXPECT_GT(r.p_value, 1e-3) << n << " blades, curvature " << c << ": " << r.Describe();
      EXPECT_NEAR(r.pdf_integral, 1, 2e-2);
    }
}

TEST(StopShape, SymmetryIsThatOfTheOpening) {
  PCG32 rng(3, 3);
  for (int n : {3, 5, 8}) {
    const double rotation = 0.7;
    const StopShape s = StopShape::Iris(n, 0.3, rotation);
    StopShape::Symmetry sym = s.symmetry();
    ASSERT_EQ(sym.order, n);
    ASSERT_TRUE(sym.mirror);
    int agree_turn = 0, agree_mirror = 0, agree_rotated = 0;
    const int count = 20000;
    for (int i = 0; i < count; ++i) {
      Vec2d p(2 * rng.UniformFloat() - 1, 2 * rng.UniformFloat() - 1);
      const double t = 2 * M_PI / n;
      Vec2d turned(std::cos(t) * p.x - std::sin(t) * p.y, std::sin(t) * p.x + std::cos(t) * p.y);
      // Mirror about the line at angle `axis`: reflect the angle.
      const double a = std::atan2(p.y, p.x), r = std::hypot(p.x, p.y), m = 2 * sym.axis - a;
      Vec2d mirrored(r * std::cos(m), r * std::sin(m));
      agree_turn += s.Contains(p.x, p.y) == s.Contains(turned.x, turned.y);
      agree_mirror += s.Contains(p.x, p.y) == s.Contains(mirrored.x, mirrored.y);
      // Turning the opening by 0.2 is turning the point by -0.2.
      const double b = a - 0.2;
      agree_rotated += s.Rotated(0.2).Contains(p.x, p.y) == s.Contains(r * std::cos(b), r * std::sin(b));
    }
    // Points within rounding of the boundary may disagree.
    EXPECT_GE(agree_turn, count - 2) << n;
    EXPECT_GE(agree_mirror, count - 2) << n;
    EXPECT_GE(agree_rotated, count - 2) << n;
  }
  EXPECT_EQ(StopShape().symmetry().order, 0);
}

TEST(StopShape, CutKeepsOnlyThePolygonAndBreaksTheSymmetry) {
  StopShape s = StopShape::Iris(6, 0, 0);
  // The right half of the stop (a square from x = 0 to beyond the circle).
  s.Cut(ConvexPolygon::HullOf({{0, -2}, {2, -2}, {2, 2}, {0, 2}}));
  EXPECT_TRUE(s.Contains(0.5, 0.1));
  EXPECT_FALSE(s.Contains(-0.5, 0.1));
  EXPECT_FALSE(s.Contains(0.99, 0.5));  // outside the hexagon
  EXPECT_EQ(s.symmetry().order, 1);
  EXPECT_FALSE(s.symmetry().mirror);
  EXPECT_NEAR(GridArea(s), 0.5 * StopShape::Iris(6, 0, 0).IrisArea(), 2e-3);
  // Turned by pi, the cut keeps the left half.
  EXPECT_TRUE(s.Rotated(M_PI).Contains(-0.5, 0.1));
  EXPECT_FALSE(s.Rotated(M_PI).Contains(0.5, 0.1));
}

}  // namespace
}  // namespace objektiv
