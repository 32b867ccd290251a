// Warps from the unit square to shapes and directions, with their densities.
#pragma once
#include <span>
#include <vector>

#include "base/vec.h"

namespace objektiv {

Vec2f SampleUniformDiskConcentric(Vec2f u);
// Uniform over a regular polygon with `blades` corners inscribed in the unit circle,
// the first corner at angle `rotation` (radians). Returns a point in [-1,1]^2.
Vec2f SampleRegularPolygon(int blades, float rotation, Vec2f u);
float RegularPolygonArea(int blades);

Vec3f SampleCosineHemisphere(Vec2f u);
inline float CosineHemispherePdf(float cos_theta) { return cos_theta * kInvPi; }
Vec3f SampleUniformHemisphere(Vec2f u);
inline float UniformHemispherePdf() { return kInv2Pi; }
Vec3f SampleUniformSphere(Vec2f u);
inline float UniformSpherePdf() { return kInv4Pi; }
// Uniform over the cone of directions around +z with cos(theta) >= cos_max.
Vec3f SampleUniformCone(Vec2f u, float cos_max);
inline float UniformConePdf(float cos_max) { return 1.f / (2 * kPi * (1 - cos_max)); }
// Barycentric coordinates (b0, b1) uniform over a triangle; b2 = 1 - b0 - b1.
Vec2f SampleUniformTriangle(Vec2f u);

inline float PowerHeuristic(float f_pdf, float g_pdf) {
  float f = f_pdf * f_pdf, g = g_pdf * g_pdf;
  if (std::isinf(f)) return 1;
  return f + g > 0 ? f / (f + g) : 0;
}

// Tent (triangle) over [-r, r]: sample and density.
float SampleTent(float u, float radius);

// Piecewise-constant 1D distribution over [0,1) with `n` equal cells.
class Distribution1D {
 public:
  Distribution1D() = default;
  explicit Distribution1D(std::span<const float> f);
  // Continuous sample in [0,1); pdf with respect to [0,1); the cell index.
  float SampleContinuous(float u, float* pdf, int* cell = nullptr) const;
  int SampleDiscrete(float u, float* pmf = nullptr) const;
  float Pdf(float x) const;
  float DiscretePmf(int i) const { return func_int_ > 0 ? func_[i] / (func_int_ * Count()) : 1.f / Count(); }
  int Count() const { return int(func_.size()); }
  float CdfAt(int i) const { return cdf_[i]; }
  float Integral() const { return func_int_; }

 private:
  std::vector<float> func_, cdf_;
  float func_int_ = 0;
};

// Piecewise-constant 2D distribution over [0,1)^2 (rows are v, columns are u).
class Distribution2D {
 public:
  Distribution2D() = default;
  Distribution2D(std::span<const float> f, int nu, int nv);
  Vec2f Sample(Vec2f u, float* pdf) const;
  float Pdf(Vec2f p) const;

 private:
  std::vector<Distribution1D> conditional_;
  Distribution1D marginal_;
};

}  // namespace objektiv
