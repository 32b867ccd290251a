#include "scene/scene.h"

#include <bit>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include "base/log.h"
#include "base/rng.h"

namespace objektiv {

namespace {
void EmbreeError(void*, RTCError code, const char* str) {
  spdlog::error("Embree error {}: {}", int(code), str ? str : "");
}

// Whether Embree takes the ray: its traversal (assertions on in Debian's build) requires
// every origin and direction component within 1.844e18 in magnitude, and a length that is
// not NaN (infinity is allowed).
bool EmbreeTakes(const Ray& r) {
  auto ok = [](float v) { return std::abs(v) <= 1.844e18f; };  // false for NaN
  return ok(r.o.x) && ok(r.o.y) && ok(r.o.z) && ok(r.d.x) && ok(r.d.y) && ok(r.d.z) && !std::isnan(r.tmax);
}
}  // namespace

Scene::Scene() {
  device_ = rtcNewDevice("threads=0");
  if (!device_) throw std::runtime_error("cannot create the Embree device");
  rtcSetDeviceErrorFunction(device_, EmbreeError, nullptr);
  scene_ = rtcNewScene(device_);
  // Low quality at the top makes Embree build two levels: each shape keeps its own BVH (a
  // mesh's built at high quality, see TriangleMesh::CreateGeometry) under a BVH over the
  // shapes. Scenes made of a few large pieces trace much faster so (Cornell box: 77 instead of
  // 98 ns per closest hit, 36 instead of 57 per shadow ray; one flat BVH packs triangles of
  // different walls into one leaf box), and a scene of one big mesh as fast as before.
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_LOW);
}

Scene::~Scene() {
  for (ShapeGroup& g : groups_)
    if (g.scene) rtcReleaseScene(g.scene);
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

ShapeRecord& Scene::AddShape(std::unique_ptr<Shape> shape, std::shared_ptr<const Material> material) {
  RTCGeometry geom = shape->CreateGeometry(device_);
  unsigned id = rtcAttachGeometry(scene_, geom);
  rtcReleaseGeometry(geom);
  if (id != shapes_.size()) throw std::logic_error("Embree geometry IDs out of step with shapes");
  bounds_.Extend(shape->WorldBounds());
  if (material && material->HasOpacity()) has_masks_ = true;
  has_null_surfaces_ |= material && material->IsNull();
  shapes_.push_back(ShapeRecord{std::move(shape), std::move(material), nullptr, -1});
  return shapes_.back();
}

int Scene::AddShapeGroup() {
  ShapeGroup g;
  g.scene = rtcNewScene(device_);
  rtcSetSceneBuildQuality(g.scene, RTC_BUILD_QUALITY_HIGH);
  groups_.push_back(std::move(g));
  return int(groups_.size()) - 1;
}

const Medium* Scene::AddMedium(std::shared_ptr<const Medium> medium) {
  media_.push_back(std::move(medium));
  return media_.back().get();
}

void Scene::AddShapeToGroup(int group, std::unique_ptr<Shape> shape, std::shared_ptr<const Material> material) {
  ShapeGroup& g = groups_.at(group);
  RTCGeometry geom = shape->CreateGeometry(device_);
  unsigned id = rtcAttachGeometry(g.scene, geom);
  rtcReleaseGeometry(geom);
  if (id != g.shapes.size()) throw std::logic_error("Embree geometry IDs out of step with group shapes");
  g.bounds.Extend(shape->WorldBounds());
  if (material && material->HasOpacity()) has_masks_ = true;
  has_null_surfaces_ |= material && material->IsNull();
  g.shapes.push_back(ShapeRecord{std::move(shape), std::move(material), nullptr, -1});
}

void Scene::AddInstance(int group, const Transform& to_world) {
  ShapeGroup& g = groups_.at(group);
  Bounds3f placed;
  for (int i = 0; i < 8 && !g.bounds.Empty(); ++i)
    placed.Extend(to_world.Point(Vec3f(i & 1 ? g.bounds.hi.x : g.bounds.lo.x, i & 2 ? g.bounds.hi.y : g.bounds.lo.y,
                                       i & 4 ? g.bounds.hi.z : g.bounds.lo.z)));
  if (!g.bounds.Empty()) CheckSceneLimit(placed, "the instance");
  // Embree needs the child BVH built before an instance of it is committed.
  rtcCommitScene(g.scene);
  RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(geom, g.scene);
  float m[12];  // 3x4, column major
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) m[c * 3 + r] = float(to_world.Matrix().m[r][c]);
  rtcSetGeometryTransform(geom, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, m);
  rtcCommitGeometry(geom);
  unsigned id = rtcAttachGeometry(scene_, geom);
  rtcReleaseGeometry(geom);
  if (id != shapes_.size()) throw std::logic_error("Embree geometry IDs out of step with shapes");
  bounds_.Extend(placed);
  instances_.push_back(Instance{group, to_world, to_world.Inverse()});
  shapes_.push_back(ShapeRecord{nullptr, nullptr, nullptr, int(instances_.size()) - 1});
}

void Scene::AddAreaLight(ShapeRecord& record, std::shared_ptr<const SpectrumTexture> radiance, bool two_sided) {
  Vec3f mean = radiance->MeanRgb();
  float y = 0.2126f * mean.x + 0.7152f * mean.y + 0.0722f * mean.z;
  float power = y * record.shape->Area() * kPi * (two_sided ? 2 : 1);
  auto light = std::make_unique<AreaLight>(record.shape.get(), std::move(radiance), two_sided, power);
  record.area_light = light.get();
  light->set_index(int(lights_.size()));
  lights_.push_back(std::move(light));
}

void Scene::AddLight(std::unique_ptr<Light> light) {
  if (light->IsInfinite())
    if (auto* inf = dynamic_cast<const InfiniteLight*>(light.get())) infinite_lights_.push_back(inf);
  light->set_index(int(lights_.size()));
  lights_.push_back(std::move(light));
}

void Scene::Commit() {
  for (ShapeGroup& g : groups_) rtcCommitScene(g.scene);
  rtcCommitScene(scene_);
  std::vector<float> power;
  for (auto& l : lights_) {
    l->Preprocess(bounds_);
    power.push_back(std::max(0.f, l->Power()));
  }
  // With no usable power estimate (all zero), fall back to uniform selection.
  float total = 0;
  for (float p : power) total += p;
  if (!(total > 0) || !std::isfinite(total))
    for (float& p : power) p = 1;
  if (!power.empty()) light_distribution_ = Distribution1D(power);
}

// --- Masks (Mitsuba's `mask`: scene/mask_material.h) ----------------------------------
//
// A surface of opacity a stops a ray with probability a and lets it pass with probability
// 1 - a, decided here, where the ray meets it, for every ray alike (camera and light paths,
// shadow rays), as pbrt-v4's alpha test: a pass-through carries weight (1 - a) / (1 - a) = 1
// and a stop weight a / a = 1, so a path's expected light is a L_surface + (1 - a) L_behind,
// Mitsuba's mask, and a shadow ray agrees with the paths that pass (an estimator that let
// paths through but stopped shadow rays would darken what lies behind; one that shaded the
// pass-through as a BSDF lobe would see no point light through the holes). Being part of
// the intersection, it does not count as a bounce and leaves multiple importance sampling as
// it is. The decision uses a hash of the ray, so it is a function of the ray alone
// (deterministic, as everything is), and independent between rays.

namespace {

float RayHashFloat(const Ray& ray) {
  const uint64_t h = Hash(std::bit_cast<uint32_t>(ray.o.x), std::bit_cast<uint32_t>(ray.o.y),
                          std::bit_cast<uint32_t>(ray.o.z), std::bit_cast<uint32_t>(ray.d.x),
                          std::bit_cast<uint32_t>(ray.d.y), std::bit_cast<uint32_t>(ray.d.z));
  return float(h >> 40) * 0x1p-24f;
}

// Enough layers of leaves for any scene; a ray that still meets masks after this many stops
// at the last one (it cannot loop for ever).
constexpr int kMaxPassThroughs = 1024;

}  // namespace

bool Scene::PassesThrough(const SurfaceInteraction& si, const Ray& ray) const {
  const Material* m = si.shape ? si.shape->material.get() : nullptr;
  if (!m || !m->HasOpacity()) return false;
  const float a = m->Opacity(si);
  if (a >= 1) return false;
  return a <= 0 || RayHashFloat(ray) >= a;
}

std::optional<SurfaceInteraction> Scene::Intersect(const Ray& ray) const {
  std::optional<SurfaceInteraction> si = IntersectSurface(ray);
  if (!has_masks_ || !si) return si;
  return SkipPassedMasks(ray, std::move(si));
}

std::optional<SurfaceInteraction> Scene::SkipPassedMasks(const Ray& ray, std::optional<SurfaceInteraction> si) const {
  Ray segment = ray;
  bool moved = false;
  for (int i = 0; i < kMaxPassThroughs && si && PassesThrough(*si, segment); ++i) {
    segment = si->ContinueBeyond(ray);
    if (!(segment.tmax > 0)) return std::nullopt;
    si = IntersectSurface(segment);
    moved = true;
  }
  // The hit's parameter along the ray asked about (absorption between surfaces reads it).
  if (si && moved) si->t = Dot(si->p - ray.o, ray.d) / Dot(ray.d, ray.d);
  return si;
}

std::optional<SurfaceInteraction> Scene::IntersectSurface(const Ray& ray) const {
  if (!EmbreeTakes(ray)) {
    skipped_rays_.fetch_add(1, std::memory_order_relaxed);
    return std::nullopt;
  }
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh;
  rh.ray.org_x = ray.o.x;
  rh.ray.org_y = ray.o.y;
  rh.ray.org_z = ray.o.z;
  rh.ray.dir_x = ray.d.x;
  rh.ray.dir_y = ray.d.y;
  rh.ray.dir_z = ray.d.z;
  rh.ray.tnear = 0;
  rh.ray.tfar = ray.tmax;
  rh.ray.time = 0;
  rh.ray.mask = 0xffffffffu;
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &ctx, &rh);
  return HitInteraction(ray, rh);
}

std::optional<SurfaceInteraction> Scene::HitInteraction(const Ray& ray, const RTCRayHit& rh) const {
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  if (rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID) return InstanceInteraction(ray, rh);
  const ShapeRecord& rec = shapes_[rh.hit.geomID];
  SurfaceInteraction si = rec.shape->ComputeInteraction(ray, rh.hit, rh.ray.tfar);
  si.shape = &rec;
  return si;
}

void Scene::IntersectCoherent(std::span<const Ray* const> rays, std::span<std::optional<SurfaceInteraction>> out) const {
  constexpr int kPacket = 8;
  for (size_t start = 0; start < rays.size(); start += kPacket) {
    const int n = int(std::min<size_t>(kPacket, rays.size() - start));
    alignas(32) int valid[kPacket];
    alignas(32) RTCRayHit8 packet;
    for (int k = 0; k < kPacket; ++k) {
      const Ray* ray = k < n ? rays[start + k] : nullptr;
      if (ray && !EmbreeTakes(*ray)) {
        skipped_rays_.fetch_add(1, std::memory_order_relaxed);
        ray = nullptr;
      }
      valid[k] = ray ? -1 : 0;
      if (!ray) continue;
      packet.ray.org_x[k] = ray->o.x;
      packet.ray.org_y[k] = ray->o.y;
      packet.ray.org_z[k] = ray->o.z;
      packet.ray.dir_x[k] = ray->d.x;
      packet.ray.dir_y[k] = ray->d.y;
      packet.ray.dir_z[k] = ray->d.z;
      packet.ray.tnear[k] = 0;
      packet.ray.tfar[k] = ray->tmax;
      packet.ray.time[k] = 0;
      packet.ray.mask[k] = 0xffffffffu;
      packet.ray.id[k] = 0;
      packet.ray.flags[k] = 0;
      packet.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
      packet.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
    }
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcIntersect8(valid, scene_, &ctx, &packet);
    for (int k = 0; k < n; ++k) {
      std::optional<SurfaceInteraction>& o = out[start + k];
      o.reset();
      if (!valid[k]) continue;
      // One lane as a single-ray answer (what the interaction code reads of it).
      RTCRayHit rh;
      rh.ray.tfar = packet.ray.tfar[k];
      rh.hit.Ng_x = packet.hit.Ng_x[k];
      rh.hit.Ng_y = packet.hit.Ng_y[k];
      rh.hit.Ng_z = packet.hit.Ng_z[k];
      rh.hit.u = packet.hit.u[k];
      rh.hit.v = packet.hit.v[k];
      rh.hit.primID = packet.hit.primID[k];
      rh.hit.geomID = packet.hit.geomID[k];
      rh.hit.instID[0] = packet.hit.instID[0][k];
      if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) o = HitInteraction(*rays[start + k], rh);
      if (has_masks_ && o) o = SkipPassedMasks(*rays[start + k], std::move(o));
    }
  }
}

SurfaceInteraction Scene::InstanceInteraction(const Ray& ray, const RTCRayHit& rh) const {
  const Instance& inst = instances_[shapes_[rh.hit.instID[0]].instance];
  const ShapeRecord& rec = groups_[inst.group].shapes[rh.hit.geomID];
  // The hit parameter t is the same along the object-space ray (an affine map).
  Ray local{inst.to_object.Point(ray.o), inst.to_object.Vector(ray.d), ray.tmax};
  SurfaceInteraction o = rec.shape->ComputeInteraction(local, rh.hit, rh.ray.tfar);
  SurfaceInteraction si = o;
  const Transform& m = inst.to_world;
  si.p = m.Point(o.p);
  // Error of the object-space point carried through |M|, plus the transform's own rounding.
  Vec3f abs_p(0.f), abs_err(0.f);
  const auto& a = m.Matrix().m;
  for (int i = 0; i < 3; ++i) {
    abs_p[i] = float(std::abs(a[i][0] * o.p.x) + std::abs(a[i][1] * o.p.y) + std::abs(a[i][2] * o.p.z) + std::abs(a[i][3]));
    abs_err[i] = float(std::abs(a[i][0]) * o.p_error.x + std::abs(a[i][1]) * o.p_error.y + std::abs(a[i][2]) * o.p_error.z);
  }
  si.p_error = abs_err * (1 + Gamma(3)) + abs_p * Gamma(3);
  si.n = Normalize(m.Normal(o.n));
  si.dpdu = m.Vector(o.dpdu);
  si.dpdv = m.Vector(o.dpdv);
  si.shading = Frame::FromNormalTangent(Normalize(m.Normal(o.shading.n)), m.Vector(o.shading.s));
  si.wo = -Normalize(ray.d);
  si.shape = &rec;
  return si;
}

bool Scene::Occluded(const Ray& ray) const {
  if (!has_masks_) return OccludedBySurface(ray);
  // Through the masks a segment passes, hit by hit (each decided as Intersect decides it).
  Ray segment = ray;
  for (int i = 0; i < kMaxPassThroughs; ++i) {
    const std::optional<SurfaceInteraction> si = IntersectSurface(segment);
    if (!si) return false;
    if (!PassesThrough(*si, segment)) return true;
    segment = si->ContinueBeyond(ray);
    if (!(segment.tmax > 0)) return false;
  }
  return true;
}

bool Scene::OccludedBySurface(const Ray& ray) const {
  if (!EmbreeTakes(ray)) {
    skipped_rays_.fetch_add(1, std::memory_order_relaxed);
    return true;
  }
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRay r;
  r.org_x = ray.o.x;
  r.org_y = ray.o.y;
  r.org_z = ray.o.z;
  r.dir_x = ray.d.x;
  r.dir_y = ray.d.y;
  r.dir_z = ray.d.z;
  r.tnear = 0;
  r.tfar = ray.tmax;
  r.time = 0;
  r.mask = 0xffffffffu;
  r.id = 0;
  r.flags = 0;
  rtcOccluded1(scene_, &ctx, &r);
  return r.tfar < 0;
}

const Light* Scene::SampleLight(float u, float* pmf) const {
  if (lights_.empty()) return nullptr;
  int i = light_distribution_.SampleDiscrete(u, pmf);
  return lights_[i].get();
}

float Scene::LightPmf(const Light* light) const {
  if (!light || light->index() < 0) return 0;
  return light_distribution_.DiscretePmf(light->index());
}

}  // namespace objektiv
