// A birefringent uniaxial crystal (calcite, crystal quartz, the plates of a sensor's optical
// low-pass filter): a medium with two indices, the ordinary n_o (its glass's) and the
// extraordinary n_e, and an optic axis a. It fills the gap after the surface it follows; the
// axis is given in that surface's frame.
//
// Light entering it splits into two waves. Their wave vectors k (index times the unit wave
// normal) obey, with theta the angle between k and the axis,
//   ordinary:       |k| = n_o
//   extraordinary:  (k.a)^2 / n_o^2 + (|k|^2 - (k.a)^2) / n_e^2 = 1,
//                   i.e. 1 / n(theta)^2 = cos^2(theta) / n_o^2 + sin^2(theta) / n_e^2.
// At an interface the component of k along it is kept (phase matching); the component along
// the normal solves the wave's relation, the root whose energy flows away from the interface.
// The ordinary ray travels along k. The extraordinary ray (its energy, the Poynting vector)
// travels along the relation's gradient, S ~ (k.a) a / n_o^2 + (k - (k.a) a) / n_e^2, off k by
// the walk-off angle rho, tan(rho) = (n_o^2 - n_e^2) sin(theta) cos(theta) /
// (n_e^2 cos^2(theta) + n_o^2 sin^2(theta)); from S, k ~ n_o^2 (S.a) a + n_e^2 (S - (S.a) a).
//
// What is modelled: unpolarised light, half in each wave (a tracer chooses one of them for
// each ray with probability 1/2 and keeps its weight); each wave's reflectance is Fresnel's
// unpolarised one with the wave's own index (|k|) at its wave normal's angle, an approximation
// (the exact anisotropic Fresnel coefficients are left out); a ray leaving one crystal is
// treated as unpolarised again in the next (the phases and polarisation states between crystals
// are not carried). Not with a gradient-index medium or a mirror in the same gap.
#pragma once
#include <memory>
#include <optional>

#include "base/vec.h"
#include "optics/glass.h"

namespace objektiv {

struct UniaxialCrystal {
  Vec3d axis{0, 0, 1};                          // unit, in the frame of the surface it follows
  std::shared_ptr<const Glass> extraordinary;  // n_e(lambda); the medium's glass is n_o(lambda)
  // Whether the optic axis leans off the surface's own axis (the crystal is then not a
  // figure of revolution about it).
  bool Leans() const { return axis.x != 0 || axis.y != 0; }
};

// A medium as a wave sees it at one wavelength: isotropic of index n, or a crystal's ordinary
// (index n) or extraordinary wave (n_o = n, n_e = ne, optic axis `axis` in lens space).
struct WaveMedium {
  double n = 1;
  bool crystal = false;        // a crystal (either wave)
  bool extraordinary = false;  // its extraordinary wave
  double ne = 1;
  Vec3d axis{0, 0, 1};
};

// The extraordinary wave's index along the unit wave normal k: n(theta).
double ExtraordinaryIndex(const Vec3d& k, const WaveMedium& m);
// The direction the extraordinary ray travels (unit) for the wave vector k, and the unit wave
// normal of the extraordinary ray travelling along s.
Vec3d ExtraordinaryRay(const Vec3d& k, const WaveMedium& m);
Vec3d ExtraordinaryWaveNormal(const Vec3d& s, const WaveMedium& m);
// The wave vector (|k| its index) of a ray travelling along unit d in m.
Vec3d WaveVectorOf(const Vec3d& d, const WaveMedium& m);
// The direction a ray of wave vector k travels in m (unit).
Vec3d RayDirectionOf(const Vec3d& k, const WaveMedium& m);
// The wave leaving an interface into m, whose unit normal `into` points into the side the
// wave goes, with `tangential` the part of the arriving wave vector along the interface:
// k = tangential + beta into, beta the root whose energy flows along `into`; nothing where
// the wave cannot exist there (beyond the critical angle).
std::optional<Vec3d> WaveVectorInto(const Vec3d& tangential, const Vec3d& into, const WaveMedium& m);

}  // namespace objektiv
