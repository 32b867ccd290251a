// A thin dielectric sheet: each face reflects Fresnel's R; light that enters bounces between the
// faces, leaving by either side at every bounce, so the sheet reflects
// R + (1-R)^2 R / (1 - R^2) = 2R / (1 + R) and transmits (1 - R) / (1 + R) (no absorption).
// Reflection or transmission is chosen by the reflectance averaged over the wavelengths.
#include "scene/bxdf.h"
#include "scene/fresnel.h"

namespace objektiv {

SampledSpectrum ThinDielectricBxDF::Reflectance(float cos_o) const {
  SampledSpectrum r;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    const float face = eta[i] == 1 ? 0.f : FresnelDielectric(cos_o, eta[i]);
    r[i] = 2 * face / (1 + face);
  }
  return r;
}

std::optional<BSDFSample> ThinDielectricBxDF::Sample(const Vec3f& wo, float uc, Vec2f) const {
  const float cos_o = AbsCosTheta(wo);
  if (cos_o == 0) return std::nullopt;
  const SampledSpectrum R = Reflectance(cos_o), T = SampledSpectrum(1.f) - R;
  const float p_reflect = R.Average();
  if (uc < p_reflect) return BSDFSample{reflect_scale * R / cos_o, Vec3f(-wo.x, -wo.y, wo.z), p_reflect, kReflection | kSpecular};
  return BSDFSample{transmit_scale * T / cos_o, -wo, 1 - p_reflect, kTransmission | kSpecular};
}

}  // namespace objektiv
