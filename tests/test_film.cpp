// The film: the filters' integrals that normalise splats.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>

#include "render_helpers.h"

namespace objektiv {
namespace {

// Integral of each filter's Evaluate by the midpoint rule on a fine grid.
TEST(Filter, IntegralMatchesTheIntegralOfEvaluate) {
  const BoxFilter box_half(0.5f), box_wide(1.5f);
  const TentFilter tent(1.f), tent_wide(2.f);
  const GaussianFilter gauss(0.5f), gauss_wide(0.8f);
  const BlackmanHarrisFilter bh(1.5f), bh_wide(2.f);
  for (const Filter* f : std::initializer_list<const Filter*>{&box_half, &box_wide, &tent, &tent_wide, &gauss,
                                                                &gauss_wide, &bh, &bh_wide}) {
    const int n = 1000;
    const double r = f->Radius(), h = 2 * r / n;
    double sum = 0;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) sum += f->Evaluate(Vec2f(float(-r + (x + 0.5) * h), float(-r + (y + 0.5) * h)));
    EXPECT_NEAR(f->Integral(), sum * h * h, 1e-5 * sum * h * h) << "radius " << r;
  }
}

}  // namespace
}  // namespace objektiv
