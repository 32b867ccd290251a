#include "render/ray_memo.h"

#include <algorithm>

namespace objektiv {

namespace {
bool SameRay(const Ray& a, const Ray& b) { return a.o == b.o && a.d == b.d && a.tmax == b.tmax; }
}  // namespace

void RayMemo::Begin(const Scene& scene, const Ray& camera_ray, RayCounts& counts, bool record) {
  counts_ = &counts;
  cursor_ = 0;
  recording_ = record;
  if (!record) {
    scene_ = &scene;
    replaying_ = false;
    entries_.clear();
    hits_.clear();
    return;
  }
  replaying_ = scene_ == &scene && SameRay(camera_ray, camera_ray_);
  if (replaying_) return;
  scene_ = &scene;
  camera_ray_ = camera_ray;
  entries_.clear();
  hits_.clear();
}

const RayMemo::Entry* RayMemo::Find(const Ray& ray, bool shadow) {
  if (!replaying_) return nullptr;
  const size_t end = std::min(entries_.size(), cursor_ + kWindow);
  for (size_t i = cursor_; i < end; ++i)
    if (entries_[i].shadow == shadow && SameRay(entries_[i].ray, ray)) {
      cursor_ = i + 1;
      return &entries_[i];
    }
  return nullptr;
}

std::optional<SurfaceInteraction> RayMemo::Intersect(const Ray& ray) {
  if (const Entry* e = Find(ray, false)) return hits_[e->hit];
  ++counts_->closest;
  std::optional<SurfaceInteraction> hit = scene_->Intersect(ray);
  if (recording_ && entries_.size() < kMaxEntries) {
    entries_.push_back({ray, false, false, hits_.size()});
    hits_.push_back(hit);
  }
  return hit;
}

bool RayMemo::Occluded(const Ray& ray) {
  if (const Entry* e = Find(ray, true)) return e->answer;
  ++counts_->shadow;
  const bool occluded = scene_->Occluded(ray);
  if (recording_ && entries_.size() < kMaxEntries) {
    entries_.push_back({ray, true, occluded});
  }
  return occluded;
}

}  // namespace objektiv
