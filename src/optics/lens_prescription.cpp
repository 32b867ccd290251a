#include "optics/lens_prescription.h"

#include <cmath>

#include "base/error.h"

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

void CheckReachable(const LensSurface& s, const std::string& path, int line) {
  double c = s.Curvature();
  if (c == 0 || s.conic <= -1) return;
  double limit = 1 / (std::abs(c) * std::sqrt(1 + s.conic));
  if (s.semi_diameter > limit)
    throw MakeInputError(path, line, "semi-diameter {} is larger than the surface can reach ({:.4g})", s.semi_diameter, limit);
}

}  // namespace objektiv
