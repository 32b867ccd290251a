// Triangle meshes in world space (transformed once when loaded), intersected by Embree.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/sampling.h"
#include "base/transform.h"
#include "scene/shape.h"

namespace objektiv {

struct MeshData {
  std::vector<Vec3f> positions;
  std::vector<Vec3f> normals;  // per vertex, optional
  std::vector<Vec2f> uvs;      // per vertex, optional
  std::vector<uint32_t> indices;  // three per triangle, counter-clockwise = front
};

class TriangleMesh final : public Shape {
 public:
  // Applies to_world to positions and normals; flip_normals reverses the front side.
  // Degenerate (zero-area) triangles are kept for Embree but never sampled.
  TriangleMesh(MeshData data, const Transform& to_world, bool flip_normals);

  RTCGeometry CreateGeometry(RTCDevice device) const override;
  SurfaceInteraction ComputeInteraction(const Ray& ray, const RTCHit& hit, float t) const override;
  float Area() const override { return area_; }
  Bounds3f WorldBounds() const override { return bounds_; }
  ShapeSample SampleArea(Vec2f u) const override;

  size_t TriangleCount() const { return data_.indices.size() / 3; }
  const MeshData& data() const { return data_; }

  // Unit-square rectangle [-1,1]^2 at z = 0 facing +z, and the cube [-1,1]^3 facing out.
  static MeshData Rectangle();
  static MeshData Cube();

 private:
  MeshData data_;
  std::vector<Vec3f> face_normals_;  // unit, front side (after flip_normals); per triangle
  bool flip_;
  float area_ = 0;
  Bounds3f bounds_;
  Distribution1D triangle_distribution_;
  // Two triangles (R, P, Q) and (S, P, Q) forming a parallelogram (a quad light, a rectangle)
  // are sampled as one, with no triangle choice: the vertex slot of each corner in its triangle.
  struct Parallelogram {
    int r_slot, p_slot, q_slot;   // in triangle 0
    int s_slot, sp_slot, sq_slot;  // in triangle 1
  };
  std::optional<Parallelogram> parallelogram_;
  void FindParallelogram();
};

}  // namespace objektiv
