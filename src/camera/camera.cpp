#include "camera/camera.h"

#include <cmath>

#include "base/sampling.h"

namespace objektiv {

void Camera::GenerateRays(std::span<const CameraSample> samples, std::span<SampledWavelengths> lambdas,
                          std::span<std::optional<CameraRay>> out, CameraRayCount& count) const {
  for (size_t i = 0; i < samples.size(); ++i) {
    out[i] = GenerateRay(samples[i], lambdas[i]);
    ++count.traced;
    count.passed += out[i].has_value();
  }
}

Vec2f ScreenTangents(float fov_deg, FovAxis axis, int width, int height) {
  float t = std::tan(Radians(fov_deg) / 2);
  float w = float(width), h = float(height);
  switch (axis) {
    case FovAxis::kX:
      return {t, t * h / w};
    case FovAxis::kY:
      return {t * w / h, t};
    case FovAxis::kDiagonal: {
      float d = std::sqrt(w * w + h * h);
      return {t * w / d, t * h / d};
    }
    case FovAxis::kSmaller:
      return w <= h ? ScreenTangents(fov_deg, FovAxis::kX, width, height) : ScreenTangents(fov_deg, FovAxis::kY, width, height);
    case FovAxis::kLarger:
      return w >= h ? ScreenTangents(fov_deg, FovAxis::kX, width, height) : ScreenTangents(fov_deg, FovAxis::kY, width, height);
  }
  return {t, t};
}

PerspectiveCamera::PerspectiveCamera(const Transform& to_world, int width, int height, float fov_deg, FovAxis axis,
                                     float near_clip, float far_clip)
    : Camera(to_world, width, height), tan_(ScreenTangents(fov_deg, axis, width, height)), near_(near_clip), far_(far_clip) {}

Vec3f PerspectiveCamera::CameraDirection(Vec2f p) const {
  // Image x to the right is camera -x; image y down is camera -y.
  float sx = (1 - 2 * p.x / width_) * tan_.x + shift_.x;
  float sy = (1 - 2 * p.y / height_) * tan_.y + shift_.y;
  return {sx, sy, 1};
}

std::optional<CameraRay> PerspectiveCamera::GenerateRay(const CameraSample& s, SampledWavelengths&) const {
  Vec3f d = CameraDirection(s.p_film);
  float inv_len = 1 / Length(d);
  Vec3f dn = d * inv_len;
  // Clip planes are perpendicular to the view axis: start at z = near.
  Vec3f o_cam = d * near_;
  CameraRay cr;
  cr.ray.o = to_world_.Point(o_cam);
  cr.ray.d = Normalize(to_world_.Vector(dn));
  cr.ray.tmax = (far_ - near_) * Length(d) * Length(to_world_.Vector(dn));
  return cr;
}

std::optional<Vec2f> PerspectiveCamera::FilmPoint(const Vec3f& d) const {
  if (!(d.z > 0)) return std::nullopt;
  const float sx = d.x / d.z - shift_.x, sy = d.y / d.z - shift_.y;
  const Vec2f p((1 - sx / tan_.x) * 0.5f * width_, (1 - sy / tan_.y) * 0.5f * height_);
  if (!(p.x >= 0 && p.x < width_ && p.y >= 0 && p.y < height_)) return std::nullopt;
  return p;
}

std::optional<CameraImportance> PerspectiveCamera::ImportanceThrough(const Vec3f& p, const Vec3f& p_lens,
                                                                     Vec2f p_film) const {
  // Camera rays start on the near plane and end on the far one.
  if (!(p.z >= near_ && p.z <= far_)) return std::nullopt;
  const Vec3f d = p - p_lens;
  const float len = Length(d), cos_theta = d.z / len;
  if (!(cos_theta > 0)) return std::nullopt;
  CameraImportance out;
  out.p_film = p_film;
  out.p_lens = to_world_.Point(p_lens);
  // The distance in the world (to_world may scale); the angles are the camera's.
  const Vec3f world = to_world_.Point(p) - out.p_lens;
  const float r2 = Dot(world, world);
  const float film_area = 4 * tan_.x * tan_.y;
  out.weight = SampledSpectrum(1 / (r2 * cos_theta * cos_theta * cos_theta * film_area));
  return out;
}

std::optional<CameraImportance> PerspectiveCamera::SampleImportance(const Vec3f& p, Vec2f, SampledWavelengths&) const {
  const Vec3f p_cam = to_world_.Inverse().Point(p);
  const std::optional<Vec2f> film = FilmPoint(p_cam);
  if (!film) return std::nullopt;
  return ImportanceThrough(p_cam, Vec3f(0.f), *film);
}

ThinLensCamera::ThinLensCamera(const Transform& to_world, int width, int height, float fov_deg, FovAxis axis,
                               float near_clip, float far_clip, float aperture_radius, float focus_distance, int blades,
                               float blade_rotation_deg)
    : PerspectiveCamera(to_world, width, height, fov_deg, axis, near_clip, far_clip),
      aperture_radius_(aperture_radius), focus_distance_(focus_distance), blades_(blades),
      blade_rotation_(Radians(blade_rotation_deg)) {}

std::optional<CameraRay> ThinLensCamera::GenerateRay(const CameraSample& s, SampledWavelengths&) const {
  Vec3f d = CameraDirection(s.p_film);
  // Every ray through the lens from this film point meets the others on the focus plane.
  Vec3f p_focus = d * focus_distance_;
  Vec2f lens = blades_ >= 3 ? SampleRegularPolygon(blades_, blade_rotation_, s.p_lens) : SampleUniformDiskConcentric(s.p_lens);
  Vec3f p_lens(lens.x * aperture_radius_, lens.y * aperture_radius_, 0);
  Vec3f dir = Normalize(p_focus - p_lens);
  Vec3f o = p_lens + dir * (near_ / dir.z);
  CameraRay cr;
  cr.ray.o = to_world_.Point(o);
  Vec3f dw = to_world_.Vector(dir);
  float scale = Length(dw);
  cr.ray.d = dw / scale;
  cr.ray.tmax = (far_ - near_) / dir.z * scale;
  return cr;
}

std::optional<CameraImportance> ThinLensCamera::SampleImportance(const Vec3f& p, Vec2f u,
                                                                 SampledWavelengths& lambda) const {
  if (aperture_radius_ <= 0) return PerspectiveCamera::SampleImportance(p, u, lambda);
  const Vec3f p_cam = to_world_.Inverse().Point(p);
  const Vec2f lens = blades_ >= 3 ? SampleRegularPolygon(blades_, blade_rotation_, u) : SampleUniformDiskConcentric(u);
  const Vec3f p_lens(lens.x * aperture_radius_, lens.y * aperture_radius_, 0);
  // Where the ray from the lens point toward p meets the focus plane: the film point looks there.
  const Vec3f d = p_cam - p_lens;
  if (!(d.z > 0)) return std::nullopt;
  const Vec3f p_focus = p_lens + d * (focus_distance_ / d.z);
  const std::optional<Vec2f> film = FilmPoint(p_focus);
  if (!film) return std::nullopt;
  return ImportanceThrough(p_cam, p_lens, *film);
}

OrthographicCamera::OrthographicCamera(const Transform& to_world, int width, int height, float near_clip, float far_clip)
    : Camera(to_world, width, height), near_(near_clip), far_(far_clip) {}

std::optional<CameraRay> OrthographicCamera::GenerateRay(const CameraSample& s, SampledWavelengths&) const {
  float aspect = float(width_) / height_;
  float x = 1 - 2 * s.p_film.x / width_;
  float y = (1 - 2 * s.p_film.y / height_) / aspect;
  CameraRay cr;
  cr.ray.o = to_world_.Point(Vec3f(x, y, near_));
  Vec3f dw = to_world_.Vector(Vec3f(0, 0, 1));
  float scale = Length(dw);
  cr.ray.d = dw / scale;
  cr.ray.tmax = (far_ - near_) * scale;
  return cr;
}

}  // namespace objektiv
