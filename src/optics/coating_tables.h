// A lens's coated surfaces' reflectance at a few fixed wavelengths, tabulated over the cosine
// of the angle of incidence: what a preview's ghost bundles (optics/compiled_sequence.h with
// bands) look up instead of solving each coating's thin-film stack (a transfer matrix per
// layer, polarisation averaged) for every ray at every surface, which made a multi-coated
// lens's ghosts four times as slow as a bare one's.
//
// Each table holds R(cos_i) at kColumns evenly spaced cosines over [0, 1] for one surface, one
// direction and one wavelength, read by cubic (Catmull-Rom) interpolation where that is exact
// enough: R is smooth in cos_i but for the kink where total internal reflection begins (light
// leaving the glass), so every interval whose middle the interpolation misses by more than
// kIntervalTolerance is marked and answered by the stack itself. (Linear interpolation missed
// in 7 times as many: a multi-coating's R rises steeply toward grazing light and just past the
// critical angle, 6% of the intervals at 32 wavelengths, each then a stack's microsecond.) The
// tables stay within 1e-4 of the stacks (tests/test_compiled_sequence.cpp). Bare surfaces are
// left to Fresnel's equations, which are cheaper than the lookup.
//
// The tables keep their own copy of each coated interface (the coating and the media on its
// two sides), so they hold for any lens that lays coatings of the same response between glasses
// of the same indices: another set-up of the lens (focus, f-number, iris) or another loading
// of it (CoatedInterface::SameResponse at the tables' wavelengths). Shared() keeps the last
// few made, for the live viewer, whose every preview frame asks for the same ones (32
// wavelengths of a multi-coated double Gauss: about 260,000 stack evaluations).
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "optics/lens_system.h"

namespace objektiv {

class CoatingTables {
 public:
  static constexpr int kColumns = 257;
  static constexpr double kIntervalTolerance = 2e-5;
  CoatingTables(const LensSystem& lens, std::span<const double> wavelengths);
  // Tables for `lens` at `wavelengths`: one made earlier that fits it (Fits), or made now and
  // kept (the last kShared of them, for every thread).
  static constexpr size_t kShared = 4;
  static std::shared_ptr<const CoatingTables> Shared(const LensSystem& lens, std::span<const double> wavelengths);

  // Whether these tables answer for `lens` at `wavelengths` (its coated interfaces are these).
  bool Fits(const LensSystem& lens, std::span<const double> wavelengths) const;
  // Whether surface i has a table (it is coated).
  bool Has(int surface) const { return offset_[size_t(surface)] >= 0; }
  // Surface i's reflectance for light travelling toward the film or toward the object, at
  // wavelength number `band` (of those given), at cos(incidence) cos_i (clamped to [0, 1]).
  double Reflectance(int surface, bool toward_film, int band, double cos_i) const;
  std::span<const double> wavelengths() const { return wavelengths_; }

 private:
  struct Interface {
    CoatedInterface coated;
    bool faces_object;  // LensSystem::CoatingFacesObject
  };
  std::vector<double> wavelengths_;
  std::vector<std::optional<Interface>> interfaces_;  // per surface: none where bare
  std::vector<long> offset_;  // per surface: its first table in values_, -1 where bare
  std::vector<float> values_;  // per coated surface: [toward film, toward object][band][column]
  std::vector<uint8_t> exact_;  // the same, per interval (from its column to the next): 1 where the stack answers
};

}  // namespace objektiv
