// Chi-square goodness-of-fit of a direction sampler against its claimed density, over a
// grid of equal-solid-angle bins in (cos theta, phi) about the +x axis. Expected counts integrate the pdf
// numerically over each bin; bins with small expectation are pooled (as Mitsuba's tests do).
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "base/rng.h"
#include "base/vec.h"

namespace objektiv::test {

// Regularized upper incomplete gamma Q(a, x).
double GammaQ(double a, double x);

struct Chi2Result {
  double statistic = 0, p_value = 1;
  int dof = 0;
  double pdf_integral = 0;  // integral of the pdf over the sphere
  std::string Describe() const;
};

using DirectionSampler = std::function<std::optional<Vec3f>(PCG32&)>;
using DirectionPdf = std::function<double(const Vec3f&)>;

Chi2Result Chi2TestDirections(const DirectionSampler& sample, const DirectionPdf& pdf, int n_samples = 200000,
                              int theta_bins = 10, int phi_bins = 20);

// The same on the unit square for 2D warps: pdf over [lo, hi]^2.
using PointSampler = std::function<Vec2f(PCG32&)>;
using PointPdf = std::function<double(Vec2f)>;
Chi2Result Chi2TestPoints(const PointSampler& sample, const PointPdf& pdf, Vec2f lo, Vec2f hi, int n_samples = 200000,
                          int bins = 16);

}  // namespace objektiv::test
