#include "optics/lens_prescription.h"

#include <cmath>

namespace objektiv {

void LensSurface::SetCurvature(double c) {
  flat = !std::isfinite(1 / c);
  radius = flat ? 0 : 1 / c;
}

int LensPrescription::StopIndex() const {
  for (size_t i = 0; i < surfaces.size(); ++i)
    if (surfaces[i].is_stop) return int(i);
  return -1;
}

double LensPrescription::TotalTrack() const {
  double t = 0;
  for (size_t i = 0; i + 1 < surfaces.size(); ++i) t += surfaces[i].thickness;
  return t;
}

}  // namespace objektiv
