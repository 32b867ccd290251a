// Where the viewer's camera stands and where it looks, as the mouse and the keys move it:
// orbit about a centre in front of it, turn in place, move along its own axes (fly), dolly
// toward the centre.
//
// The scene's to_world is split into a rigid part R (the position, the viewing direction and
// the up direction, which the controls change) and the rest S = R^-1 to_world (a scale or a
// mirror the scene wrote), kept: the pose's to_world is R' S. Turning left and right is about
// the world axis nearest the camera's up direction (y for a y-up scene, whatever the camera's
// pitch), or that direction itself if no axis lies within 45 degrees of it; looking up and
// down stops 1 degree short of that axis.
#pragma once
#include "base/transform.h"

namespace objektiv {

class CameraPose {
 public:
  // The pose of a scene's to_world, orbiting a centre `orbit_distance` ahead (scene units).
  static CameraPose FromToWorld(const Transform& to_world, double orbit_distance);
  Transform ToWorld() const;

  // Degrees: yaw turns about the scene's up direction (positive to the left, as seen by the
  // camera), pitch up and down (positive up).
  void Orbit(double yaw_deg, double pitch_deg);  // about the centre, looking at it
  void Turn(double yaw_deg, double pitch_deg);   // in place (the centre moves along)
  // Along the camera's own axes as the viewer sees them: right, up, forward (scene units).
  void Move(double right, double up, double forward);
  // The distance to the centre times `factor` (> 0), the centre staying; the distance kept
  // within 1e-6 to 1e6 scene units.
  void Dolly(double factor);
  // Turn to look at `point` and orbit about it (a point picked in the image).
  void LookAt(const Vec3d& point);

  const Vec3d& position() const { return position_; }
  const Vec3d& forward() const { return forward_; }
  Vec3d Centre() const { return position_ + forward_ * orbit_distance_; }
  double orbit_distance() const { return orbit_distance_; }

 private:
  // forward_ turned by yaw about up_ and by pitch about the camera's horizontal axis, the angle
  // to up_ kept within [1, 179] degrees.
  void Rotate(double yaw_deg, double pitch_deg);
  Vec3d position_{0, 0, 0}, forward_{0, 0, 1}, up_{0, 1, 0};
  double orbit_distance_ = 1;
  Matrix4 rest_ = Matrix4::Identity();
};

}  // namespace objektiv
