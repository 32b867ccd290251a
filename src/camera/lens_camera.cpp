#include "camera/lens_camera.h"

#include <cmath>

namespace objektiv {

LensCamera::LensCamera(const Transform& to_world, int width, int height, const LensCameraSettings& settings)
    : Camera(to_world, width, height), settings_(settings), mm_to_units_(1e-3 / settings.metres_per_unit),
      weight_scale_(float(4 / M_PI * settings.exposure_scale)) {
  SetOriginZ(0);
}

void LensCamera::SetOriginZ(double z) {
  origin_z_ = z;
  const auto& m = to_world_.Matrix().m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      dir_[3 * r + c] = float(m[r][c]);
      point_[3 * r + c] = float(m[r][c] * mm_to_units_);
    }
  // Camera-space origin at lens z: (x, y, z) -> (x, y, z_origin - z) mm.
  Vec3d o = to_world_.Point(Vec3d(0, 0, z * mm_to_units_));
  offset_ = Vec3f(float(o.x), float(o.y), float(o.z));
  // A rotation times a uniform scale (the usual lookat) stretches every direction alike: the
  // world direction's length is then known without a square root.
  double s2[3], dots = 0;
  for (int c = 0; c < 3; ++c) s2[c] = m[0][c] * m[0][c] + m[1][c] * m[1][c] + m[2][c] * m[2][c];
  for (int a = 0; a < 3; ++a)
    for (int b = a + 1; b < 3; ++b) dots += std::abs(m[0][a] * m[0][b] + m[1][a] * m[1][b] + m[2][a] * m[2][b]);
  bool uniform = std::abs(s2[1] - s2[0]) < 1e-9 * s2[0] && std::abs(s2[2] - s2[0]) < 1e-9 * s2[0] && dots < 1e-9 * s2[0];
  dir_scale_ = uniform ? float(std::sqrt(s2[0])) : 0.f;
}

double LensCamera::FilmRadius() const {
  return std::hypot(settings_.sensor_width / 2, settings_.sensor_height / 2) +
         std::hypot(settings_.shift.x, settings_.shift.y);
}

Vec3d LensCamera::LensSpacePoint(const Vec3f& world) const {
  // Camera space (scene units) = mm_to_units (x, y, origin_z - z).
  const Vec3d c = to_world_.Inverse().Point(Vec3d(world.x, world.y, world.z));
  return {c.x / mm_to_units_, c.y / mm_to_units_, origin_z_ - c.z / mm_to_units_};
}

Vec3d LensCamera::LensSpaceDirection(const Vec3f& world) const {
  const Vec3f c = to_world_.Inverse().Vector(world);
  return Normalize(Vec3d(c.x, c.y, -c.z));
}

Vec2d LensCamera::PixelOf(Vec2d film) const {
  return {((film.x - settings_.shift.x) / settings_.sensor_width + 0.5) * width_,
          ((film.y + settings_.shift.y) / settings_.sensor_height + 0.5) * height_};
}

Vec2d LensCamera::FilmPoint(Vec2f p) const {
  // Image right (camera -x) is imaged onto lens +x, image top (+y) onto -y. A lens shifted
  // right / up moves the axis to -x / +y relative to the film.
  double x = (p.x / width_ - 0.5) * settings_.sensor_width, y = (p.y / height_ - 0.5) * settings_.sensor_height;
  return {x + settings_.shift.x, y - settings_.shift.y};
}

float LensCamera::Weight(Vec2d film, double cos_theta, double dz, double pdf) const {
  float c2 = float(cos_theta * cos_theta), z2 = float(dz * dz);
  float w = weight_scale_ * c2 * c2 / (z2 * float(pdf));
  return w / float(ChiefRayFactor(film, dz));
}

double LensCamera::ChiefRayFactor(Vec2d film, double dz) const {
  if (!(settings_.vignetting == Vignetting::kOptical || settings_.vignetting == Vignetting::kNone)) return 1;
  const double z2 = dz * dz, chief2 = z2 / (z2 + film.x * film.x + film.y * film.y);  // cos^2 of the chief ray
  return chief2 * chief2;
}

Ray LensCamera::WorldRay(Vec3d o, Vec3d d) const {
  auto apply = [](const std::array<float, 9>& a, float x, float y, float z) {
    return Vec3f(a[0] * x + a[1] * y + a[2] * z, a[3] * x + a[4] * y + a[5] * z, a[6] * x + a[7] * y + a[8] * z);
  };
  Ray r;
  r.o = apply(point_, float(o.x), float(o.y), float(-o.z)) + offset_;
  Vec3f dw = apply(dir_, float(d.x), float(d.y), float(-d.z));
  float scale = dir_scale_ > 0 ? dir_scale_ : Length(dw);
  r.d = dw / scale;
  r.tmax = settings_.far_clip * scale;
  return r;
}

}  // namespace objektiv
