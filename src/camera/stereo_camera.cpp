#include "camera/stereo_camera.h"

#include <cmath>
#include <vector>

#include "base/rng.h"

namespace objektiv {

namespace {
// A world length per camera-space unit along a camera axis.
double AxisScale(const Transform& to_world, Vec3f axis) { return double(Length(to_world.Vector(axis))); }
}  // namespace

Transform EyeTransform(const Transform& to_world, double offset_units) {
  return to_world * Transform::Translate(Vec3d(offset_units / AxisScale(to_world, Vec3f(1, 0, 0)), 0, 0));
}

float EyeFrustumShift(const Transform& to_world, double offset_units, double convergence_units) {
  // In the eye's camera space the convergence point lies at x = -offset, z = convergence: the
  // frustum is shifted so that its direction, x / z, is the image's centre.
  const double x = -offset_units / AxisScale(to_world, Vec3f(1, 0, 0));
  const double z = convergence_units / AxisScale(to_world, Vec3f(0, 0, 1));
  return float(x / z);
}

Transform OrthographicEyeTransform(const Transform& to_world, double offset_units, double convergence_units) {
  // World axes of the camera (to_world may scale them unequally, as an orthographic camera's
  // often does: the turn is made in the world, where it is a rotation).
  const Vec3f x = Normalize(to_world.Vector(Vec3f(1, 0, 0)));
  const Vec3f y = Normalize(to_world.Vector(Vec3f(0, 1, 0)));
  const Vec3f z = Normalize(to_world.Vector(Vec3f(0, 0, 1)));
  const Vec3f o = to_world.Point(Vec3f(0.f));
  const Vec3f pivot = o + z * float(convergence_units);
  // The left eye (offset > 0, at +x) looks toward -x: a turn that takes z toward -x.
  double angle = -std::atan(offset_units / convergence_units) * 180 / M_PI;
  const Vec3f turned = Transform::Rotate(1, Vec3d(y.x, y.y, y.z)).Vector(z);
  if (Dot(turned, x) < 0) angle = -angle;  // the rotation's sense in this frame's handedness
  const Vec3d p(pivot.x, pivot.y, pivot.z);
  return Transform::Translate(p) * Transform::Rotate(angle, Vec3d(y.x, y.y, y.z)) * Transform::Translate(-p) * to_world;
}

StereoCamera::StereoCamera(std::unique_ptr<Camera> left, std::unique_ptr<Camera> right, StereoLayout layout)
    : Camera(Transform(), layout == StereoLayout::kOverUnder ? left->width() : 2 * left->width(),
             layout == StereoLayout::kOverUnder ? 2 * left->height() : left->height()),
      left_(std::move(left)), right_(std::move(right)), layout_(layout) {}

Vec2i StereoCamera::EyeOrigin(int i) const {
  if (i == 0) return {0, 0};
  return layout_ == StereoLayout::kOverUnder ? Vec2i(0, left_->height()) : Vec2i(left_->width(), 0);
}

int StereoCamera::EyeOf(Vec2i pixel) const {
  return layout_ == StereoLayout::kOverUnder ? int(pixel.y >= left_->height()) : int(pixel.x >= left_->width());
}

int StereoCamera::Split(const CameraSample& s, CameraSample& local) const {
  const Vec2i pixel =
      s.pixel.x >= 0 ? s.pixel : Vec2i(int(std::floor(s.p_film.x)), int(std::floor(s.p_film.y)));
  const int eye = EyeOf(pixel);
  const Vec2i o = EyeOrigin(eye);
  local = s;
  local.p_film = Vec2f(s.p_film.x - float(o.x), s.p_film.y - float(o.y));
  local.pixel = Vec2i(pixel.x - o.x, pixel.y - o.y);
  return eye;
}

std::optional<CameraRay> StereoCamera::GenerateRay(const CameraSample& s, SampledWavelengths& lambda) const {
  CameraSample local;
  const int e = Split(s, local);
  return eye(e).GenerateRay(local, lambda);
}

void StereoCamera::GenerateRays(std::span<const CameraSample> samples, std::span<SampledWavelengths> lambdas,
                                std::span<std::optional<CameraRay>> out, CameraRayCount& count) const {
  // Per eye: the samples, their wavelengths (a lens may keep only the hero) and rays.
  thread_local std::vector<CameraSample> local[2];
  thread_local std::vector<SampledWavelengths> lambda[2];
  thread_local std::vector<std::optional<CameraRay>> rays[2];
  thread_local std::vector<size_t> index[2];
  for (int e = 0; e < 2; ++e) local[e].clear(), lambda[e].clear(), index[e].clear();
  for (size_t i = 0; i < samples.size(); ++i) {
    CameraSample ls;
    const int e = Split(samples[i], ls);
    local[e].push_back(ls);
    lambda[e].push_back(lambdas[i]);
    index[e].push_back(i);
  }
  for (int e = 0; e < 2; ++e) {
    if (local[e].empty()) continue;
    rays[e].assign(local[e].size(), std::nullopt);
    eye(e).GenerateRays(local[e], lambda[e], rays[e], count);
    for (size_t j = 0; j < index[e].size(); ++j) {
      out[index[e][j]] = rays[e][j];
      lambdas[index[e][j]] = lambda[e][j];
    }
  }
}

std::optional<CameraImportance> StereoCamera::SampleImportance(const Vec3f& p, Vec2f u,
                                                               SampledWavelengths& lambda) const {
  const int e = u.x < 0.5f ? 0 : 1;
  const Vec2f ue(std::min(e == 0 ? 2 * u.x : 2 * u.x - 1, kOneMinusEpsilon), u.y);
  std::optional<CameraImportance> imp = eye(e).SampleImportance(p, ue, lambda);
  if (!imp) return std::nullopt;
  const Vec2i o = EyeOrigin(e);
  imp->p_film = Vec2f(imp->p_film.x + float(o.x), imp->p_film.y + float(o.y));
  // x 2 for choosing the eye, x (eye's pixels / film's pixels) = 1/2 for the light paths per
  // pixel sample of the whole film: the eye's own weight.
  return imp;
}

}  // namespace objektiv
