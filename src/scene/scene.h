// The scene: shapes in an Embree BVH with their materials and area lights, plus the lights.
#pragma once
#include <embree3/rtcore.h>

#include <atomic>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "base/sampling.h"
#include "scene/infinite_light.h"
#include "scene/light.h"
#include "scene/material.h"
#include "scene/medium.h"
#include "scene/shape.h"

namespace objektiv {

struct ShapeRecord {
  std::unique_ptr<Shape> shape;
  std::shared_ptr<const Material> material;
  const AreaLight* area_light = nullptr;
  int instance = -1;  // for a top-level instance: index into the scene's instances
  // The media on the two sides of the surface (as Mitsuba 3): a shape that names either is a
  // boundary between media, and a ray leaving it toward the side of the geometric normal
  // travels in `exterior`, else in `interior` (nullptr: vacuum). A shape that names neither
  // leaves the medium a ray travels in unchanged.
  const Medium* interior = nullptr;
  const Medium* exterior = nullptr;
  bool medium_interface = false;
  // The medium a ray leaving the surface in direction w travels in, coming from `current`.
  const Medium* MediumToward(const Vec3f& n, const Vec3f& w, const Medium* current) const {
    if (!medium_interface) return current;
    return Dot(w, n) > 0 ? exterior : interior;
  }
};

class Scene {
 public:
  Scene();
  ~Scene();
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  // Building. Shapes keep their order (Embree geometry ID = index).
  ShapeRecord& AddShape(std::unique_ptr<Shape> shape, std::shared_ptr<const Material> material);
  // Makes the shape record an emitter.
  void AddAreaLight(ShapeRecord& record, std::shared_ptr<const SpectrumTexture> radiance, bool two_sided);
  void AddLight(std::unique_ptr<Light> light);
  // Participating media: the scene keeps them; shapes (ShapeRecord::interior, exterior) and
  // the camera point to them.
  const Medium* AddMedium(std::shared_ptr<const Medium> medium);
  void SetCameraMedium(const Medium* medium) { camera_medium_ = medium; }
  // Instancing: shapes added to a group live in its own BVH (in object space); each instance
  // places the whole group with a transform. Instanced shapes cannot emit.
  int AddShapeGroup();
  void AddShapeToGroup(int group, std::unique_ptr<Shape> shape, std::shared_ptr<const Material> material);
  // Throws std::invalid_argument if the placed group reaches beyond kMaxSceneCoordinate.
  void AddInstance(int group, const Transform& to_world);
  // Builds the BVH, preprocesses lights, builds the light-selection distribution.
  void Commit();

  // Queries (thread-safe after Commit).
  std::optional<SurfaceInteraction> Intersect(const Ray& ray) const;
  // The same for many rays that mostly go the same way (a pixel's camera rays), traced in
  // packets of eight, which Embree does several times faster per ray than one by one.
  // out[i] stays empty where rays[i] is null.
  void IntersectCoherent(std::span<const Ray* const> rays, std::span<std::optional<SurfaceInteraction>> out) const;
  // Both honour masks (materials with an opacity): a ray passes such a surface with
  // probability 1 - opacity, the same way for both (scene.cpp).
  bool Occluded(const Ray& ray) const;
  // Rays that Embree could not take (an origin or direction non-finite or beyond its range,
  // a NaN length), skipped rather than traced: a miss for Intersect, occluded for Occluded.
  // Geometry is bounded at load (kMaxSceneCoordinate); this guards against what the
  // arithmetic may still produce. Counted since the scene was built.
  uint64_t SkippedRays() const { return skipped_rays_.load(std::memory_order_relaxed); }

  const std::vector<std::unique_ptr<Light>>& lights() const { return lights_; }
  const std::vector<const InfiniteLight*>& infinite_lights() const { return infinite_lights_; }
  // Chooses a light in proportion to its power; nullptr when the scene has none.
  const Light* SampleLight(float u, float* pmf) const;
  float LightPmf(const Light* light) const;
  const Bounds3f& bounds() const { return bounds_; }
  // The medium the camera sits in (nullptr: vacuum).
  const Medium* camera_medium() const { return camera_medium_; }
  // Whether rays may travel through media or pass surfaces with a `null` BSDF: integrators
  // that follow neither must refuse the scene (Integrator::RendersMedia).
  bool HasMedia() const { return !media_.empty() || has_null_surfaces_; }
  size_t ShapeCount() const { return shapes_.size(); }

 private:
  struct ShapeGroup {
    RTCScene scene = nullptr;
    std::vector<ShapeRecord> shapes;
    Bounds3f bounds;
  };
  struct Instance {
    int group;
    Transform to_world, to_object;
  };
  // The interaction for Embree's answer rh to `ray` (empty for a miss).
  std::optional<SurfaceInteraction> HitInteraction(const Ray& ray, const RTCRayHit& rh) const;
  SurfaceInteraction InstanceInteraction(const Ray& ray, const RTCRayHit& rh) const;
  // The nearest surface, mask or not, and whether a ray occludes ignoring masks.
  std::optional<SurfaceInteraction> IntersectSurface(const Ray& ray) const;
  bool OccludedBySurface(const Ray& ray) const;
  // Whether `ray` passes the mask it meets at si; and the first hit along `ray`, from `si` on,
  // that it does not pass.
  bool PassesThrough(const SurfaceInteraction& si, const Ray& ray) const;
  std::optional<SurfaceInteraction> SkipPassedMasks(const Ray& ray, std::optional<SurfaceInteraction> si) const;

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<ShapeRecord> shapes_;
  std::vector<ShapeGroup> groups_;
  std::vector<Instance> instances_;
  std::vector<std::unique_ptr<Light>> lights_;
  std::vector<const InfiniteLight*> infinite_lights_;
  Distribution1D light_distribution_;
  Bounds3f bounds_;
  bool has_masks_ = false;  // whether any shape's material has an opacity
  std::vector<std::shared_ptr<const Medium>> media_;
  const Medium* camera_medium_ = nullptr;
  bool has_null_surfaces_ = false;
  mutable std::atomic<uint64_t> skipped_rays_{0};
};

}  // namespace objektiv
