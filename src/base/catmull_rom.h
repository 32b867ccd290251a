// Catmull-Rom interpolation on evenly spaced samples: the cubic between samples k and k+1 whose
// slopes there are the central differences of the samples around. It passes through every
// sample and reproduces quadratics exactly; where a sample one past either end is needed, it
// is extrapolated quadratically from the three inside (CatmullRomSample), which keeps
// quadratics exact up to the ends.
#pragma once

namespace objektiv {

// The weights of samples k-1, k, k+1, k+2 at fraction f in [0, 1] of the interval from k.
inline void CatmullRomWeights(double f, double w[4]) {
  const double f2 = f * f, f3 = f2 * f;
  w[0] = 0.5 * (-f3 + 2 * f2 - f);
  w[1] = 0.5 * (3 * f3 - 5 * f2 + 2);
  w[2] = 0.5 * (-3 * f3 + 4 * f2 + f);
  w[3] = 0.5 * (f3 - f2);
}

// Sample k of `count` (at least 3) given by at(i) for i in [0, count), extended by one on either
// side: at(-1) = 3 at(0) - 3 at(1) + at(2), and likewise past the last.
template <typename T, typename At>
T CatmullRomSample(int k, int count, const At& at) {
  if (k < 0) return at(0) * 3.0 - at(1) * 3.0 + at(2);
  if (k >= count) return at(count - 1) * 3.0 - at(count - 2) * 3.0 + at(count - 3);
  return at(k);
}

}  // namespace objektiv
