// CIE 1931 2-degree colour matching functions and standard illuminants.
#pragma once
#include "base/vec.h"

namespace objektiv {

constexpr float kLambdaMin = 360.f, kLambdaMax = 830.f;

// Colour matching functions x-bar, y-bar, z-bar at wavelength `lambda` (nm), linearly
// interpolated from the CIE 1931 table at 10 nm; zero outside [360, 830].
Vec3f CieXyz(float lambda);
// Integral of y-bar over [360, 830] nm (the normalisation of luminance).
float CieYIntegral();
// The matching functions times `weight(lambda)` integrated over [lo, hi] nm (midpoint rule,
// steps of at most 1 nm): the colour of a band of wavelengths.
template <class Weight>
Vec3d CieXyzOverBand(double lo, double hi, Weight&& weight) {
  const int steps = hi > lo ? int(hi - lo) + 1 : 1;
  const double dl = (hi - lo) / steps;
  Vec3d sum(0.0);
  for (int j = 0; j < steps; ++j) {
    const double l = lo + (j + 0.5) * dl;
    const Vec3f c = CieXyz(float(l));
    sum += Vec3d(c.x, c.y, c.z) * (weight(l) * dl);
  }
  return sum;
}

// CIE standard illuminant D65 relative spectral power (100 at 560 nm), 10 nm table.
float D65Raw(float lambda);
// Planck's law: spectral radiance of a blackbody at temperature T (K), lambda in nm, W/(m^2 sr nm).
double Blackbody(double lambda_nm, double temperature_k);

}  // namespace objektiv
