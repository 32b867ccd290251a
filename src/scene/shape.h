// Shapes: geometry registered with Embree that can also be sampled (for area lights).
#pragma once
#include <embree3/rtcore.h>

#include <optional>

#include "base/bounds.h"
#include "scene/interaction.h"

namespace objektiv {

struct ShapeSample {
  Vec3f p, p_error, n;
  Vec2f uv;
  float pdf = 0;  // per unit area, or per unit solid angle when returned by SampleFrom
};

class Shape {
 public:
  virtual ~Shape() = default;

  // A committed Embree geometry for this shape (the caller attaches it to a scene).
  virtual RTCGeometry CreateGeometry(RTCDevice device) const = 0;
  // Fill in the interaction for an Embree hit on this shape.
  virtual SurfaceInteraction ComputeInteraction(const Ray& ray, const RTCHit& hit, float t) const = 0;
  virtual float Area() const = 0;
  virtual Bounds3f WorldBounds() const = 0;
  // A point uniformly distributed over the surface (pdf per unit area).
  virtual ShapeSample SampleArea(Vec2f u) const = 0;
  // A point on the shape as seen from `ref`, pdf per unit solid angle at ref. Shapes that
  // can do better than area sampling (spheres: the cone of directions) override this. A pdf
  // of 0 means no sample (ref on the shape's plane, or on the shape). A plain struct rather
  // than an optional: it is built in the caller's slot, never copied (a measurable cost).
  virtual ShapeSample SampleFrom(const Vec3f& ref, Vec2f u) const;
  // Density (solid angle at ref) with which SampleFrom would return the point `hit`.
  virtual float PdfFrom(const Vec3f& ref, const SurfaceInteraction& hit) const;
};

// Largest magnitude of any coordinate of a scene point, in scene units. Far beyond any real
// scene (a single-precision coordinate there resolves only 8 units), it keeps what light
// sampling computes from positions, up to fourth powers of distances (1e33 at most), within
// single precision (3.4e38), and every ray within the range Embree accepts (1.8e18).
inline constexpr float kMaxSceneCoordinate = 1e8f;
// Whether every coordinate of p lies within kMaxSceneCoordinate (false for NaN).
bool WithinSceneLimit(const Vec3f& p);
// Throws std::invalid_argument naming `what` unless b is non-empty and within the limit.
void CheckSceneLimit(const Bounds3f& b, const char* what);

// Solid-angle density at `ref` of area density `pdf_area` at a point p with normal n.
float AreaToSolidAnglePdf(float pdf_area, const Vec3f& ref, const Vec3f& p, const Vec3f& n);

}  // namespace objektiv
