// The colour lattice (optics/colour_lattice.h): cubic between its nodes, so a colour that is
// quadratic in each coordinate of the start point comes back exactly anywhere (bilinear with two
// nodes a side); nodes without a colour take their nearest node's; the rectangle's outside and
// NaN take the edge's nodes; nothing below zero.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "base/rng.h"
#include "optics/colour_lattice.h"

namespace objektiv {
namespace {

// Positive over the rectangles below; quadratic in x and in y.
Vec3d Biquadratic(Vec2d p) {
  return Vec3d(30 + 2 * p.x + 3 * p.y + 4 * p.x * p.y + p.x * p.x * p.y * p.y, 2 + p.x * p.x,
               0.5 + 0.1 * p.y * p.y + 0.01 * p.x * p.y);
}
Vec3d Bilinear(Vec2d p) { return Vec3d(10 + 2 * p.x + 3 * p.y + 0.5 * p.x * p.y, 8 - p.x, 20 + p.x * p.y); }

TEST(ColourLattice, ReproducesQuadraticsBetweenItsNodes) {
  const Vec2d lo(-3, 1), hi(2, 4.5);
  int asked = 0;
  const ColourLattice lattice(lo, hi, 5, [&](Vec2d p) {
    ++asked;
    return std::optional<Vec3d>(Biquadratic(p));
  });
  EXPECT_EQ(asked, 25);
  ASSERT_FALSE(lattice.empty());
  PCG32 rng(7, 11);
  for (int k = 0; k < 1000; ++k) {
    const Vec2d p(lo.x + (hi.x - lo.x) * double(rng.UniformFloat()), lo.y + (hi.y - lo.y) * double(rng.UniformFloat()));
    const Vec3d got = lattice.At(p), want = Biquadratic(p);
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(got[c], want[c], 1e-9 * std::abs(want[c])) << p.x << " " << p.y;
  }
  // Outside: the nearest point of the rectangle's edge; NaN: the lowest node.
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(lattice.At(Vec2d(10, 2))[c], Biquadratic(Vec2d(hi.x, 2))[c], 1e-9);
    EXPECT_NEAR(lattice.At(Vec2d(-10, -10))[c], Biquadratic(lo)[c], 1e-9);
    EXPECT_NEAR(lattice.At(Vec2d(NAN, NAN))[c], Biquadratic(lo)[c], 1e-9);
  }
  // Two nodes a side (fewer are two): bilinear.
  for (int nodes : {1, 2}) {
    const ColourLattice two(lo, hi, nodes, [](Vec2d p) { return std::optional<Vec3d>(Bilinear(p)); });
    for (const Vec2d& p : {lo, hi, Vec2d(0.3, 2.2), Vec2d(-2.9, 4.1)})
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(two.At(p)[c], Bilinear(p)[c], 1e-9);
  }
}

// A colour that falls to none between nodes (a cubic would dip below zero there) stays at zero
// or above.
TEST(ColourLattice, NeverBelowZero) {
  const ColourLattice lattice(Vec2d(0, 0), Vec2d(4, 4), 5, [](Vec2d p) {
    return std::optional<Vec3d>(p.x == 2 ? Vec3d(1, 1, 1) : Vec3d(0.0));
  });
  double lowest = 1;
  for (double x = 0; x <= 4; x += 0.01) lowest = std::min(lowest, lattice.At(Vec2d(x, 1.3)).y);
  EXPECT_EQ(lowest, 0);
  EXPECT_NEAR(lattice.At(Vec2d(2, 3.7)).x, 1, 1e-12);
}

TEST(ColourLattice, NodesWithoutAColourTakeTheNearestNodes) {
  // Nodes at x = 0, 1, 2, 3 and y = 0..3; those with x >= 2 have none: they take the colour of
  // the node at x = 1 in their row.
  const ColourLattice lattice(Vec2d(0, 0), Vec2d(3, 3), 4, [](Vec2d p) {
    return p.x < 1.5 ? std::optional<Vec3d>(Vec3d(p.x, p.y, 1)) : std::nullopt;
  });
  for (int y = 0; y <= 3; ++y) {
    EXPECT_DOUBLE_EQ(lattice.At(Vec2d(3, y)).x, 1);
    EXPECT_DOUBLE_EQ(lattice.At(Vec2d(2, y)).y, y);
    EXPECT_DOUBLE_EQ(lattice.At(Vec2d(2.5, y)).x, 1);
  }
  EXPECT_TRUE(ColourLattice(Vec2d(0, 0), Vec2d(1, 1), 3, [](Vec2d) { return std::optional<Vec3d>(); }).empty());
  const ColourLattice uniform = ColourLattice::Uniform(Vec3d(0.25, 0.5, 2));
  EXPECT_EQ(uniform.At(Vec2d(-1e9, 7)).z, 2);
  EXPECT_EQ(uniform.At(Vec2d(NAN, 0)).y, 0.5);
}

}  // namespace
}  // namespace objektiv
