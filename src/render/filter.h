// Pixel reconstruction filters, importance-sampled (pbrt-v4 style): each camera sample is
// placed by the filter's own distribution and weighted by f/pdf, so no sample is shared
// between pixels and every pixel is independent (deterministic with any tiling).
#pragma once
#include <memory>
#include <string>

#include "base/sampling.h"

namespace objektiv {

struct FilterSample {
  Vec2f offset;  // from the pixel centre, in pixels
  float weight;
};

class Filter {
 public:
  virtual ~Filter() = default;
  virtual float Evaluate(Vec2f p) const = 0;
  virtual FilterSample Sample(Vec2f u) const = 0;
  virtual float Radius() const = 0;
  // The integral of Evaluate over the plane (splats are weighted by Evaluate / Integral).
  virtual float Integral() const = 0;
};

class BoxFilter final : public Filter {
 public:
  explicit BoxFilter(float radius = 0.5f) : r_(radius) {}
  float Evaluate(Vec2f p) const override { return (std::abs(p.x) <= r_ && std::abs(p.y) <= r_) ? 1.f : 0.f; }
  FilterSample Sample(Vec2f u) const override { return {{(2 * u.x - 1) * r_, (2 * u.y - 1) * r_}, 1.f}; }
  float Radius() const override { return r_; }
  float Integral() const override { return 4 * r_ * r_; }

 private:
  float r_;
};

class TentFilter final : public Filter {
 public:
  explicit TentFilter(float radius = 1.f) : r_(radius) {}
  float Evaluate(Vec2f p) const override {
    return std::max(0.f, r_ - std::abs(p.x)) * std::max(0.f, r_ - std::abs(p.y));
  }
  FilterSample Sample(Vec2f u) const override { return {{SampleTent(u.x, r_), SampleTent(u.y, r_)}, 1.f}; }
  float Radius() const override { return r_; }
  float Integral() const override { return r_ * r_ * r_ * r_; }  // (integral of r - |x|)^2

 private:
  float r_;
};

// Filters without a closed-form inverse CDF are sampled from a tabulated distribution.
class TabulatedFilter : public Filter {
 public:
  FilterSample Sample(Vec2f u) const override;
  float Radius() const override { return r_; }

 protected:
  explicit TabulatedFilter(float radius) : r_(radius) {}
  void Tabulate();  // call from the derived constructor once Evaluate works
  float r_;

 private:
  Distribution2D distribution_;
  int n_ = 0;
};

// Mitsuba's Gaussian: exp(-x^2 / 2 sigma^2) minus its value at the radius (4 sigma).
class GaussianFilter final : public TabulatedFilter {
 public:
  explicit GaussianFilter(float stddev = 0.5f);
  float Evaluate(Vec2f p) const override;
  float Integral() const override;

 private:
  float G(float x) const;
  float sigma_;
};

// Blackman-Harris window over [-radius, radius] (Cycles' default pixel filter).
class BlackmanHarrisFilter final : public TabulatedFilter {
 public:
  explicit BlackmanHarrisFilter(float radius = 1.5f);
  float Evaluate(Vec2f p) const override;
  float Integral() const override;

 private:
  float W(float x) const;
};

}  // namespace objektiv
