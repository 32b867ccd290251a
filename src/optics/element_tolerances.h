// Decentre and tilt tolerances: one lens as a production line builds it. Each element (a run of
// surfaces with glass between them, from one air gap to the next: a singlet, a cemented group)
// is moved as a rigid body about its first vertex by a random decentre, uniform over the disc
// of radius `decenter_mm`, and a random tilt, its angle uniform in [0, tilt_deg] about an axis
// of random direction across the lens's axis. The draws come from `seed`: the same seed gives
// the same lens; another seed another copy within the same tolerances. A stop in air is no
// element and stays on the axis. The moves compose with the surfaces' own placements.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "optics/lens_prescription.h"

namespace objektiv {

struct ElementTolerances {
  double decenter_mm = 0, tilt_deg = 0;
  uint64_t seed = 1;
  bool Any() const { return decenter_mm > 0 || tilt_deg > 0; }
};

// The elements: [first, last] surface indices of each run of surfaces joined by glass.
std::vector<std::pair<size_t, size_t>> LensElements(const LensPrescription& lens);

// The lens with every element moved by its draw (see above).
LensPrescription WithToleranceSample(const LensPrescription& lens, const ElementTolerances& tolerances);

}  // namespace objektiv
