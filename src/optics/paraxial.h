// First-order (paraxial) optics of a prescription, by y-nu ray tracing at one wavelength.
#pragma once
#include "optics/lens_prescription.h"

namespace objektiv {

struct ParaxialData {
  double efl = 0;  // effective focal length, mm
  double bfl = 0;  // back focal length: last vertex to the paraxial focus, mm
  double ffl = 0;  // front focal length: first vertex to the front focus (negative: in front), mm
};

// Object at infinity. Surfaces are refracted with their indices at lambda_nm.
ParaxialData ComputeParaxial(const LensPrescription& lens, double lambda_nm = 587.5618);

}  // namespace objektiv
