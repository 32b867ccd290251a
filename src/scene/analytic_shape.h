// Shapes with closed-form intersection, registered with Embree as user geometry.
// Each one intersects in double precision and reports world positions with error bounds.
#pragma once
#include "base/transform.h"
#include "scene/shape.h"

namespace objektiv {

class AnalyticShape : public Shape {
 public:
  RTCGeometry CreateGeometry(RTCDevice device) const override;

  // Nearest hit with 0 < t < tmax; `param` is handed back to ComputeInteraction via the
  // Embree hit's (u, v).
  virtual bool Intersect(const Vec3d& o, const Vec3d& d, double tmax, double* t, Vec2f* param) const = 0;
  // Bounds given to Embree (may be larger than WorldBounds, e.g. for the infinite plane).
  virtual Bounds3f EmbreeBounds() const { return WorldBounds(); }
};

// The world position of an object-space point and a bound on its rounding error.
void TransformPointWithError(const Transform& t, const Vec3d& p_obj, Vec3f* p, Vec3f* p_error);

// Unit sphere scaled and moved: a similarity transform only (no ellipsoids).
class Sphere final : public AnalyticShape {
 public:
  Sphere(const Vec3f& center, float radius, bool flip_normals, const Transform& to_world);
  bool Intersect(const Vec3d& o, const Vec3d& d, double tmax, double* t, Vec2f* param) const override;
  SurfaceInteraction ComputeInteraction(const Ray& ray, const RTCHit& hit, float t) const override;
  float Area() const override;
  Bounds3f WorldBounds() const override;
  ShapeSample SampleArea(Vec2f u) const override;
  ShapeSample SampleFrom(const Vec3f& ref, Vec2f u) const override;
  float PdfFrom(const Vec3f& ref, const SurfaceInteraction& hit) const override;
  Vec3f center() const { return Vec3f(center_); }
  float radius() const { return float(radius_); }

 private:
  ShapeSample PointAt(const Vec3d& p) const;
  Vec3d center_;
  double radius_;         // in world units
  double object_radius_;  // before to_world's scale
  bool flip_;
  Transform to_world_;  // orientation for the uv parameterisation
};

// Unit disk at z = 0 facing +z, under any affine transform (an ellipse in general).
class Disk final : public AnalyticShape {
 public:
  Disk(const Transform& to_world, bool flip_normals);
  bool Intersect(const Vec3d& o, const Vec3d& d, double tmax, double* t, Vec2f* param) const override;
  SurfaceInteraction ComputeInteraction(const Ray& ray, const RTCHit& hit, float t) const override;
  float Area() const override { return area_; }
  Bounds3f WorldBounds() const override;
  ShapeSample SampleArea(Vec2f u) const override;

 private:
  Transform to_world_;
  Vec3f normal_;
  float area_;
  bool flip_;
};

// Open cylinder of radius 1 around z from z = 0 to 1, under a similarity transform.
class Cylinder final : public AnalyticShape {
 public:
  Cylinder(const Transform& object_to_world, bool flip_normals);
  bool Intersect(const Vec3d& o, const Vec3d& d, double tmax, double* t, Vec2f* param) const override;
  SurfaceInteraction ComputeInteraction(const Ray& ray, const RTCHit& hit, float t) const override;
  float Area() const override { return area_; }
  Bounds3f WorldBounds() const override;
  ShapeSample SampleArea(Vec2f u) const override;

 private:
  ShapeSample PointAt(double phi, double z) const;
  Transform to_world_;
  float area_;
  bool flip_;
};

// How far the infinite plane reaches from the world origin along each axis. Embree drops any
// box beyond about 1.8e18 (its FLT_LARGE), so no geometry reaches farther; hits are computed
// in double precision, so they are exact wherever a float can tell points apart.
constexpr double kInfinitePlaneExtent = 1e18;

// The infinite plane z = 0 (object space) facing +z. It cannot be sampled (no emission).
// Throws std::invalid_argument if it lies wholly beyond kInfinitePlaneExtent.
class InfinitePlane final : public AnalyticShape {
 public:
  InfinitePlane(const Transform& to_world, bool flip_normals);
  bool Intersect(const Vec3d& o, const Vec3d& d, double tmax, double* t, Vec2f* param) const override;
  SurfaceInteraction ComputeInteraction(const Ray& ray, const RTCHit& hit, float t) const override;
  float Area() const override { return std::numeric_limits<float>::infinity(); }
  Bounds3f WorldBounds() const override { return {}; }
  Bounds3f EmbreeBounds() const override { return embree_bounds_; }
  ShapeSample SampleArea(Vec2f) const override { return {}; }

 private:
  Transform to_world_;
  Vec3f normal_;
  bool flip_;
  Bounds3f embree_bounds_;  // the plane inside the cube of half-size kInfinitePlaneExtent
};

}  // namespace objektiv
