#include "optics/mirror_metal.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace objektiv {

std::optional<MirrorMetal> MirrorMetal::Named(const std::string& name) {
  if (name == "none") return std::nullopt;  // base's perfect mirror is reflectance=1 here
  std::optional<ConductorIndex> index = NamedConductor(name);
  if (!index) return std::nullopt;
  return MirrorMetal(name, std::move(*index));
}

double MirrorMetal::Reflectance(double lambda_nm, double cos_i, double n1) const {
  using C = std::complex<double>;
  const double lambda = std::clamp(lambda_nm, 300.0, 1000.0);
  const C eta = C(index_.eta(float(lambda)), index_.k(float(lambda))) / n1;
  cos_i = std::clamp(cos_i, 0.0, 1.0);
  const C cos_t = std::sqrt(C(1) - C(1 - cos_i * cos_i) / (eta * eta));
  const C r_s = (C(cos_i) - eta * cos_t) / (C(cos_i) + eta * cos_t);
  const C r_p = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return 0.5 * (std::norm(r_s) + std::norm(r_p));
}

std::string MirrorMetalList() { return "Al, Ag, Au, Cu"; }

}  // namespace objektiv
