#include "scene/scene.h"

#include <stdexcept>
#include <unordered_map>

#include "base/log.h"

namespace objektiv {

namespace {
void EmbreeError(void*, RTCError code, const char* str) {
  spdlog::error("Embree error {}: {}", int(code), str ? str : "");
}
}  // namespace

Scene::Scene() {
  device_ = rtcNewDevice("threads=0");
  if (!device_) throw std::runtime_error("cannot create the Embree device");
  rtcSetDeviceErrorFunction(device_, EmbreeError, nullptr);
  scene_ = rtcNewScene(device_);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
}

Scene::~Scene() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

ShapeRecord& Scene::AddShape(std::unique_ptr<Shape> shape, std::shared_ptr<const Material> material) {
  RTCGeometry geom = shape->CreateGeometry(device_);
  unsigned id = rtcAttachGeometry(scene_, geom);
  rtcReleaseGeometry(geom);
  if (id != shapes_.size()) throw std::logic_error("Embree geometry IDs out of step with shapes");
  bounds_.Extend(shape->WorldBounds());
  shapes_.push_back(ShapeRecord{std::move(shape), std::move(material), nullptr});
  return shapes_.back();
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

std::optional<SurfaceInteraction> Scene::Intersect(const Ray& ray) const {
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
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  const ShapeRecord& rec = shapes_[rh.hit.geomID];
  SurfaceInteraction si = rec.shape->ComputeInteraction(ray, rh.hit, rh.ray.tfar);
  si.shape = &rec;
  return si;
}

bool Scene::Occluded(const Ray& ray) const {
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
