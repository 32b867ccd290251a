// The scene's answers to the rays of one camera sample, kept for the sample's other wavelength
// sets (CameraPathIntegrator::WavelengthSets). Each set repeats the sample's path with a copy of
// its sampler started alike, so wherever nothing depends on wavelength (no dispersion, no
// decision on a spectral value) it asks the same rays in the same order: the memo answers them
// from its record instead of tracing again. An answer is given only for the bit-identical ray
// (origin, direction, tmax) and kind of query, so it is always what the scene would answer; a
// ray not recorded is traced (and counted) and recorded.
//
// Begin(scene, camera ray, counts, record) starts a set: a camera ray or scene other than the
// last one's starts a new record, made without looking anything up (none with record false:
// a sample of one set has nothing to share, and every ray goes straight to the scene). A later set looks its rays up
// in the order they were recorded: at the cursor or up to kWindow entries after it (where a
// branch of the first set's path was not taken, its rays are passed over); a ray not found
// there is traced and added. At most kMaxEntries rays a sample.
#pragma once
#include <optional>
#include <vector>

#include "render/block_context.h"
#include "scene/scene.h"

namespace objektiv {

class RayMemo {
 public:
  static constexpr size_t kMaxEntries = 4096, kWindow = 64;
  void Begin(const Scene& scene, const Ray& camera_ray, RayCounts& counts, bool record = true);
  std::optional<SurfaceInteraction> Intersect(const Ray& ray);
  bool Occluded(const Ray& ray);

 private:
  struct Entry {
    Ray ray;
    bool shadow;          // an Occluded query, else Intersect
    bool answer = false;  // Occluded's
    size_t hit = 0;       // Intersect's, in hits_
  };
  const Entry* Find(const Ray& ray, bool shadow);
  const Scene* scene_ = nullptr;
  RayCounts* counts_ = nullptr;
  Ray camera_ray_;
  std::vector<Entry> entries_;
  std::vector<std::optional<SurfaceInteraction>> hits_;
  size_t cursor_ = 0;
  bool replaying_ = false;  // a later set of the recorded sample
  bool recording_ = true;
};

}  // namespace objektiv
