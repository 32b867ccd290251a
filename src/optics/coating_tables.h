// A lens's coated surfaces' reflectance at a few fixed wavelengths, tabulated over the cosine
// of the angle of incidence: what a preview's ghost bundles (optics/compiled_sequence.h with
// bands) look up instead of solving each coating's thin-film stack (a transfer matrix per
// layer, polarisation averaged) for every ray at every surface, which made a multi-coated
// lens's ghosts four times as slow as a bare one's.
//
// Each table holds R(cos_i) at kColumns evenly spaced cosines over [0, 1] for one surface, one
// direction and one wavelength, read by linear interpolation where that is exact enough: R is
// smooth in cos_i but for the kink where total internal reflection begins (light leaving the
// glass), so every interval whose middle the interpolation misses by more than
// kIntervalTolerance is marked and answered by the stack itself. The tables stay within 1e-4 of
// the stacks (tests/test_compiled_sequence.cpp). Bare surfaces are left to Fresnel's
// equations, which are cheaper than the lookup.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "optics/lens_system.h"

namespace objektiv {

class CoatingTables {
 public:
  static constexpr int kColumns = 257;
  static constexpr double kIntervalTolerance = 2e-5;
  CoatingTables(const LensSystem& lens, std::span<const double> wavelengths);
  // Whether surface i has a table (it is coated).
  bool Has(int surface) const { return offset_[size_t(surface)] >= 0; }
  // Surface i's reflectance for light travelling toward the film or toward the object, at
  // wavelength number `band` (of those given), at cos(incidence) cos_i (clamped to [0, 1]).
  double Reflectance(int surface, bool toward_film, int band, double cos_i) const;
  std::span<const double> wavelengths() const { return wavelengths_; }

 private:
  const LensSystem* lens_;
  std::vector<double> wavelengths_;
  std::vector<long> offset_;  // per surface: its first table in values_, -1 where bare
  std::vector<float> values_;  // per coated surface: [toward film, toward object][band][column]
  std::vector<uint8_t> exact_;  // the same, per interval (from its column to the next): 1 where the stack answers
};

}  // namespace objektiv
