#include "scene/infinite_light.h"

#include <cmath>
#include <limits>

#include "base/color_space.h"
#include "base/frame.h"
#include "scene/texture.h"

namespace objektiv {

namespace {
LightSample EscapingSample(const Vec3f& ref, const Vec3f& wi, float radius, SampledSpectrum L, float pdf) {
  LightSample s;
  s.wi = wi;
  s.L = L;
  s.pdf = pdf;
  s.p = ref + wi * (2 * radius);
  s.infinite = true;
  return s;
}
}  // namespace

std::optional<LightLeSample> InfiniteLight::SampleLe(Vec2f u_pos, Vec2f u_dir, const SampledWavelengths& lambda) const {
  const std::optional<LightSample> ls = SampleLi(scene_center_, u_dir, lambda);
  if (!ls || !(ls->pdf > 0) || ls->L.IsBlack()) return std::nullopt;
  const Vec2f disc = SampleUniformDiskConcentric(u_pos);
  const Frame frame = Frame::FromZ(ls->wi);
  LightLeSample s;
  s.ray = Ray{scene_center_ + scene_radius_ * (ls->wi + frame.s * disc.x + frame.t * disc.y), -ls->wi};
  s.L = ls->L;
  s.pdf_pos = 1 / (kPi * scene_radius_ * scene_radius_);
  s.pdf_dir = ls->pdf;
  return s;
}

std::optional<LightSample> ConstantEnvironment::SampleLi(const Vec3f& ref, Vec2f u, const SampledWavelengths& lambda) const {
  Vec3f wi = SampleUniformSphere(u);
  return EscapingSample(ref, wi, scene_radius_ + Length(ref - scene_center_), radiance_.Sample(lambda), UniformSpherePdf());
}

float ConstantEnvironment::Power() const { return kPi * 4 * kPi * scene_radius_ * scene_radius_ * SpectrumToY(radiance_); }

EnvironmentMap::EnvironmentMap(Image rgb, float scale, const Transform& to_world)
    : image_(std::move(rgb)), scale_(scale), to_world_(to_world), to_local_(to_world.Inverse()) {
  const int w = image_.width, h = image_.height;
  std::vector<float> weights(size_t(w) * h);
  const ColorSpace& cs = ColorSpace::Rec709();
  double sum_y = 0;
  for (int y = 0; y < h; ++y) {
    float sin_theta = std::sin(kPi * (y + 0.5f) / h);
    for (int x = 0; x < w; ++x) {
      float lum = std::max(0.f, cs.ToXYZ(image_.Rgb(x, y)).y);
      sum_y += lum * sin_theta;
      // Texels the sampler cannot reach are still found by BSDF sampling (MIS keeps it unbiased).
      weights[size_t(y) * w + x] = lum * sin_theta;
    }
  }
  mean_y_ = float(sum_y / (double(w) * h)) * scale_;
  distribution_ = Distribution2D(weights, w, h);
}

Vec2f EnvironmentMap::DirectionToUv(const Vec3f& w_world) const {
  Vec3f d = Normalize(to_local_.Vector(w_world));
  float u = std::atan2(d.x, -d.z) * kInv2Pi;
  if (u < 0) u += 1;
  return {u, std::acos(Clamp(d.y, -1, 1)) * kInvPi};
}

Vec3f EnvironmentMap::UvToDirection(Vec2f uv) const {
  float phi = uv.x * 2 * kPi, theta = uv.y * kPi;
  float st = std::sin(theta);
  return Normalize(to_world_.Vector(Vec3f(std::sin(phi) * st, std::cos(theta), -std::cos(phi) * st)));
}

Vec3f EnvironmentMap::Lookup(Vec2f uv) const {
  // Bilinear, wrapping in u and clamping in v.
  float x = WrapTexelCoordinate(uv.x * image_.width - 0.5f, WrapMode::kRepeat, image_.width);
  float y = WrapTexelCoordinate(uv.y * image_.height - 0.5f, WrapMode::kClamp, image_.height);
  if (std::isnan(x) || std::isnan(y)) return Vec3f(std::numeric_limits<float>::quiet_NaN());  // a NaN direction
  int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  float dx = x - x0, dy = y - y0;
  auto texel = [&](int xi, int yi) {
    xi = ((xi % image_.width) + image_.width) % image_.width;
    yi = std::clamp(yi, 0, image_.height - 1);
    return image_.Rgb(xi, yi);
  };
  return (texel(x0, y0) * (1 - dx) + texel(x0 + 1, y0) * dx) * (1 - dy) +
         (texel(x0, y0 + 1) * (1 - dx) + texel(x0 + 1, y0 + 1) * dx) * dy;
}

SampledSpectrum EnvironmentMap::Le(const Vec3f& w, const SampledWavelengths& lambda) const {
  return RgbToSampled(Lookup(DirectionToUv(w)) * scale_, SpectrumUsage::kIlluminant, lambda);
}

std::optional<LightSample> EnvironmentMap::SampleLi(const Vec3f& ref, Vec2f u, const SampledWavelengths& lambda) const {
  float map_pdf;
  Vec2f uv = distribution_.Sample(u, &map_pdf);
  if (map_pdf == 0) return std::nullopt;
  float sin_theta = std::sin(uv.y * kPi);
  if (sin_theta == 0) return std::nullopt;
  Vec3f wi = UvToDirection(uv);
  // (u, v) -> (phi, theta) -> solid angle: dw = sin(theta) dtheta dphi = 2 pi^2 sin(theta) du dv.
  float pdf = map_pdf / (2 * kPi * kPi * sin_theta);
  return EscapingSample(ref, wi, scene_radius_ + Length(ref - scene_center_), Le(wi, lambda), pdf);
}

float EnvironmentMap::PdfLi(const Vec3f& w) const {
  Vec2f uv = DirectionToUv(w);
  float sin_theta = std::sin(uv.y * kPi);
  if (!(sin_theta > 0)) return 0;  // a pole, or a NaN direction
  return distribution_.Pdf(uv) / (2 * kPi * kPi * sin_theta);
}

float EnvironmentMap::Power() const { return kPi * 4 * kPi * scene_radius_ * scene_radius_ * mean_y_; }

}  // namespace objektiv
