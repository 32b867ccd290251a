#include "app/view/camera_pose.h"

#include <algorithm>
#include <cmath>

namespace objektiv {

namespace {

// The world axis (signed) nearest `up`, if within 45 degrees of it; else `up`.
Vec3d TurningAxis(const Vec3d& up) {
  for (int a = 0; a < 3; ++a)
    if (std::abs(up[a]) > std::sqrt(0.5)) {
      Vec3d axis(0, 0, 0);
      axis[a] = up[a] > 0 ? 1 : -1;
      return axis;
    }
  return up;
}

// v turned by `deg` degrees about the unit axis (Rodrigues).
Vec3d Turned(const Vec3d& v, const Vec3d& axis, double deg) {
  const double a = deg * M_PI / 180, c = std::cos(a), s = std::sin(a);
  return v * c + Cross(axis, v) * s + axis * (Dot(axis, v) * (1 - c));
}

}  // namespace

CameraPose CameraPose::FromToWorld(const Transform& to_world, double orbit_distance) {
  CameraPose pose;
  pose.position_ = to_world.Point(Vec3d(0, 0, 0));
  pose.forward_ = Normalize(to_world.Vector(Vec3d(0, 0, 1)));
  const Vec3d camera_up = to_world.Vector(Vec3d(0, 1, 0));
  const Transform rigid = Transform::LookAt(pose.position_, pose.position_ + pose.forward_, camera_up);
  pose.rest_ = rigid.InverseMatrix() * to_world.Matrix();
  pose.up_ = Normalize(TurningAxis(Normalize(camera_up)));
  // A camera looking along its turning axis (straight down at a floor) keeps its own up.
  if (std::abs(Dot(pose.up_, pose.forward_)) > std::cos(M_PI / 180)) pose.up_ = Normalize(camera_up);
  pose.orbit_distance_ = orbit_distance > 0 && std::isfinite(orbit_distance) ? orbit_distance : 1;
  return pose;
}

Transform CameraPose::ToWorld() const {
  return Transform::LookAt(position_, position_ + forward_, up_) * Transform(rest_);
}

void CameraPose::Rotate(double yaw_deg, double pitch_deg) {
  Vec3d f = Normalize(Turned(forward_, up_, yaw_deg));
  // Pitch: within [1, 179] degrees of the turning axis.
  const double now = std::acos(std::clamp(Dot(f, up_), -1.0, 1.0)) * 180 / M_PI;
  const double target = std::clamp(now - pitch_deg, 1.0, 179.0);
  const Vec3d right = Normalize(Cross(f, up_));
  forward_ = Normalize(Turned(f, right, now - target));
}

void CameraPose::Orbit(double yaw_deg, double pitch_deg) {
  const Vec3d centre = Centre();
  Rotate(yaw_deg, pitch_deg);
  position_ = centre - forward_ * orbit_distance_;
}

void CameraPose::Turn(double yaw_deg, double pitch_deg) { Rotate(yaw_deg, pitch_deg); }

void CameraPose::Move(double right, double up, double forward) {
  const Vec3d r = Normalize(Cross(forward_, up_));
  const Vec3d u = Cross(r, forward_);
  position_ = position_ + r * right + u * up + forward_ * forward;
}

void CameraPose::Dolly(double factor) {
  if (!(factor > 0) || !std::isfinite(factor)) return;
  const Vec3d centre = Centre();
  // Within a factor 1e6 of a unit either way: farther, the pose's position would lose the
  // centre in rounding; nearer, it would stand on it.
  orbit_distance_ = std::clamp(orbit_distance_ * factor, 1e-6, 1e6);
  position_ = centre - forward_ * orbit_distance_;
}

void CameraPose::LookAt(const Vec3d& point) {
  const Vec3d d = point - position_;
  const double length = Length(d);
  if (!(length > 0) || !std::isfinite(length)) return;
  const Vec3d f = d / length;
  if (std::abs(Dot(f, up_)) > std::cos(M_PI / 180)) return;  // straight along the turning axis
  forward_ = f;
  orbit_distance_ = length;
}

}  // namespace objektiv
