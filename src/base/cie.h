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

// CIE standard illuminant D65 relative spectral power (100 at 560 nm), 10 nm table.
float D65Raw(float lambda);
// Planck's law: spectral radiance of a blackbody at temperature T (K), lambda in nm, W/(m^2 sr nm).
double Blackbody(double lambda_nm, double temperature_k);

}  // namespace objektiv
