// What a mirror reflects. A real mirror is a metal layer (aluminium on most camera and
// telescope mirrors, silver on some Mangin mirrors), seen from the medium the light arrives
// in: air on a front-surface mirror, the glass on a Mangin mirror (a lens silvered on its
// back). Its reflectance is Fresnel's for a conductor of complex index n + i k (the measured
// data of base/conductor_data.h), relative to that medium's index n1, averaged over the two
// polarisations:
//   eta = (n + i k) / n1,  cos_t = sqrt(1 - sin^2(i) / eta^2),
//   r_s = (cos_i - eta cos_t) / (cos_i + eta cos_t),  r_p = (eta cos_i - cos_t) / (eta cos_i + cos_t),
//   R = (|r_s|^2 + |r_p|^2) / 2;  at normal incidence ((n - n1)^2 + k^2) / ((n + n1)^2 + k^2).
// Aluminium reflects 91-92% of the visible from air, 87-90% from glass. Without a metal, a
// mirror reflects a constant share at every wavelength and angle (1: ideal, as Zemax's
// default).
#pragma once
#include <memory>
#include <optional>
#include <string>

#include "base/conductor_data.h"

namespace objektiv {

class MirrorMetal {
 public:
  // "Al", "Ag", "Au", "Cu" (base/conductor_data.h); nothing for another name.
  static std::optional<MirrorMetal> Named(const std::string& name);
  const std::string& name() const { return name_; }
  // Reflectance for light arriving from a medium of index n1 at cos(incidence) cos_i.
  double Reflectance(double lambda_nm, double cos_i, double n1) const;

 private:
  MirrorMetal(std::string name, ConductorIndex index) : name_(std::move(name)), index_(std::move(index)) {}
  std::string name_;
  ConductorIndex index_;
};

// The metals a mirror may name, for messages: "Al, Ag, Au, Cu".
std::string MirrorMetalList();

}  // namespace objektiv
