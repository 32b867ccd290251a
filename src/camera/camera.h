// Cameras turn a film position (and lens sample) into a weighted ray in world space.
// Camera space follows Mitsuba: +z looks forward, +y is up, +x is to the left, so that
// image x grows to the right.
#pragma once
#include <cstdint>
#include <optional>
#include <span>

#include "base/sampled_spectrum.h"
#include "base/transform.h"
#include "base/ray.h"
#include "camera/spectral_mis.h"

namespace objektiv {

struct CameraSample {
  Vec2f p_film;  // continuous pixel coordinates on the full film (0..width, 0..height; y down)
  Vec2f p_lens;  // in [0,1)^2
  // The pixel whose sample this is ((-1, -1): the one under p_film). A filter wider than a pixel
  // puts samples beyond it; a camera that tiles its film (stereo) keeps them in the pixel's tile.
  Vec2i pixel{-1, -1};
  // The caller weighs the wavelengths itself where the camera gives their terms
  // (CameraRay::spectral, camera/spectral_mis.h): it knows the pixel filter.
  bool spectral_mis = false;
};

struct CameraRay {
  Ray ray;
  SampledSpectrum weight{1.f};
  // Through a dispersive lens, for a sample that asked (CameraSample::spectral_mis): the terms
  // from which the caller sets `weight` (SpectralMisWeight); the ray serves every wavelength.
  std::optional<SpectralMisTerms> spectral;
};

// The light side of a camera (camera importance, as pbrt-v4's Camera::SampleWi): light
// leaving a scene point toward the camera. A point of the camera's lens is chosen; the light
// through it lands on the film at p_film (continuous pixel coordinates of the full film), and
// light of radiant intensity J leaving the scene point toward p_lens (a light path's vertex on
// a surface: its beta f |cos|; a point light: its intensity) adds J x weight there, splatted
// (Film::AddSplat) by one light path per pixel sample of the full film. The shadow ray runs
// from the scene point to p_lens.
struct CameraImportance {
  Vec2f p_film;
  Vec3f p_lens;
  SampledSpectrum weight{0.f};
};

// Camera rays traced through a lens, and those of them that came out of its front (film
// points that no light reaches, such as outside a fisheye's image circle, trace nothing).
struct CameraRayCount {
  uint64_t traced = 0, passed = 0;
};

class Camera {
 public:
  Camera(const Transform& to_world, int width, int height) : to_world_(to_world), width_(width), height_(height) {}
  virtual ~Camera() = default;
  virtual std::optional<CameraRay> GenerateRay(const CameraSample& s, SampledWavelengths& lambda) const = 0;
  // Many rays at once (a lens camera traces them together, which is faster); out[i] is empty
  // where no light gets through.
  virtual void GenerateRays(std::span<const CameraSample> samples, std::span<SampledWavelengths> lambdas,
                            std::span<std::optional<CameraRay>> out, CameraRayCount& count) const;
  // Whether rays depend on CameraSample::p_lens; if not, the renderer does not draw it (one
  // 2D sample fewer per camera ray for pinhole and orthographic cameras).
  virtual bool UsesLensSample() const { return true; }
  // Camera importance for light at world point p (u in [0,1)^2 picks the lens point);
  // nothing where no light from p reaches the film through that point, or where the camera
  // cannot be reached from the light side.
  virtual std::optional<CameraImportance> SampleImportance(const Vec3f& /*p*/, Vec2f /*u*/,
                                                           SampledWavelengths& /*lambda*/) const {
    return std::nullopt;
  }
  // Whether SampleImportance can find this camera at all (light tracing needs it).
  virtual bool HasImportance() const { return false; }
  int width() const { return width_; }
  int height() const { return height_; }
  const Transform& to_world() const { return to_world_; }
  // The same camera moved to another place in the world (the interactive viewer's orbit and
  // fly): its lens, focus and film stay as set up. False for a camera that cannot be moved so
  // (a stereo rig, whose eyes' places follow from its own; build it again instead).
  virtual bool MoveTo(const Transform& to_world) {
    to_world_ = to_world;
    return true;
  }

 protected:
  Transform to_world_;
  int width_, height_;
};

// How a field of view is measured (Mitsuba's fov_axis).
enum class FovAxis { kX, kY, kDiagonal, kSmaller, kLarger };

// tan(fov/2) along x and y for a film of width x height pixels.
Vec2f ScreenTangents(float fov_deg, FovAxis axis, int width, int height);

class PerspectiveCamera : public Camera {
 public:
  PerspectiveCamera(const Transform& to_world, int width, int height, float fov_deg, FovAxis axis, float near_clip,
                    float far_clip);
  std::optional<CameraRay> GenerateRay(const CameraSample& s, SampledWavelengths& lambda) const override;
  bool UsesLensSample() const override { return false; }
  // The pinhole's importance (u unused): light from p through the pinhole lands where its ray
  // crosses the film; weight 1 / (r^2 cos^3 theta A), r the distance, theta the ray's angle to
  // the view axis, A the film's area on the plane at unit distance (the camera rays' weight is
  // 1: the image is radiance).
  std::optional<CameraImportance> SampleImportance(const Vec3f& p, Vec2f u, SampledWavelengths& lambda) const override;
  bool HasImportance() const override { return true; }
  // An off-axis frustum (a stereo eye's, camera/stereo_camera.h): the image's window on the
  // plane at unit distance moved by `shift` (camera-space x, y), as a shift lens moves it.
  void ShiftFrustum(Vec2f shift) { shift_ = shift; }

 protected:
  // Direction in camera space through film point p (not normalised; z = 1).
  Vec3f CameraDirection(Vec2f p_film) const;
  // The film point whose direction is d (camera space, d.z > 0), if it lies on the film.
  std::optional<Vec2f> FilmPoint(const Vec3f& d) const;
  // The importance of light from camera-space point p through camera-space lens point
  // p_lens (z = 0) landing at film point p_film: the pinhole's weight with the ray from the
  // lens point (a thin lens's rays from each of its points see the film as the pinhole does).
  std::optional<CameraImportance> ImportanceThrough(const Vec3f& p, const Vec3f& p_lens, Vec2f p_film) const;
  Vec2f tan_;
  Vec2f shift_{0.f, 0.f};
  float near_, far_;
};

// Thin lens: a circular or n-bladed aperture of radius `aperture_radius` (scene units) and a
// plane in focus at `focus_distance`.
class ThinLensCamera final : public PerspectiveCamera {
 public:
  ThinLensCamera(const Transform& to_world, int width, int height, float fov_deg, FovAxis axis, float near_clip,
                 float far_clip, float aperture_radius, float focus_distance, int blades, float blade_rotation_deg);
  std::optional<CameraRay> GenerateRay(const CameraSample& s, SampledWavelengths& lambda) const override;
  bool UsesLensSample() const override { return aperture_radius_ > 0; }
  // A lens point chosen uniformly over the aperture (by u); the film point whose rays through
  // the lens meet on the focus plane where the ray from p through the lens point does; the
  // pinhole's weight for the ray from the lens point (the aperture's area cancels against the
  // lens point's density).
  std::optional<CameraImportance> SampleImportance(const Vec3f& p, Vec2f u, SampledWavelengths& lambda) const override;

 private:
  float aperture_radius_, focus_distance_;
  int blades_;
  float blade_rotation_;
};

// Parallel projection of camera-space [-1,1] x [-1/aspect, 1/aspect] (scaled by to_world).
class OrthographicCamera final : public Camera {
 public:
  OrthographicCamera(const Transform& to_world, int width, int height, float near_clip, float far_clip);
  std::optional<CameraRay> GenerateRay(const CameraSample& s, SampledWavelengths& lambda) const override;
  bool UsesLensSample() const override { return false; }

 private:
  float near_, far_;
};

}  // namespace objektiv
