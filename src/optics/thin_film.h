// Thin-film interference: how much light a stack of thin, homogeneous, non-absorbing layers
// between two media reflects and transmits, by the characteristic-matrix (transfer-matrix)
// method (H. A. Macleod, Thin-Film Optical Filters, chapter 2).
//
// Light arrives from the incident medium (index n0) at the angle theta0; Snell's invariant
// n_j sin(theta_j) = n0 sin(theta0) gives each layer's angle (cos(theta_j) imaginary where the
// layer is beyond its critical angle: the wave is evanescent there). Layer j of index n_j and
// physical thickness d_j has the phase thickness delta_j = 2 pi n_j d_j cos(theta_j) / lambda
// and the tilted admittance eta_j = n_j cos(theta_j) for s polarisation, n_j / cos(theta_j)
// for p. Its characteristic matrix is
//     M_j = [[cos delta_j, i sin delta_j / eta_j], [i eta_j sin delta_j, cos delta_j]],
// the stack's is the product M_1 M_2 ... (incident side first), and with
//     [B, C]^T = M [1, eta_s]^T         (eta_s: the substrate's admittance)
// the amplitude reflectance is r = (eta_0 B - C) / (eta_0 B + C), so
//     R = |r|^2,   T = 4 eta_0 Re(eta_s) / |eta_0 B + C|^2.
// Without absorption R + T = 1 (T = 0 where the substrate is beyond the critical angle).
// Without layers these are Fresnel's equations. Unpolarised light averages s and p.
#pragma once
#include <span>

namespace objektiv {

struct ThinFilmLayer {
  double index;         // real: the layers do not absorb
  double thickness_nm;  // physical thickness
};

struct ThinFilmResponse {
  double rs = 0, rp = 0, ts = 0, tp = 0;  // intensity reflectances and transmittances
  double Reflectance() const { return 0.5 * (rs + rp); }    // unpolarised
  double Transmittance() const { return 0.5 * (ts + tp); }  // unpolarised
};

// Light from the medium of index `n_incident` at cos(theta0) = `cos_incident` (clamped to
// (0, 1]), through `layers` (incident side first), into the substrate of index `n_substrate`.
ThinFilmResponse ThinFilmStack(double n_incident, std::span<const ThinFilmLayer> layers, double n_substrate,
                               double lambda_nm, double cos_incident);

}  // namespace objektiv
