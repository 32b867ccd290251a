#include "optics/thin_film.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace objektiv {

namespace {

using Complex = std::complex<double>;

// cos(theta) in a medium of index n for Snell's invariant s = n0 sin(theta0): real while the
// wave propagates, positive imaginary where it is evanescent (the root that decays). Kept off
// zero (exactly at the critical angle the p admittance n / cos would be infinite).
Complex CosIn(double n, double s) {
  double c2 = 1 - (s / n) * (s / n);
  Complex c = c2 >= 0 ? Complex(std::sqrt(c2), 0) : Complex(0, std::sqrt(-c2));
  return std::abs(c) < 1e-12 ? Complex(1e-12, 0) : c;
}

Complex Admittance(double n, Complex cos_theta, bool p) { return p ? n / cos_theta : n * cos_theta; }

}  // namespace

ThinFilmResponse ThinFilmStack(double n_incident, std::span<const ThinFilmLayer> layers, double n_substrate,
                               double lambda_nm, double cos_incident) {
  const double cos0 = std::clamp(cos_incident, 1e-12, 1.0);
  const double invariant = n_incident * std::sqrt(std::max(0.0, 1 - cos0 * cos0));
  ThinFilmResponse out;
  for (bool p : {false, true}) {
    const Complex eta0 = Admittance(n_incident, cos0, p);
    // M = product of the layers' matrices, incident side first.
    Complex m00 = 1, m01 = 0, m10 = 0, m11 = 1;
    for (const ThinFilmLayer& layer : layers) {
      const Complex c = CosIn(layer.index, invariant);
      const Complex eta = Admittance(layer.index, c, p);
      Complex delta = 2 * M_PI * layer.index * layer.thickness_nm * c / lambda_nm;
      // An evanescent layer many decay lengths thick is a wall (frustrated total reflection
      // that lets nothing through): cap its attenuation at e^-30 before cosh overflows.
      delta = Complex(delta.real(), std::min(delta.imag(), 30.0));
      const Complex cd = std::cos(delta), sd = std::sin(delta);
      const Complex l00 = cd, l01 = Complex(0, 1) * sd / eta, l10 = Complex(0, 1) * eta * sd, l11 = cd;
      const Complex a00 = m00 * l00 + m01 * l10, a01 = m00 * l01 + m01 * l11;
      const Complex a10 = m10 * l00 + m11 * l10, a11 = m10 * l01 + m11 * l11;
      m00 = a00, m01 = a01, m10 = a10, m11 = a11;
    }
    const Complex eta_s = Admittance(n_substrate, CosIn(n_substrate, invariant), p);
    const Complex b = m00 + m01 * eta_s, c = m10 + m11 * eta_s;
    const Complex denominator = eta0 * b + c;
    const double r = std::norm((eta0 * b - c) / denominator);
    const double t = 4 * eta0.real() * eta_s.real() / std::norm(denominator);
    (p ? out.rp : out.rs) = std::min(r, 1.0);
    (p ? out.tp : out.ts) = std::max(t, 0.0);
  }
  return out;
}

}  // namespace objektiv
