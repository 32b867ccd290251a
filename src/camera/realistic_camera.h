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
  bool StartRay(const CameraSample& s, SampledWavelengths& lambda, FloatRay& ray, float& weight) const;
  CameraRay Finish(const FloatRay& ray, float weight) const;
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
