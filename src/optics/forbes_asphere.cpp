#include "optics/forbes_asphere.h"

#include <array>
#include <cmath>
#include <stdexcept>

namespace objektiv {

namespace {

constexpr int kTerms = ForbesAsphere::kMaxTerms;
using Table = std::array<std::array<double, kTerms>, kTerms>;  // [m][k]: Q_m's Chebyshev coefficients

// Jacobi's P^(0,4)_m(t) by its three-term recurrence.
double Jacobi04(int m, double t) {
  double p0 = 1, p1 = 3 * t - 2;
  if (m == 0) return p0;
  for (int n = 2; n <= m; ++n) {
    const double s = 2.0 * n + 4;  // 2n + alpha + beta
    const double p2 = ((s - 1) * (s * (s - 2) * t - 16) * p1 - 2.0 * (n - 1) * (n + 3) * s * p0) / (2.0 * n * (n + 4) * (s - 2));
    p0 = p1, p1 = p2;
  }
  return p1;
}

// Q^con_m in Chebyshev coefficients: each P^(0,4)_m sampled at kTerms Chebyshev nodes and
// transformed (exact for a polynomial of degree below kTerms).
Table QconTable() {
  Table c{};
  for (int m = 0; m < kTerms; ++m)
    for (int k = 0; k < kTerms; ++k) {
      double sum = 0;
      for (int j = 0; j < kTerms; ++j) {
        const double theta = M_PI * (j + 0.5) / kTerms;
        sum += Jacobi04(m, std::cos(theta)) * std::cos(k * theta);
      }
      c[m][k] = sum * (k == 0 ? 1.0 : 2.0) / kTerms;
    }
  return c;
}

// Q^bfs_m: the Chebyshev polynomials T_k(2x - 1), k = 0.., orthonormalised (Gram-Schmidt, done
// twice) under <f, g> = (2 / pi) int_0^1 f'(u) g'(u) / sqrt(1 - u^2) du of f(u) = u^2 (1 - u^2)
// p(u^2). The slopes are odd polynomials in u of degree at most 2 kTerms + 1, their products
// even, so Gauss-Chebyshev quadrature over [-1, 1] with kNodes nodes is exact: <f, g> =
// (1 / kNodes) sum_j f'(u_j) g'(u_j).
Table QbfsTable() {
  constexpr int kNodes = 2 * kTerms + 8;
  // v[k][j]: the slope of T_k's departure at node j, over sqrt(kNodes).
  std::vector<std::array<double, kNodes>> v(kTerms);
  for (int j = 0; j < kNodes; ++j) {
    const double u = std::cos(M_PI * (j + 0.5) / kNodes), x = u * u, t = 2 * x - 1;
    for (int k = 0; k < kTerms; ++k) {
      // T_k(t) and dT_k/dt (from the Chebyshev series with the single coefficient 1 at k).
      std::array<double, kTerms> unit{};
      unit[size_t(k)] = 1;
      double p, dp_dt;
      ChebyshevSum(unit.data(), k + 1, t, p, dp_dt);
      // d/du [x (1 - x) p(x)] = 2u [(1 - 2x) p + x (1 - x) 2 dp/dt].
      v[size_t(k)][size_t(j)] = 2 * u * ((1 - 2 * x) * p + x * (1 - x) * 2 * dp_dt) / std::sqrt(double(kNodes));
    }
  }
  Table c{};
  std::vector<std::array<double, kNodes>> w(kTerms);  // the orthonormal slopes
  for (int m = 0; m < kTerms; ++m) {
    std::array<double, kNodes> vec = v[size_t(m)];
    std::array<double, kTerms> coef{};
    coef[size_t(m)] = 1;
    for (int pass = 0; pass < 2; ++pass)
      for (int n = 0; n < m; ++n) {
        double dot = 0;
        for (int j = 0; j < kNodes; ++j) dot += vec[size_t(j)] * w[size_t(n)][size_t(j)];
        for (int j = 0; j < kNodes; ++j) vec[size_t(j)] -= dot * w[size_t(n)][size_t(j)];
        for (int k = 0; k < kTerms; ++k) coef[size_t(k)] -= dot * c[size_t(n)][size_t(k)];
      }
    double norm = 0;
    for (double e : vec) norm += e * e;
    norm = std::sqrt(norm);
    // Forbes's sign: Q_m(0) > 0, T_k(-1) = (-1)^k.
    double at_zero = 0;
    for (int k = 0; k <= m; ++k) at_zero += (k % 2 ? -1 : 1) * coef[size_t(k)];
    const double scale = (at_zero < 0 ? -1 : 1) / norm;
    for (int j = 0; j < kNodes; ++j) w[size_t(m)][size_t(j)] = vec[size_t(j)] * scale;
    for (int k = 0; k < kTerms; ++k) c[size_t(m)][size_t(k)] = coef[size_t(k)] * scale;
  }
  return c;
}

const Table& TableFor(ForbesAsphere::Kind kind) {
  static const Table bfs = QbfsTable(), con = QconTable();
  return kind == ForbesAsphere::Kind::kBestFitSphere ? bfs : con;
}

}  // namespace

ForbesAsphere::ForbesAsphere(Kind kind, double norm_radius, std::vector<double> terms)
    : kind_(kind), norm_radius_(norm_radius), terms_(std::move(terms)) {
  if (!(norm_radius_ > 0) || terms_.empty() || terms_.size() > size_t(kMaxTerms))
    throw std::invalid_argument("ForbesAsphere: a positive normalisation radius and 1 to 30 terms");
  const Table& table = TableFor(kind);
  chebyshev_.assign(terms_.size(), 0.0);
  for (size_t m = 0; m < terms_.size(); ++m)
    for (size_t k = 0; k <= m; ++k) chebyshev_[k] += terms_[m] * table[m][k];
}

void ForbesAsphere::Departure(double r, double c, double& z, double& dz_dr) const {
  const double x = (r / norm_radius_) * (r / norm_radius_), dx_dr = 2 * r / (norm_radius_ * norm_radius_);
  double s, ds_dt;
  ChebyshevSum(chebyshev_.data(), int(chebyshev_.size()), 2 * x - 1, s, ds_dt);
  const double ds = 2 * ds_dt;  // dS/dx
  if (kind_ == Kind::kConic) {
    z = x * x * s;
    dz_dr = (2 * x * s + x * x * ds) * dx_dr;
    return;
  }
  const double rho = std::sqrt(std::max(1 - c * c * r * r, 1e-300));
  const double w = x * (1 - x);
  z = w * s / rho;
  dz_dr = ((1 - 2 * x) * s + w * ds) * dx_dr / rho + w * s * c * c * r / (rho * rho * rho);
}

double ForbesAsphere::VertexR2Term() const {
  if (kind_ == Kind::kConic) return 0;
  double s, ds;
  ChebyshevSum(chebyshev_.data(), int(chebyshev_.size()), -1.0, s, ds);
  return s / (norm_radius_ * norm_radius_);
}

ForbesAsphere ForbesAsphere::Scaled(double factor) const {
  std::vector<double> terms = terms_;
  for (double& a : terms) a *= factor;
  return ForbesAsphere(kind_, norm_radius_ * factor, std::move(terms));
}

double QbfsPolynomial(int m, double x) {
  const auto& row = TableFor(ForbesAsphere::Kind::kBestFitSphere).at(size_t(m));
  double value, derivative;
  ChebyshevSum(row.data(), m + 1, 2 * x - 1, value, derivative);
  return value;
}

double QconPolynomial(int m, double x) {
  if (m < 0 || m >= kTerms) throw std::out_of_range("QconPolynomial");
  return Jacobi04(m, 2 * x - 1);
}

}  // namespace objektiv
