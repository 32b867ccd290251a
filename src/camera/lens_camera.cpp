#include "camera/lens_camera.h"

#include <cmath>

namespace objektiv {

LensCamera::LensCamera(const Transform& to_world, int width, int height, const LensCameraSettings& settings)
    : Camera(to_world, width, height), settings_(settings), mm_to_units_(1e-3 / settings.metres_per_unit) {}

double LensCamera::FilmRadius() const {
  return std::hypot(settings_.sensor_width / 2, settings_.sensor_height / 2) +
         std::hypot(settings_.shift.x, settings_.shift.y);
}

Vec2d LensCamera::FilmPoint(Vec2f p) const {
  // Image right (camera -x) is imaged onto lens +x, image top (+y) onto -y. A lens shifted
  // right / up moves the axis to -x / +y relative to the film.
  double x = (p.x / width_ - 0.5) * settings_.sensor_width, y = (p.y / height_ - 0.5) * settings_.sensor_height;
  return {x + settings_.shift.x, y - settings_.shift.y};
}

float LensCamera::Weight(Vec2d film, double cos_theta, double dz, double pdf) const {
  double c2 = cos_theta * cos_theta;
  double w = (4 / M_PI) * settings_.exposure_scale * c2 * c2 / (dz * dz * pdf);
  if (settings_.vignetting == Vignetting::kOptical || settings_.vignetting == Vignetting::kNone) {
    double chief2 = dz * dz / (dz * dz + film.x * film.x + film.y * film.y);  // cos^2 of the chief ray
    w /= chief2 * chief2;
  }
  return float(w);
}

Ray LensCamera::WorldRay(Vec3d o, Vec3d d) const {
  Vec3f oc(float(o.x * mm_to_units_), float(o.y * mm_to_units_), float((origin_z_ - o.z) * mm_to_units_));
  Vec3f dc(float(d.x), float(d.y), float(-d.z));
  Ray r;
  r.o = to_world_.Point(oc);
  Vec3f dw = to_world_.Vector(dc);
  float scale = Length(dw);
  r.d = dw / scale;
  r.tmax = settings_.far_clip * scale;
  return r;
}

}  // namespace objektiv
