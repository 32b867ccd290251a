#include "scene/phase_function.h"

#include <algorithm>
#include <cmath>

#include "base/frame.h"
#include "base/sampling.h"

namespace objektiv {

float HenyeyGreenstein(float cos_theta, float g) {
  const float denom = 1 + g * g - 2 * g * cos_theta;
  return kInv4Pi * (1 - g * g) / (denom * std::sqrt(std::max(denom, 1e-12f)));
}

HGPhaseFunction::HGPhaseFunction(float g) : g_(std::clamp(g, -0.999f, 0.999f)) {}

float HGPhaseFunction::p(const Vec3f& wo, const Vec3f& wi) const { return HenyeyGreenstein(-Dot(wo, wi), g_); }

PhaseSample HGPhaseFunction::Sample(const Vec3f& wo, Vec2f u) const {
  // Inverse CDF of cos theta: cos = (1 + g^2 - ((1 - g^2) / (1 - g + 2 g u))^2) / (2 g), which
  // runs from -1 at u = 0 to 1 at u = 1; uniform in [-1, 1] near g = 0 (the formula cancels).
  float cos_theta;
  if (std::abs(g_) < 1e-3f) {
    cos_theta = 1 - 2 * u[0];
  } else {
    const float s = (1 - g_ * g_) / (1 - g_ + 2 * g_ * u[0]);
    cos_theta = (1 + g_ * g_ - s * s) / (2 * g_);
  }
  cos_theta = std::clamp(cos_theta, -1.f, 1.f);
  const float sin_theta = std::sqrt(std::max(0.f, 1 - cos_theta * cos_theta));
  const float phi = 2 * kPi * u[1];
  // Around the propagation direction -wo.
  const Frame f = Frame::FromZ(-wo);
  const Vec3f wi = f.FromLocal(Vec3f(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta));
  return {wi, HenyeyGreenstein(cos_theta, g_)};
}

}  // namespace objektiv
