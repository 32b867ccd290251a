#include "chi2.h"

#include <cmath>
#include <sstream>

namespace objektiv::test {

double GammaQ(double a, double x) {
  if (x <= 0) return 1;
  double gln = std::lgamma(a);
  if (x < a + 1) {
    // Series for P(a, x).
    double ap = a, sum = 1 / a, del = sum;
    for (int n = 0; n < 1000; ++n) {
      ap += 1;
      del *= x / ap;
      sum += del;
      if (std::abs(del) < std::abs(sum) * 1e-15) break;
    }
    return 1 - sum * std::exp(-x + a * std::log(x) - gln);
  }
  // Continued fraction for Q(a, x) (modified Lentz).
  double b = x + 1 - a, c = 1 / 1e-300, d = 1 / b, h = d;
  for (int i = 1; i < 1000; ++i) {
    double an = -i * (i - a);
    b += 2;
    d = an * d + b;
    if (std::abs(d) < 1e-300) d = 1e-300;
    c = b + an / c;
    if (std::abs(c) < 1e-300) c = 1e-300;
    d = 1 / d;
    double del = d * c;
    h *= del;
    if (std::abs(del - 1) < 1e-15) break;
  }
  return std::exp(-x + a * std::log(x) - gln) * h;
}

std::string Chi2Result::Describe() const {
  std::ostringstream s;
  s << "chi2 = " << statistic << ", dof = " << dof << ", p = " << p_value << ", pdf integral = " << pdf_integral;
  return s.str();
}

namespace {
Chi2Result Evaluate(const std::vector<double>& observed, const std::vector<double>& expected, double integral) {
  // Pool the bins whose expected count is below 5 into one.
  Chi2Result r;
  r.pdf_integral = integral;
  double pooled_obs = 0, pooled_exp = 0;
  for (size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] < 5) {
      pooled_obs += observed[i];
      pooled_exp += expected[i];
      continue;
    }
    r.statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++r.dof;
  }
  if (pooled_exp >= 5) {
    r.statistic += (pooled_obs - pooled_exp) * (pooled_obs - pooled_exp) / pooled_exp;
    ++r.dof;
  } else if (pooled_obs > 10) {
    // Many samples where the pdf claims (almost) none: a clear mismatch.
    r.statistic = 1e30;
  }
  r.dof -= 1;
  r.p_value = r.dof > 0 ? GammaQ(r.dof / 2.0, r.statistic / 2) : 1;
  return r;
}
}  // namespace

Chi2Result Chi2TestDirections(const DirectionSampler& sample, const DirectionPdf& pdf, int n, int tb, int pb) {
  std::vector<double> observed(size_t(tb) * pb, 0), expected(size_t(tb) * pb, 0);
  PCG32 rng(7, 11);
  for (int i = 0; i < n; ++i) {
    std::optional<Vec3f> w = sample(rng);
    if (!w) continue;
    // The grid's pole is +x, so that lobes around +-z (normal incidence) lie on its equator,
    // where the bins resolve them; see the pdf quadrature below.
    float z = Clamp(w->x, -1, 1);
    float phi = std::atan2(w->z, w->y);
    if (phi < 0) phi += 2 * kPi;
    int ti = std::min(int((z + 1) / 2 * tb), tb - 1), pi = std::min(int(phi / (2 * kPi) * pb), pb - 1);
    observed[size_t(ti) * pb + pi] += 1;
  }
  // Integrate the pdf over each bin with a fine midpoint rule in (cos theta, phi).
  const int sub = 24;
  double integral = 0;
  for (int ti = 0; ti < tb; ++ti)
    for (int pi = 0; pi < pb; ++pi) {
      double sum = 0;
      for (int a = 0; a < sub; ++a)
        for (int b = 0; b < sub; ++b) {
          double z = -1 + 2.0 * (ti + (a + 0.5) / sub) / tb;
          double phi = 2 * M_PI * (pi + (b + 0.5) / sub) / pb;
          double r = std::sqrt(std::max(0.0, 1 - z * z));
          sum += pdf(Vec3f(float(z), float(r * std::cos(phi)), float(r * std::sin(phi))));
        }
      double bin_area = (2.0 / tb) * (2 * M_PI / pb);
      double mass = sum / (sub * sub) * bin_area;
      integral += mass;
      expected[size_t(ti) * pb + pi] = mass * n;
    }
  return Evaluate(observed, expected, integral);
}

Chi2Result Chi2TestPoints(const PointSampler& sample, const PointPdf& pdf, Vec2f lo, Vec2f hi, int n, int bins) {
  std::vector<double> observed(size_t(bins) * bins, 0), expected(size_t(bins) * bins, 0);
  PCG32 rng(3, 5);
  Vec2f ext = hi - lo;
  for (int i = 0; i < n; ++i) {
    Vec2f p = sample(rng);
    int x = int((p.x - lo.x) / ext.x * bins), y = int((p.y - lo.y) / ext.y * bins);
    if (x < 0 || y < 0 || x >= bins || y >= bins) continue;
    observed[size_t(y) * bins + x] += 1;
  }
  const int sub = 48;
  double integral = 0;
  for (int y = 0; y < bins; ++y)
    for (int x = 0; x < bins; ++x) {
      double sum = 0;
      for (int a = 0; a < sub; ++a)
        for (int b = 0; b < sub; ++b) {
          Vec2f p(lo.x + ext.x * (x + (a + 0.5f) / sub) / bins, lo.y + ext.y * (y + (b + 0.5f) / sub) / bins);
          sum += pdf(p);
        }
      double mass = sum / (sub * sub) * (ext.x / bins) * (ext.y / bins);
      integral += mass;
      expected[size_t(y) * bins + x] = mass * n;
    }
  return Evaluate(observed, expected, integral);
}

}  // namespace objektiv::test
