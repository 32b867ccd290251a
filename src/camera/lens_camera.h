// What every camera with a lens prescription shares (the realistic camera and the thin- and
// thick-lens cameras built from the same prescription's paraxial data): the sensor, the
// mapping between lens space and the world, and the radiometric weight of a camera ray.
//
// Lens space: millimetres, z along the axis toward the film (the lens library's). Camera
// space: the origin at the lens's entrance pupil, +z looking out of the lens, +y up, +x left
// (as the other cameras); one scene unit is `metres_per_unit` metres.
#pragma once
#include <array>
#include <memory>

#include "camera/aperture_mask.h"
#include "camera/camera.h"

namespace objektiv {

// Which of the two kinds of vignetting the image keeps (to compare them).
enum class Vignetting {
  kFull,     // natural (cos^4) and optical (the pupil cut by the rims), as a real lens
  kNatural,  // cos^4 only: the rims do not clip (only the stop does)
  kOptical,  // the effective aperture only: the cos^4 of the chief ray divided out
  kNone,     // neither
};

struct LensCameraSettings {
  double sensor_width = 36, sensor_height = 24;  // mm: the rectangle the image covers
  Vec2d shift{0, 0};           // lens shift, mm (+x right, +y up as the photographer sees it)
  double metres_per_unit = 1;  // size of one scene unit
  // Pixel value = exposure_scale x (4 / pi) x sensor irradiance: a perfect lens at f/1
  // records the scene's radiance on the axis, and each stop closed halves the value.
  double exposure_scale = 1;
  Vignetting vignetting = Vignetting::kFull;
  bool transmission = true;  // Fresnel losses and glass absorption (real lens only)
  // Through dispersive glass, every wavelength of a sample weighed by spectral MIS
  // (camera/spectral_mis.h); false: the hero alone (pbrt-v4's way, more colour noise).
  bool spectral_mis = true;
  float far_clip = 1e4;      // scene units
  std::shared_ptr<const ApertureMask> aperture_mask;  // over the stop; null: none
};

class LensCamera : public Camera {
 public:
  LensCamera(const Transform& to_world, int width, int height, const LensCameraSettings& settings);
  // Largest distance from the axis of a film point the image uses (mm).
  double FilmRadius() const;

  // The light side of the mapping (what light arriving at the lens needs: flare, light
  // paths). A world point in lens space (mm), and a world direction of travel as a unit
  // lens-space direction.
  Vec3d LensSpacePoint(const Vec3f& world) const;
  Vec3d LensSpaceDirection(const Vec3f& world) const;
  // A lens-space point (mm) in the world.
  Vec3f WorldPoint(Vec3d lens) const { return WorldRay(lens, Vec3d(0, 0, -1)).o; }
  // The continuous pixel position (full film) of a lens-space film point: FilmPoint's inverse.
  Vec2d PixelOf(Vec2d film) const;
  // The film pixel's size (mm) and the film point of pixel coordinates (0, 0).
  Vec2d PixelSize() const { return {settings_.sensor_width / width_, settings_.sensor_height / height_}; }
  Vec2d FilmOrigin() const { return {-settings_.sensor_width / 2 + settings_.shift.x, -settings_.sensor_height / 2 - settings_.shift.y}; }
  const LensCameraSettings& settings() const { return settings_; }
  bool MoveTo(const Transform& to_world) override {
    to_world_ = to_world;
    SetOriginZ(origin_z_);  // the lens-space to world mapping, from the new place
    return true;
  }

 protected:
  // The lens-space film point (mm from the axis) for a continuous pixel position. The image
  // comes out upright: the film point is the pixel's point reflected through the axis.
  Vec2d FilmPoint(Vec2f p_film) const;
  // The camera weight of a ray from a film point toward a point on the pupil plane `dz` mm in
  // front of the film, sampled with `pdf` per mm^2 there: (4/pi) scale cos^4 / (dz^2 pdf),
  // without the cos^4 of the chief ray (toward the pupil's centre) when natural vignetting
  // is off.
  float Weight(Vec2d film, double cos_theta, double dz, double pdf) const;
  // The chief ray's cos^4 that Weight divides out (1 where natural vignetting is kept).
  double ChiefRayFactor(Vec2d film, double dz) const;
  // The world ray for a ray leaving the lens at lens-space `o` in direction `d` (d.z < 0).
  Ray WorldRay(Vec3d o, Vec3d d) const;
  // Lens-space z of the camera-space origin (the entrance pupil).
  void SetOriginZ(double z);

  LensCameraSettings settings_;

 private:
  // Lens space to world, affine, in single precision: p = point_ (x, y, -z) + offset_,
  // d = dir_ (dx, dy, -dz) (the to_world matrix, scaled by mm_to_units_ for points).
  std::array<float, 9> point_{}, dir_{};
  Vec3f offset_;
  float dir_scale_ = 0;  // |dir_ d| for every unit d, when the same for all (else 0)
  double mm_to_units_;
  double origin_z_ = 0;  // lens-space z of the camera-space origin
  float weight_scale_;  // (4 / pi) exposure_scale
};

}  // namespace objektiv
