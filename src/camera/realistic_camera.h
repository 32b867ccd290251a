// The realistic camera: rays start on the sensor and are traced exactly through every surface
// of a lens prescription (per wavelength, with each glass's dispersion, Fresnel losses and
// absorption), aimed only where light can pass (the pupil bounds), and weighted with the
// sensor's irradiance geometry, so that all vignetting and aberrations appear by themselves.
#pragma once
#include "camera/lens_camera.h"
#include "camera/lens_effects.h"
#include "optics/batch_tracer.h"
#include "optics/pupil_bounds.h"

namespace objektiv {

class RealisticCamera final : public LensCamera {
 public:
  // `tracer`: the lens with its stop set and focused (the film at its place).
  RealisticCamera(const Transform& to_world, int width, int height, const LensSystem& lens,
                  const LensCameraSettings& settings);
  std::optional<CameraRay> GenerateRay(const CameraSample& s, SampledWavelengths& lambda) const override;
  void GenerateRays(std::span<const CameraSample> samples, std::span<SampledWavelengths> lambdas,
                    std::span<std::optional<CameraRay>> out, CameraRayCount& count) const override;
  // Through a point of the front element chosen uniformly (optics/front_element.h), traced
  // exactly to the film at the hero wavelength (the others terminated where the camera rays
  // carry the hero alone), with the lens's transmittance and the aperture mask. Follows
  // `vignetting` full and optical; with natural and none the rims still clip.
  std::optional<CameraImportance> SampleImportance(const Vec3f& p, Vec2f u, SampledWavelengths& lambda) const override;
  bool HasImportance() const override { return true; }
  const PupilBounds& bounds() const { return bounds_; }
  // The lens as set up (stop, focus, coatings): what the flare passes trace.
  const LensSystem& lens() const { return lens_; }
  // Ghosts and diffraction, when asked for.
  const LensEffects& effects() const { return effects_; }
  void SetEffects(const LensEffects& e) { effects_ = e; }
  // The working f-number (paraxial: the exit pupil's distance from the film over its
  // diameter), which scales the diffraction pattern.
  double WorkingFNumber() const;
  bool dispersive() const { return dispersive_; }

 private:
  // The ray from the sample's film point toward its pupil sample (weight in `weight`);
  // false where no light reaches that film point.
  // `spectral`: the sample's wavelengths all go on (spectral MIS); else through dispersive
  // glass the hero alone.
  bool StartRay(const CameraSample& s, SampledWavelengths& lambda, FloatRay& ray, float& weight, Vec2d& aim,
                double& pdf, bool spectral) const;
  CameraRay Finish(const FloatRay& ray, float weight) const;
  // Spectral MIS (camera/spectral_mis.h). A hero ray that got through: its place in the traced
  // batch, its sample, film point, aim point and the density it was aimed with, and the
  // aperture mask's transmittance for it.
  struct MisHero {
    size_t j;
    uint32_t sample;
    Vec2d film, aim;
    double pdf;
    float mask;
  };
  // For each hero, its sample's terms: the hero's from its own trace, the other wavelengths'
  // by tracing its world ray back into the lens at each (realistic_camera_spectral.cpp).
  void SpectralTerms(const RayBatch& batch, std::span<const MisHero> heroes, std::span<const SampledWavelengths> lambdas,
                     std::vector<SpectralMisTerms>& terms) const;
  // A technique's parts for the ray from film point x to aim point u, which the pupil bound
  // samples with density `pdf`: s / c(x) over G, and pdf over G (camera/spectral_mis.h).
  struct Technique {
    float scale, density;
  };
  Technique TechniqueAt(Vec2d x, Vec2d u, double pdf) const;
  // The weights of a sample's wavelengths whose copies (one per wavelength, alike but for it)
  // the batch traced at `first`.
  SampledSpectrum PerWavelengthWeight(const RayBatch& batch, size_t first, float weight) const;

  LensSystem lens_;
  LensEffects effects_;
  BatchLensTracer fast_;
  PupilBounds bounds_;
  double film_z_;
  float stop_radius_;  // for the aperture mask
  bool dispersive_;  // each camera ray carries its hero wavelength only: each takes its own path
  bool birefringent_;  // a crystal in the lens: each ray chooses its waves (LensRay::wave_choices)
  // Without dispersion every wavelength of a sample takes one path, but coatings and absorbing
  // glass (a colour filter) transmit each differently: the ray is traced once for each of the
  // sample's wavelengths, for its transmittance (the hero's alone would leave colour noise).
  bool per_wavelength_transmittance_;
};

}  // namespace objektiv
