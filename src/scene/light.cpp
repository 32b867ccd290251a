#include "scene/light.h"

#include "base/frame.h"
#include "base/rng.h"
#include "base/sampling.h"
#include "scene/shape.h"

namespace objektiv {

namespace {
// The geometry of a sample of a light at the point p seen from ref (a delta in position):
// direction, pdf 1, exact position; the caller fills in L. *dist2 gets the squared distance.
std::optional<LightSample> PointSourceSample(const Vec3f& p, const Vec3f& ref, float* dist2) {
  Vec3f d = p - ref;
  *dist2 = LengthSquared(d);
  if (*dist2 == 0) return std::nullopt;
  LightSample s;
  s.wi = d / std::sqrt(*dist2);
  s.pdf = 1;
  s.p = p;
  s.p_error = Vec3f(0.f);
  s.n = Vec3f(0.f);
  return s;
}

// A ray from the point p in a direction d chosen with density pdf_dir; the caller fills in L.
LightLeSample RayFromPoint(const Vec3f& p, const Vec3f& d, float pdf_dir) {
  LightLeSample s;
  s.ray = Ray{p, d};
  s.pdf_pos = 1;
  s.pdf_dir = pdf_dir;
  return s;
}
}  // namespace

std::optional<LightLeSample> PointLight::SampleLe(Vec2f, Vec2f u_dir, const SampledWavelengths& lambda) const {
  LightLeSample s = RayFromPoint(p_, SampleUniformSphere(u_dir), UniformSpherePdf());
  s.L = intensity_.Sample(lambda);
  return s;
}

std::optional<LightSample> PointLight::SampleLi(const Vec3f& ref, Vec2f, const SampledWavelengths& lambda) const {
  float dist2;
  std::optional<LightSample> s = PointSourceSample(p_, ref, &dist2);
  if (s) s->L = intensity_.Sample(lambda) / dist2;
  return s;
}

float PointLight::Power() const { return 4 * kPi * SpectrumToY(intensity_); }

SpotLight::SpotLight(const Vec3f& position, const Vec3f& direction, Spectrum intensity, float cutoff_deg,
                     float beam_width_deg)
    : p_(position), dir_(Normalize(direction)), intensity_(std::move(intensity)) {
  cutoff_ = Radians(cutoff_deg);
  beam_ = Radians(std::min(beam_width_deg, cutoff_deg));
  cos_cutoff_ = std::cos(cutoff_);
  cos_beam_ = std::cos(beam_);
}

float SpotLight::Falloff(const Vec3f& w) const {
  float cos_t = Dot(w, dir_);
  if (cos_t <= cos_cutoff_) return 0;
  if (cos_t >= cos_beam_) return 1;
  // Linear in angle between the beam width and the cutoff, as Mitsuba's spot.
  float angle = std::acos(Clamp(cos_t, -1, 1));
  return (cutoff_ - angle) / (cutoff_ - beam_);
}

std::optional<LightSample> SpotLight::SampleLi(const Vec3f& ref, Vec2f, const SampledWavelengths& lambda) const {
  float dist2;
  std::optional<LightSample> s = PointSourceSample(p_, ref, &dist2);
  if (!s) return s;
  float fall = Falloff(-s->wi);
  if (fall == 0) return std::nullopt;
  s->L = intensity_.Sample(lambda) * (fall / dist2);
  return s;
}

std::optional<LightLeSample> SpotLight::SampleLe(Vec2f, Vec2f u_dir, const SampledWavelengths& lambda) const {
  const Vec3f d = Frame::FromZ(dir_).FromLocal(SampleUniformCone(u_dir, cos_cutoff_));
  const float fall = Falloff(d);
  if (fall == 0) return std::nullopt;
  LightLeSample s = RayFromPoint(p_, Normalize(d), UniformConePdf(cos_cutoff_));
  s.L = intensity_.Sample(lambda) * fall;
  return s;
}

float SpotLight::Power() const {
  // Solid angle of the cone, counting the falloff region at half weight.
  return SpectrumToY(intensity_) * 2 * kPi * (1 - 0.5f * (cos_beam_ + cos_cutoff_));
}

std::optional<LightSample> DirectionalLight::SampleLi(const Vec3f& ref, Vec2f, const SampledWavelengths& lambda) const {
  LightSample s;
  s.wi = -dir_;
  s.L = irradiance_.Sample(lambda);
  s.pdf = 1;
  s.p = ref + s.wi * (2 * scene_radius_);
  s.infinite = true;
  return s;
}

std::optional<LightLeSample> DirectionalLight::SampleLe(Vec2f u_pos, Vec2f, const SampledWavelengths& lambda) const {
  const Vec2f disc = SampleUniformDiskConcentric(u_pos);
  const Frame frame = Frame::FromZ(dir_);
  LightLeSample s;
  s.ray = Ray{scene_center_ + scene_radius_ * (frame.s * disc.x + frame.t * disc.y - dir_), dir_};
  s.L = irradiance_.Sample(lambda);
  s.pdf_pos = 1 / (kPi * scene_radius_ * scene_radius_);
  s.pdf_dir = 1;
  return s;
}

float DirectionalLight::Power() const { return kPi * scene_radius_ * scene_radius_ * SpectrumToY(irradiance_); }

SampledSpectrum AreaLight::L(const Vec3f& n, Vec2f uv, const Vec3f& w, const SampledWavelengths& lambda) const {
  if (!two_sided_ && Dot(n, w) <= 0) return {};
  return radiance_->Evaluate(uv, lambda);
}

std::optional<LightSample> AreaLight::SampleLi(const Vec3f& ref, Vec2f u, const SampledWavelengths& lambda) const {
  // Filled in place and returned by one name on every path (so the optional is built in the
  // caller's slot): assembling it elsewhere and copying it over stalled on store forwarding,
  // a measurable part of the render.
  std::optional<LightSample> out;
  ShapeSample ss = shape_->SampleFrom(ref, u);
  Vec3f d = ss.p - ref;
  float dist2 = LengthSquared(d);
  if (ss.pdf > 0 && dist2 > 0) {
    LightSample& s = out.emplace();
    s.wi = d / std::sqrt(dist2);
    s.L = L(ss.n, ss.uv, -s.wi, lambda);
    s.pdf = ss.pdf;
    s.p = ss.p;
    s.p_error = ss.p_error;
    s.n = ss.n;
    if (s.L.IsBlack()) out.reset();
  }
  return out;
}

std::optional<LightLeSample> AreaLight::SampleLe(Vec2f u_pos, Vec2f u_dir, const SampledWavelengths& lambda) const {
  const ShapeSample ss = shape_->SampleArea(u_pos);
  if (!(ss.pdf > 0)) return std::nullopt;
  Vec3f n = ss.n;
  float side_pmf = 1;
  if (two_sided_) {  // the first half of u_dir.x picks the front, the second the back
    side_pmf = 0.5f;
    if (u_dir.x < 0.5f) {
      u_dir.x = std::min(2 * u_dir.x, kOneMinusEpsilon);
    } else {
      u_dir.x = std::min(2 * (u_dir.x - 0.5f), kOneMinusEpsilon);
      n = -n;
    }
  }
  const Vec3f local = SampleCosineHemisphere(u_dir);
  if (!(local.z > 0)) return std::nullopt;
  const Vec3f d = Normalize(Frame::FromZ(n).FromLocal(local));
  LightLeSample s;
  s.ray = Ray{OffsetRayOrigin(ss.p, ss.p_error, n, d), d};
  s.L = L(ss.n, ss.uv, d, lambda);
  if (s.L.IsBlack()) return std::nullopt;
  s.n = ss.n;
  s.pdf_pos = ss.pdf;
  s.pdf_dir = side_pmf * CosineHemispherePdf(local.z);
  return s;
}

float AreaLight::PdfLi(const Vec3f& ref, const SurfaceInteraction& hit) const { return shape_->PdfFrom(ref, hit); }

}  // namespace objektiv
