#include "render/filter.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace objektiv {

void TabulatedFilter::Tabulate() {
  n_ = std::max(8, int(std::ceil(32 * r_)) * 2);
  std::vector<float> f(size_t(n_) * n_);
  for (int y = 0; y < n_; ++y)
    for (int x = 0; x < n_; ++x) {
      Vec2f p(-r_ + (x + 0.5f) * 2 * r_ / n_, -r_ + (y + 0.5f) * 2 * r_ / n_);
      f[size_t(y) * n_ + x] = Evaluate(p);
    }
  distribution_ = Distribution2D(f, n_, n_);
}

FilterSample TabulatedFilter::Sample(Vec2f u) const {
  float pdf;
  Vec2f q = distribution_.Sample(u, &pdf);
  Vec2f p(-r_ + q.x * 2 * r_, -r_ + q.y * 2 * r_);
  // pdf over [0,1)^2 -> over the filter's square; weight = f / pdf.
  float pdf_p = pdf / (4 * r_ * r_);
  return {p, pdf_p > 0 ? Evaluate(p) / pdf_p : 0.f};
}

GaussianFilter::GaussianFilter(float stddev) : TabulatedFilter(4 * stddev), sigma_(stddev) { Tabulate(); }

float GaussianFilter::G(float x) const {
  float alpha = -1 / (2 * sigma_ * sigma_);
  return std::max(0.f, std::exp(alpha * x * x) - std::exp(alpha * r_ * r_));
}

float GaussianFilter::Evaluate(Vec2f p) const { return G(p.x) * G(p.y); }

// Separable: the square of the 1D integral over [-r, r] of the Gaussian less its value at r.
float GaussianFilter::Integral() const {
  double s = sigma_, r = r_;
  double g = s * std::sqrt(2 * std::numbers::pi) * std::erf(r / (s * std::sqrt(2.0))) - 2 * r * std::exp(-r * r / (2 * s * s));
  return float(g * g);
}

BlackmanHarrisFilter::BlackmanHarrisFilter(float radius) : TabulatedFilter(radius) { Tabulate(); }

float BlackmanHarrisFilter::W(float x) const {
  if (std::abs(x) > r_) return 0;
  float t = 2 * kPi * (x / (2 * r_) + 0.5f);
  return 0.35875f - 0.48829f * std::cos(t) + 0.14128f * std::cos(2 * t) - 0.01168f * std::cos(3 * t);
}

float BlackmanHarrisFilter::Evaluate(Vec2f p) const { return W(p.x) * W(p.y); }

// Separable; over [-r, r] the cosines run whole periods and integrate to zero.
float BlackmanHarrisFilter::Integral() const {
  float w = 0.35875f * 2 * r_;
  return w * w;
}

}  // namespace objektiv
