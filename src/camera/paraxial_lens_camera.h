// Ideal (first-order) cameras built from a prescription's paraxial data, to compare with the
// real lens: the thick lens (its focal length, principal planes and pupils, imaging every
// film point perfectly onto its conjugate) and the thin lens (the same focal length and
// f-number with both principal planes and both pupils in one plane). Both are focused at the
// same distance from the film as the real lens, have no aberrations and no optical
// vignetting; their radiometry is the same as the realistic camera's.
#pragma once
#include "camera/lens_camera.h"
#include "optics/lens_tracer.h"

namespace objektiv {

struct ParaxialLensModel {
  double efl = 0;
  double front_principal_z = 0, back_principal_z = 0;  // lens space, mm
  double entrance_pupil_z = 0, entrance_pupil_radius = 0;
  double exit_pupil_z = 0, exit_pupil_radius = 0;
  double film_z = 0;
};

// From the lens with its stop set; the film where the paraxial image of an object at
// `distance_from_film` mm lies (infinity allowed). `thin` collapses the lens to one plane.
ParaxialLensModel MakeParaxialModel(const LensSystem& lens, double distance_from_film, bool thin);

class ParaxialLensCamera final : public LensCamera {
 public:
  // `stop`: the opening laid over the exit pupil (its iris is sampled; an aperture mask, in the
  // settings, weights the light).
  ParaxialLensCamera(const Transform& to_world, int width, int height, const ParaxialLensModel& model,
                     const StopShape& stop, const LensCameraSettings& settings);
  std::optional<CameraRay> GenerateRay(const CameraSample& s, SampledWavelengths& lambda) const override;
  const ParaxialLensModel& model() const { return m_; }

 private:
  ParaxialLensModel m_;
  StopShape stop_;
};

}  // namespace objektiv
