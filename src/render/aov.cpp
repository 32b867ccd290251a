#include "render/aov.h"

#include <stdexcept>

#include "base/rng.h"
#include "render/film.h"
#include "scene/material.h"
#include "scene/shape.h"

namespace objektiv {

namespace {

struct AovName {
  const char* name;
  AovType type;
};
constexpr AovName kAovTypes[] = {{"depth", AovType::kDepth},
                                 {"position", AovType::kPosition},
                                 {"uv", AovType::kUv},
                                 {"geo_normal", AovType::kGeoNormal},
                                 {"sh_normal", AovType::kShNormal},
                                 {"albedo", AovType::kAlbedo}};

std::string Trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\n\r"), b = s.find_last_not_of(" \t\n\r");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

}  // namespace

std::vector<std::string> Aov::ChannelNames() const {
  switch (type) {
    case AovType::kDepth: return {name};
    case AovType::kUv: return {name + ".U", name + ".V"};
    case AovType::kAlbedo: return {name + ".R", name + ".G", name + ".B"};
    default: return {name + ".X", name + ".Y", name + ".Z"};
  }
}

std::vector<Aov> ParseAovs(const std::string& text) {
  std::vector<Aov> out;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = Trim(text.substr(start, comma - start));
    start = comma + 1;
    if (item.empty()) throw std::invalid_argument("an empty entry (expected name:type, separated by commas)");
    const size_t colon = item.find(':');
    if (colon == std::string::npos) throw std::invalid_argument("'" + item + "' is not name:type");
    const std::string name = Trim(item.substr(0, colon)), type = Trim(item.substr(colon + 1));
    if (name.empty()) throw std::invalid_argument("'" + item + "' has no name");
    bool found = false;
    std::string known;
    for (const AovName& a : kAovTypes) {
      known += known.empty() ? a.name : std::string(", ") + a.name;
      if (type == a.name) out.push_back({name, a.type}), found = true;
    }
    if (!found) throw std::invalid_argument("unknown AOV type '" + type + "' (known: " + known + ")");
    for (size_t i = 0; i + 1 < out.size(); ++i)
      if (out[i].name == name) throw std::invalid_argument("the AOV name '" + name + "' is given twice");
    if (comma == text.size()) break;
  }
  return out;
}

int AovIntegrator::AovChannels() const {
  int n = 0;
  for (const Aov& a : aovs_) n += a.Channels();
  return n;
}

namespace {

// One BSDF sample's estimate of the reflectance toward -ray.d (f cos / pdf), as XYZ under D65.
Vec3f AlbedoXyz(const Ray& ray, const SurfaceInteraction& hit, const SampledWavelengths& lambda, uint64_t seed) {
  const Material* material = hit.shape ? hit.shape->material.get() : nullptr;
  if (!material) return Vec3f(0.f);
  SampledWavelengths l = lambda;  // a dispersive surface may keep the hero alone
  const BSDF bsdf = material->GetBSDF(hit, l);
  PCG32 rng;
  rng.SetSequence(seed);
  const float uc = rng.UniformFloat();
  const Vec2f u(rng.UniformFloat(), rng.UniformFloat());
  // Energy, not radiance: light entering glass is not counted n^2 denser.
  const std::optional<BSDFSample> s = bsdf.Sample(-Normalize(ray.d), uc, u, TransportMode::kImportance);
  if (!s || !(s->pdf > 0)) return Vec3f(0.f);
  SampledSpectrum rho = s->f * (AbsDot(s->wi, bsdf.frame().n) / s->pdf);
  for (int i = 0; i < kSpectrumSamples; ++i) rho[i] *= D65Normalized(l[i]);
  return SampledToXYZ(rho, l);
}

}  // namespace

void AovIntegrator::EvaluateAovs(const Ray& ray, const std::optional<SurfaceInteraction>& hit,
                                 const SampledWavelengths& lambda, uint64_t seed, float* out) const {
  for (const Aov& a : aovs_) {
    const int n = a.Channels();
    if (!hit) {
      for (int c = 0; c < n; ++c) *out++ = 0;
      continue;
    }
    switch (a.type) {
      case AovType::kDepth: *out++ = hit->t * Length(ray.d); break;
      case AovType::kPosition: *out++ = hit->p.x, *out++ = hit->p.y, *out++ = hit->p.z; break;
      case AovType::kUv: *out++ = hit->uv.x, *out++ = hit->uv.y; break;
      case AovType::kGeoNormal: *out++ = hit->n.x, *out++ = hit->n.y, *out++ = hit->n.z; break;
      case AovType::kShNormal: {
        // The normal the material shades with: a bump or normal map's, where there is one.
        const Material* m = hit->shape ? hit->shape->material.get() : nullptr;
        const Vec3f ns = m ? m->ShadingFrame(*hit).n : hit->shading.n;
        *out++ = ns.x, *out++ = ns.y, *out++ = ns.z;
        break;
      }
      case AovType::kAlbedo: {
        const Vec3f xyz = AlbedoXyz(ray, *hit, lambda, seed);
        *out++ = xyz.x, *out++ = xyz.y, *out++ = xyz.z;
        break;
      }
    }
  }
}

}  // namespace objektiv
