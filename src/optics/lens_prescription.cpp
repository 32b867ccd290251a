#include "optics/lens_prescription.h"

namespace objektiv {

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
