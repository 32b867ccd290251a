// Build-time generator of the RGB -> sigmoid-polynomial table (see base/rgb_to_spectrum.h).
// For every table entry it solves, by damped Gauss-Newton with an analytic Jacobian, for
// the coefficients whose reflectance spectrum, lit by D65 and seen through the CIE 1931
// observer, has the target linear Rec.709 colour. Neighbouring entries along the brightness
// axis start from each other's solution (continuation), which keeps every solve short.
// Usage: rgb2spec_gen OUTPUT.bin
#include <cmath>
#include <cstdio>
#include <vector>

#include <tbb/parallel_for.h>

#include "base/cie.h"
#include "base/color_space.h"
#include "base/rgb_to_spectrum.h"

using namespace objektiv;

namespace {

constexpr int kSteps = 471;  // 1 nm over [360, 830]
struct Quadrature {
  double t[kSteps];
  double w[kSteps][3];  // weight * (RGB of the matching functions times D65) / Y(D65)
};

Quadrature MakeQuadrature() {
  Quadrature q;
  const Mat3& m = ColorSpace::Rec709().xyz_to_rgb;
  double ynorm = 0;
  for (int i = 0; i < kSteps; ++i) {
    double l = 360.0 + i, wt = (i == 0 || i == kSteps - 1) ? 0.5 : 1.0;
    ynorm += wt * CieXyz(float(l)).y * D65Raw(float(l));
  }
  for (int i = 0; i < kSteps; ++i) {
    double l = 360.0 + i, wt = (i == 0 || i == kSteps - 1) ? 0.5 : 1.0;
    Vec3f c = CieXyz(float(l));
    double d = D65Raw(float(l)) * wt / ynorm;
    q.t[i] = (l - 360.0) / 470.0;
    for (int k = 0; k < 3; ++k) q.w[i][k] = (m[k][0] * c.x + m[k][1] * c.y + m[k][2] * c.z) * d;
  }
  return q;
}

// Residual (RGB of the spectrum minus target) and its Jacobian with respect to c.
void Evaluate(const Quadrature& q, const double c[3], const double target[3], double r[3], double J[3][3]) {
  for (int k = 0; k < 3; ++k) {
    r[k] = -target[k];
    J[k][0] = J[k][1] = J[k][2] = 0;
  }
  for (int i = 0; i < kSteps; ++i) {
    double t = q.t[i], x = (c[0] * t + c[1]) * t + c[2];
    double den = 1 + x * x, sq = std::sqrt(den);
    double s = 0.5 + x / (2 * sq), ds = 0.5 / (den * sq);
    double dc[3] = {ds * t * t, ds * t, ds};
    for (int k = 0; k < 3; ++k) {
      r[k] += s * q.w[i][k];
      for (int j = 0; j < 3; ++j) J[k][j] += dc[j] * q.w[i][k];
    }
  }
}

bool Solve3(double a[3][3], double b[3], double x[3]) {
  Mat3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = a[i][j];
  double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  if (!(std::abs(det) > 1e-30)) return false;
  Mat3 inv = Inverse3(m);
  for (int i = 0; i < 3; ++i) x[i] = inv[i][0] * b[0] + inv[i][1] * b[1] + inv[i][2] * b[2];
  return true;
}

void GaussNewton(const Quadrature& q, const double target[3], double c[3]) {
  for (int it = 0; it < 60; ++it) {
    double r[3], J[3][3], d[3];
    Evaluate(q, c, target, r, J);
    double err = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    if (err < 1e-7) return;
    double neg[3] = {-r[0], -r[1], -r[2]};
    if (!Solve3(J, neg, d)) return;
    // Damping: the sigmoid saturates, so cap the step to keep the iteration stable.
    double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double scale = len > 50 ? 50 / len : 1;
    for (int k = 0; k < 3; ++k) c[k] += d[k] * scale;
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: rgb2spec_gen OUTPUT.bin\n");
    return 2;
  }
  const int res = kRgbTableRes;
  const Quadrature q = MakeQuadrature();
  std::vector<float> table(size_t(3) * res * res * res * 3);
  for (int l = 0; l < 3; ++l) {
    tbb::parallel_for(0, res, [&](int j) {
      double y = double(j) / (res - 1);
      for (int i = 0; i < res; ++i) {
        double x = double(i) / (res - 1);
        auto solve_from = [&](int start, int end, int step) {
          double c[3] = {0, 0, 0};
          for (int k = start; k != end; k += step) {
            double b = RgbTableZ(k), target[3];
            target[l] = b;
            target[(l + 1) % 3] = x * b;
            target[(l + 2) % 3] = y * b;
            GaussNewton(q, target, c);
            size_t idx = ((((size_t(l) * res + k) * res + j) * res + i) * 3);
            for (int t = 0; t < 3; ++t) table[idx + t] = float(c[t]);
          }
        };
        int start = res / 5;
        solve_from(start, res, 1);
        solve_from(start, -1, -1);
      }
    });
  }
  FILE* f = std::fopen(argv[1], "wb");
  if (!f || std::fwrite(table.data(), sizeof(float), table.size(), f) != table.size() || std::fclose(f) != 0) {
    std::fprintf(stderr, "rgb2spec_gen: cannot write %s\n", argv[1]);
    return 1;
  }
  return 0;
}
