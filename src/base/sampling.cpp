#include "base/sampling.h"

#include <algorithm>
#include <cmath>

#include "base/rng.h"

namespace objektiv {

// Shirley-Chiu concentric map: preserves area fractions and adjacency.
namespace {
// cos and sin of t for |t| <= pi/4 by their Taylor series to t^10 and t^9 (truncation error
// below 2e-9, under float rounding): several times cheaper than the library's sincosf, which
// must reduce any argument.
inline Vec2f CosSinQuarter(float t) {
  float t2 = t * t;
  float c = 1 + t2 * (-1.f / 2 + t2 * (1.f / 24 + t2 * (-1.f / 720 + t2 * (1.f / 40320 - t2 * (1.f / 3628800)))));
  float s = t * (1 + t2 * (-1.f / 6 + t2 * (1.f / 120 + t2 * (-1.f / 5040 + t2 * (1.f / 362880)))));
  return {c, s};
}
}  // namespace

Vec2f SampleUniformDiskConcentric(Vec2f u) {
  float ox = 2 * u.x - 1, oy = 2 * u.y - 1;
  if (ox == 0 && oy == 0) return {0, 0};
  // Shirley-Chiu: the angle is pi/4 times the ratio of the smaller coordinate to the larger,
  // measured from the larger one's axis (|angle| <= pi/4 there).
  if (std::abs(ox) > std::abs(oy)) {
    Vec2f cs = CosSinQuarter((kPi / 4) * (oy / ox));
    return {ox * cs.x, ox * cs.y};
  }
  // theta = pi/2 - t: cos theta = sin t, sin theta = cos t.
  Vec2f cs = CosSinQuarter((kPi / 4) * (ox / oy));
  return {oy * cs.y, oy * cs.x};
}

float RegularPolygonArea(int blades) { return 0.5f * blades * std::sin(2 * kPi / blades); }

Vec2f SampleRegularPolygon(int blades, float rotation, Vec2f u) {
  // Pick one of the n congruent triangles (centre, corner k, corner k+1), then a uniform
  // point in it; u.x is reused after the discrete choice.
  float scaled = u.x * blades;
  int k = std::min(int(scaled), blades - 1);
  float ux = scaled - k;
  Vec2f b = SampleUniformTriangle({ux, u.y});
  float a0 = rotation + 2 * kPi * k / blades, a1 = rotation + 2 * kPi * (k + 1) / blades;
  Vec2f c0{std::cos(a0), std::sin(a0)}, c1{std::cos(a1), std::sin(a1)};
  // Barycentric (b0, b1) weight corners c0 and c1; the centre gets the rest.
  return c0 * b.x + c1 * b.y;
}

Vec3f SampleCosineHemisphere(Vec2f u) {
  Vec2f d = SampleUniformDiskConcentric(u);
  float z = SafeSqrt(1 - d.x * d.x - d.y * d.y);
  return {d.x, d.y, z};
}

Vec3f SampleUniformHemisphere(Vec2f u) {
  float z = u.x;
  float r = SafeSqrt(1 - z * z), phi = 2 * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

Vec3f SampleUniformSphere(Vec2f u) {
  float z = 1 - 2 * u.x;
  float r = SafeSqrt(1 - z * z), phi = 2 * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

Vec3f SampleUniformCone(Vec2f u, float cos_max) {
  float cos_t = (1 - u.x) + u.x * cos_max;
  float sin_t = SafeSqrt(1 - cos_t * cos_t), phi = u.y * 2 * kPi;
  return {std::cos(phi) * sin_t, std::sin(phi) * sin_t, cos_t};
}

// Area-preserving square-to-triangle map (Heitz 2019, "A Low-Distortion Map Between Triangle and Square").
Vec2f SampleUniformTriangle(Vec2f u) {
  float b0, b1;
  if (u.x < u.y) {
    b0 = u.x / 2;
    b1 = u.y - b0;
  } else {
    b1 = u.y / 2;
    b0 = u.x - b1;
  }
  return {b0, b1};
}

float SampleTent(float u, float r) {
  // Inverse CDF of the tent, one half at a time.
  if (u < 0.5f) {
    float up = std::min(u * 2, kOneMinusEpsilon);
    return -r + r * std::sqrt(up);
  }
  float up = std::min((u - 0.5f) * 2, kOneMinusEpsilon);
  return r - r * std::sqrt(1 - up);
}

Distribution1D::Distribution1D(std::span<const float> f) : func_(f.begin(), f.end()), cdf_(f.size() + 1) {
  int n = Count();
  for (float& v : func_) v = std::abs(v);
  cdf_[0] = 0;
  for (int i = 1; i <= n; ++i) cdf_[i] = cdf_[i - 1] + func_[i - 1] / n;
  func_int_ = cdf_[n];
  if (func_int_ == 0) {
    for (int i = 1; i <= n; ++i) cdf_[i] = float(i) / n;
  } else {
    for (int i = 1; i <= n; ++i) cdf_[i] /= func_int_;
  }
}

float Distribution1D::SampleContinuous(float u, float* pdf, int* cell) const {
  int n = Count();
  // Largest i with cdf[i] <= u.
  int i = int(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin()) - 1;
  i = std::clamp(i, 0, n - 1);
  if (cell) *cell = i;
  float du = u - cdf_[i];
  float width = cdf_[i + 1] - cdf_[i];
  if (width > 0) du /= width;
  if (pdf) *pdf = func_int_ > 0 ? func_[i] / func_int_ : 1;
  return std::min((i + du) / n, kOneMinusEpsilon);
}

int Distribution1D::SampleDiscrete(float u, float* pmf) const {
  int n = Count();
  if (n == 1) {  // one light, one triangle: common enough to skip the search
    if (pmf) *pmf = 1;
    return 0;
  }
  int i;
  if (n <= 8) {  // a short linear scan beats the binary search (a quad light: 2 triangles)
    i = 0;
    while (i + 1 < n && cdf_[i + 1] <= u) ++i;
  } else {
    i = int(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin()) - 1;
  }
  i = std::clamp(i, 0, n - 1);
  if (pmf) *pmf = DiscretePmf(i);
  return i;
}

float Distribution1D::Pdf(float x) const {
  int n = Count();
  int i = std::clamp(int(x * n), 0, n - 1);
  return func_int_ > 0 ? func_[i] / func_int_ : 1;
}

Distribution2D::Distribution2D(std::span<const float> f, int nu, int nv) {
  conditional_.reserve(nv);
  std::vector<float> marginal(nv);
  for (int v = 0; v < nv; ++v) {
    conditional_.emplace_back(f.subspan(size_t(v) * nu, nu));
    marginal[v] = conditional_.back().Integral();
  }
  marginal_ = Distribution1D(marginal);
}

Vec2f Distribution2D::Sample(Vec2f u, float* pdf) const {
  float pdfs[2];
  int v;
  float d1 = marginal_.SampleContinuous(u.y, &pdfs[1], &v);
  float d0 = conditional_[v].SampleContinuous(u.x, &pdfs[0]);
  *pdf = pdfs[0] * pdfs[1];
  return {d0, d1};
}

float Distribution2D::Pdf(Vec2f p) const {
  int nv = int(conditional_.size());
  int v = std::clamp(int(p.y * nv), 0, nv - 1);
  return conditional_[v].Pdf(p.x) * marginal_.Pdf(p.y);
}

}  // namespace objektiv
