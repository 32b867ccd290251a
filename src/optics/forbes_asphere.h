// Forbes's Q-type aspheres (G. W. Forbes, "Shape specification for axially symmetric optical
// surfaces", Opt. Express 15, 5218, 2007): a surface's departure from its base written in
// polynomials orthogonal over its normalisation disc, r <= r_n, with u = r / r_n, x = u^2:
//
//   Qcon (a conic base of curvature c, conic k):
//     z(r) = c r^2 / (1 + sqrt(1 - (1 + k) c^2 r^2)) + u^4 sum_m a_m Q^con_m(x)
//     Q^con_m(x) = P^(0,4)_m(2x - 1), Jacobi's polynomials: orthogonal in sag.
//   Qbfs (a best-fit sphere of curvature c):
//     z(r) = c r^2 / (1 + sqrt(1 - c^2 r^2)) + u^2 (1 - u^2) / sqrt(1 - c^2 r^2) sum_m a_m Q^bfs_m(x)
//     Q^bfs_m: the slopes d/du [u^2 (1 - u^2) Q^bfs_m(u^2)] orthonormal under the weight
//     (2 / pi) / sqrt(1 - u^2) on [0, 1] (so sum a_m^2 is the departure's mean square slope
//     normal to the sphere), Q^bfs_m(0) > 0: Q0 = 1, Q1 = (13 - 16x) / sqrt(19), ...
//
// The coefficients a_m are lengths (mm). The sum S(x) = sum_m a_m Q_m(x), a polynomial of degree
// M in x, is kept as a Chebyshev series in t = 2x - 1 (well conditioned in single precision too,
// unlike its power series), evaluated with its derivative by Clenshaw's recurrence. Q^bfs_m are
// built once by orthonormalising the Chebyshev polynomials under Forbes's inner product, which
// Gauss-Chebyshev quadrature computes exactly.
#pragma once
#include <memory>
#include <vector>

namespace objektiv {

class ForbesAsphere {
 public:
  enum class Kind { kBestFitSphere, kConic };  // Qbfs, Qcon
  static constexpr int kMaxTerms = 30;          // a_0 ... a_29

  // `terms` a_0.. (mm), at most kMaxTerms; `norm_radius` r_n > 0 (mm).
  ForbesAsphere(Kind kind, double norm_radius, std::vector<double> terms);

  Kind kind() const { return kind_; }
  double norm_radius() const { return norm_radius_; }
  const std::vector<double>& terms() const { return terms_; }
  // S(x) = sum a_m Q_m(x) as Chebyshev coefficients: S = sum_k b_k T_k(2x - 1).
  const std::vector<double>& chebyshev() const { return chebyshev_; }

  // The departure from the base at radius r and its slope d/dr, given the base's curvature c
  // (Qbfs divides by sqrt(1 - c^2 r^2): r must lie where the sphere does, c^2 r^2 < 1).
  void Departure(double r, double c, double& z, double& dz_dr) const;
  // The departure's r^2 coefficient at the vertex: Qbfs adds S(0) / r_n^2 (so 2 S(0) / r_n^2 to
  // the paraxial curvature); Qcon's starts at r^4.
  double VertexR2Term() const;
  // The same shape `factor` times larger (r_n and the a_m scale with it).
  ForbesAsphere Scaled(double factor) const;
  const char* Name() const { return kind_ == Kind::kBestFitSphere ? "Qbfs" : "Qcon"; }

 private:
  Kind kind_;
  double norm_radius_;
  std::vector<double> terms_, chebyshev_;
};

// The polynomials themselves (for the tests and for whoever wants them), m < kMaxTerms.
double QbfsPolynomial(int m, double x);
double QconPolynomial(int m, double x);

// sum_k b_k T_k(t) and its derivative d/dt (Clenshaw), for the batch tracer's float copy too.
template <typename T>
inline void ChebyshevSum(const T* b, int count, T t, T& value, T& derivative) {
  T y1 = 0, y2 = 0, d1 = 0, d2 = 0;  // y_{k+1}, y_{k+2} and their t-derivatives
  for (int k = count - 1; k >= 1; --k) {
    const T y = b[k] + 2 * t * y1 - y2;
    const T d = 2 * y1 + 2 * t * d1 - d2;
    y2 = y1, y1 = y, d2 = d1, d1 = d;
  }
  value = (count > 0 ? b[0] : T(0)) + t * y1 - y2;
  derivative = y1 + t * d1 - d2;
}

}  // namespace objektiv
