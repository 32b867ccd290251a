// What the lens harnesses do with a prescription that a reader accepted: check that it is a
// lens the tracers can take (every number finite, indices at least 1: a reader that lets
// anything else through gives silently wrong lenses), then compute its first-order data,
// set it up at its paraxial focus and trace a few real rays, as `objektiv lens info` does.
#pragma once
#include "optics/lens_prescription.h"

namespace objektiv::fuzz {

void ExerciseLens(const LensPrescription& lens);

}  // namespace objektiv::fuzz
