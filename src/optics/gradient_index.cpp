#include "optics/gradient_index.h"

#include <cmath>

#include <fmt/format.h>

namespace objektiv {

GradientIndex GradientIndex::Polynomial(const std::array<double, 3>& radial, const std::array<double, 3>& axial) {
  return GradientIndex(Kind::kPolynomial, {radial[0], radial[1], radial[2], axial[0], axial[1], axial[2]});
}

GradientIndex GradientIndex::Spherical(double centre, double s1, double s2) {
  return GradientIndex(Kind::kSpherical, {centre, s1, s2, 0, 0, 0});
}

GradientIndex GradientIndex::Selfoc(double g, double h4, double h6) {
  return GradientIndex(Kind::kSelfoc, {g, h4, h6, 0, 0, 0});
}

double GradientIndex::IndexSquared(double n_v, const Vec3d& p, Vec3d* half_gradient) const {
  const double r2 = p.x * p.x + p.y * p.y;
  switch (kind_) {
    case Kind::kPolynomial: {
      const double z = p.z;
      const double n = n_v + r2 * (c_[0] + r2 * (c_[1] + r2 * c_[2])) + z * (c_[3] + z * (c_[4] + z * c_[5]));
      if (half_gradient) {
        // grad n = (2 x P'(r^2), 2 y P'(r^2), Q'(z)); grad(n^2) / 2 = n grad n.
        const double radial = 2 * (c_[0] + r2 * (2 * c_[1] + 3 * r2 * c_[2]));
        const double axial = c_[3] + z * (2 * c_[4] + 3 * z * c_[5]);
        *half_gradient = Vec3d(n * radial * p.x, n * radial * p.y, n * axial);
      }
      return n * n;
    }
    case Kind::kSpherical: {
      const Vec3d q(p.x, p.y, p.z - c_[0]);
      const double rho = Length(q), d = rho - std::abs(c_[0]);
      const double n = n_v + d * (c_[1] + d * c_[2]);
      if (half_gradient) {
        // grad n = (s1 + 2 s2 d) q / rho (none at the centre, where the shells shrink to a point).
        const double dn = c_[1] + 2 * c_[2] * d;
        *half_gradient = rho > 0 ? q * (n * dn / rho) : Vec3d(0, 0, 0);
      }
      return n * n;
    }
    case Kind::kSelfoc: {
      const double u = c_[0] * c_[0] * r2, n_v2 = n_v * n_v;
      if (half_gradient) {
        // d(n^2)/dx = n_v^2 g^2 2x (-1 + 2 h4 u + 3 h6 u^2).
        const double k = n_v2 * c_[0] * c_[0] * (-1 + u * (2 * c_[1] + 3 * c_[2] * u));
        *half_gradient = Vec3d(k * p.x, k * p.y, 0);
      }
      return n_v2 * (1 + u * (-1 + u * (c_[1] + u * c_[2])));
    }
  }
  return n_v * n_v;
}

double GradientIndex::Index(double n_v, const Vec3d& p) const {
  return std::sqrt(std::max(IndexSquared(n_v, p), 0.0));
}

void GradientIndex::Paraxial(double n_v, double z, double& n0, double& n2) const {
  switch (kind_) {
    case Kind::kPolynomial:
      n0 = n_v + z * (c_[3] + z * (c_[4] + z * c_[5]));
      n2 = c_[0];
      return;
    case Kind::kSpherical: {
      // On the axis rho0 = |z - R|; near it rho ~ rho0 + r^2 / (2 rho0).
      const double rho0 = std::abs(z - c_[0]), d = rho0 - std::abs(c_[0]);
      n0 = n_v + d * (c_[1] + d * c_[2]);
      n2 = rho0 > 0 ? (c_[1] + 2 * c_[2] * d) / (2 * rho0) : 0;
      return;
    }
    case Kind::kSelfoc:
      // n = n_v sqrt(1 - g^2 r^2 + ...) ~ n_v (1 - g^2 r^2 / 2).
      n0 = n_v;
      n2 = -0.5 * n_v * c_[0] * c_[0];
      return;
  }
}

GradientIndex GradientIndex::Scaled(double f) const {
  std::array<double, 6> c = c_;
  switch (kind_) {
    case Kind::kPolynomial:
      c[0] /= f * f, c[1] /= std::pow(f, 4), c[2] /= std::pow(f, 6);
      c[3] /= f, c[4] /= f * f, c[5] /= f * f * f;
      break;
    case Kind::kSpherical:
      c[0] *= f, c[1] /= f, c[2] /= f * f;
      break;
    case Kind::kSelfoc:
      c[0] /= f;
      break;
  }
  return GradientIndex(kind_, c);
}

const char* GradientIndex::KindName() const {
  switch (kind_) {
    case Kind::kPolynomial: return "polynomial";
    case Kind::kSpherical: return "spherical";
    case Kind::kSelfoc: return "SELFOC";
  }
  return "";
}

std::string GradientIndex::Terms() const {
  static const char* const names[3][6] = {{"nr2", "nr4", "nr6", "nz1", "nz2", "nz3"},
                                          {"R", "s1", "s2", "", "", ""},
                                          {"g", "h4", "h6", "", "", ""}};
  const int k = int(kind_);
  std::string out;
  for (int i = 0; i < 6; ++i) {
    if (!*names[k][i] || (c_[i] == 0 && !(kind_ == Kind::kSelfoc && i == 0))) continue;
    out += fmt::format("{}{} {:.6g}", out.empty() ? "" : ", ", names[k][i], c_[i]);
  }
  return out.empty() ? "none" : out;
}

}  // namespace objektiv
