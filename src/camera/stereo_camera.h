// A stereo rig: two cameras of one kind (any: pinhole, thin lens, orthographic, a real lens),
// the eyes, sharing one film. Side by side the film is 2W x H with the left eye's image on the
// left half; over-under it is W x 2H with the left eye's on top (the usual layouts of stereo
// displays and players). An anaglyph is rendered side by side and combined at the end
// (io/anaglyph.h).
//
// The eyes are the rig's camera moved by +-separation/2 along its x axis (+x is the camera's
// left: the left eye sits at +separation/2). How each kind of camera makes the zero-parallax
// plane (off-axis frusta) is in StereoEye; the sensor plugins build the eyes from it.
#pragma once
#include <memory>

#include "camera/camera.h"

namespace objektiv {

// One eye of a rig, as a sensor plugin builds it: the offset along the camera's x axis
// (metres; +: left) and the distance of the plane on which both eyes' images coincide (metres
// from the camera's origin; 0 for parallel frusta, no shift).
struct StereoEye {
  double offset = 0;
  double convergence = 0;
  bool OffAxis() const { return convergence > 0; }
};

// The eye's place: the rig's to_world moved by `offset_units` (scene units) along the camera's x
// axis (measured in the world, so that a scaled to_world moves the eye by that length).
Transform EyeTransform(const Transform& to_world, double offset_units);
// The pinhole's and the thin lens's off-axis frustum: the tangent shift that puts the point on
// the rig's axis at `convergence_units` from the camera at the centre of the eye's image.
float EyeFrustumShift(const Transform& to_world, double offset_units, double convergence_units);
// The orthographic eye: parallel rays show no parallax when moved, so each eye turns about the
// vertical axis through the rig's axis at the convergence distance, as seen from the eye at
// `offset_units` (by atan(offset / convergence)); points on the plane through that axis at the
// convergence distance keep their place (to first order), nearer and farther ones move apart.
Transform OrthographicEyeTransform(const Transform& to_world, double offset_units, double convergence_units);

enum class StereoLayout { kSideBySide, kOverUnder, kAnaglyph };

class StereoCamera final : public Camera {
 public:
  // Both eyes of the same film size (W x H); the film is 2W x H (side by side, anaglyph) or
  // W x 2H (over-under).
  StereoCamera(std::unique_ptr<Camera> left, std::unique_ptr<Camera> right, StereoLayout layout);

  // A sample belongs to the eye of its pixel (CameraSample::pixel, else the pixel under p_film):
  // near the seam a wide filter's samples stray over it, and they look through their own eye,
  // as a mono camera's samples beyond the film's edge do.
  std::optional<CameraRay> GenerateRay(const CameraSample& s, SampledWavelengths& lambda) const override;
  // Each eye's samples together (a lens traces them in one batch), in the samples' order.
  void GenerateRays(std::span<const CameraSample> samples, std::span<SampledWavelengths> lambdas,
                    std::span<std::optional<CameraRay>> out, CameraRayCount& count) const override;
  bool UsesLensSample() const override { return left_->UsesLensSample() || right_->UsesLensSample(); }
  // One eye chosen by u.x (each with probability 1/2, u.x stretched back to [0,1) for the
  // eye's own lens point), its importance times 2 for the choice and times 1/2 since the rig's
  // film has twice the pixels an eye's has (one light path per pixel sample of the whole film):
  // the eye's own weight. The film point is moved into the eye's part of the film.
  std::optional<CameraImportance> SampleImportance(const Vec3f& p, Vec2f u, SampledWavelengths& lambda) const override;
  bool HasImportance() const override { return left_->HasImportance() && right_->HasImportance(); }
  bool MoveTo(const Transform&) override { return false; }

  StereoLayout layout() const { return layout_; }
  const Camera& eye(int i) const { return i == 0 ? *left_ : *right_; }
  // Where eye i's image starts on the film (pixels).
  Vec2i EyeOrigin(int i) const;
  // The eye (0 left, 1 right) of a film pixel.
  int EyeOf(Vec2i pixel) const;

 private:
  // The eye of a sample and the sample in that eye's film coordinates.
  int Split(const CameraSample& s, CameraSample& local) const;

  std::unique_ptr<Camera> left_, right_;
  StereoLayout layout_;
};

}  // namespace objektiv
