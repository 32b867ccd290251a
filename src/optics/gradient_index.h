// A gradient-index (GRIN) medium: glass whose index varies through it. It fills the gap after
// the surface it follows and is laid out in that surface's frame (the vertex at the origin, z
// along the surface's axis toward the film: the lens's axis unless the surface is decentred or
// tilted), relative to the medium's glass, whose index n_v(lambda) it has on the axis at the
// vertex. Three profiles:
//   polynomial, radial and axial (Zemax's Gradient 3 form), r^2 = x^2 + y^2:
//     n = n_v + nr2 r^2 + nr4 r^4 + nr6 r^6 + nz1 z + nz2 z^2 + nz3 z^3
//   spherical: shells about the point (0, 0, R) of the axis, rho the distance from it:
//     n = n_v + s1 (rho - |R|) + s2 (rho - |R|)^2
//   SELFOC (the rod lenses' catalogue form):
//     n^2 = n_v^2 (1 - (g r)^2 + h4 (g r)^4 + h6 (g r)^6)
// Dispersion is the glass's: the gradient's terms are the same at every wavelength (SELFOC's
// scale with n_v); a material whose gradient itself disperses is not modelled.
//
// Rays obey the ray equation d/ds (n dr/ds) = grad n. With dtau = ds / n and T = n dr/ds it is
// the autonomous system dr/dtau = T, dT/dtau = grad(n^2) / 2, which the propagation integrates
// (optics/gradient_propagation.h); the index squared and half its gradient are what it needs.
// Paraxial optics sees the index on the axis, N0(z), and its r^2 coefficient N2(z): a paraxial
// ray obeys d/dz (N0 dy/dz) = 2 N2 y.
#pragma once
#include <array>
#include <string>

#include "base/vec.h"

namespace objektiv {

class GradientIndex {
 public:
  enum class Kind { kPolynomial, kSpherical, kSelfoc };
  // nr2, nr4, nr6 (per mm^2, mm^4, mm^6) and nz1, nz2, nz3 (per mm, mm^2, mm^3).
  static GradientIndex Polynomial(const std::array<double, 3>& radial, const std::array<double, 3>& axial);
  // The shells' centre R mm from the vertex (nonzero), s1 per mm, s2 per mm^2.
  static GradientIndex Spherical(double centre, double s1, double s2);
  // g per mm (> 0), h4 and h6 without units.
  static GradientIndex Selfoc(double g, double h4, double h6);

  // n^2 at p (the medium's frame) for the glass's index n_v, and where asked, grad(n^2) / 2.
  double IndexSquared(double n_v, const Vec3d& p, Vec3d* half_gradient = nullptr) const;
  double Index(double n_v, const Vec3d& p) const;
  // The index on the axis at z, and its r^2 coefficient there: n ~ n0 + n2 r^2 near the axis.
  void Paraxial(double n_v, double z, double& n0, double& n2) const;
  // The same medium in a lens `factor` times larger (each term scales with its power of length).
  GradientIndex Scaled(double factor) const;

  Kind kind() const { return kind_; }
  const char* KindName() const;  // "polynomial", "spherical", "SELFOC"
  // The terms as the lens file writes them (for lens info): "nr2 -0.002, nz1 0.01".
  std::string Terms() const;
  // The profile's terms in order: polynomial nr2, nr4, nr6, nz1, nz2, nz3; spherical R, s1, s2;
  // SELFOC g, h4, h6.
  const std::array<double, 6>& coefficients() const { return c_; }

 private:
  GradientIndex(Kind kind, const std::array<double, 6>& c) : kind_(kind), c_(c) {}
  Kind kind_;
  std::array<double, 6> c_;
};

}  // namespace objektiv
