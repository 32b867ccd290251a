#include "render/sampler.h"

#include <cmath>

namespace objektiv {

const char* AdaptiveModeName(AdaptiveMode m) {
  switch (m) {
    case AdaptiveMode::kNone: return "none";
    case AdaptiveMode::kStatistical: return "statistical";
    case AdaptiveMode::kWhitted: return "whitted";
  }
  return "?";
}

Sampler::Sampler(SamplerKind kind, int spp, uint64_t seed, PixelPattern pattern, AdaptiveSettings adaptive)
    : kind_(kind), pattern_(pattern), adaptive_(adaptive), spp_(spp), seed_(seed) {
  if (kind == SamplerKind::kStratified) {
    side_ = int(std::ceil(std::sqrt(double(spp))));
    spp_ = side_ * side_;
  }
}

namespace {
// A random permutation of [0, n) evaluated at i, without storing it (Kensler 2013,
// "Correlated Multi-Jittered Sampling"), by cycle-walking a hash-based bijection.
uint32_t PermutationElement(uint32_t i, uint32_t n, uint32_t seed) {
  uint32_t w = n - 1;
  w |= w >> 1;
  w |= w >> 2;
  w |= w >> 4;
  w |= w >> 8;
  w |= w >> 16;
  do {
    i ^= seed;
    i *= 0xe170893du;
    i ^= seed >> 16;
    i ^= (i & w) >> 4;
    i ^= seed >> 8;
    i *= 0x0929eb3fu;
    i ^= seed >> 23;
    i ^= (i & w) >> 1;
    i *= 1 | seed >> 27;
    i *= 0x6935fa69u;
    i ^= (i & w) >> 11;
    i *= 0x74dcb303u;
    i ^= (i & w) >> 2;
    i *= 0x9e501cc3u;
    i ^= (i & w) >> 2;
    i *= 0xc860a3dfu;
    i &= w;
    i ^= i >> 5;
  } while (i >= n);
  return (i + seed) % n;
}
}  // namespace

float Sampler::Stratified1D() {
  uint64_t h = DimensionHash(dim_++);
  uint32_t n = uint32_t(spp_);
  uint32_t stratum = PermutationElement(uint32_t(index_) % n, n, uint32_t(h));
  float jitter = UIntToUnitFloat(uint32_t(MixBits(h ^ uint64_t(index_))));
  return std::min((stratum + jitter) / n, kOneMinusEpsilon);
}

Vec2f Sampler::Stratified2D() {
  uint64_t h = DimensionHash(dim_);
  dim_ += 2;
  uint32_t n = uint32_t(spp_);
  uint32_t stratum = PermutationElement(uint32_t(index_) % n, n, uint32_t(h));
  uint32_t sx = stratum % side_, sy = stratum / side_;
  uint64_t j = MixBits(h ^ uint64_t(index_));
  float dx = UIntToUnitFloat(uint32_t(j)), dy = UIntToUnitFloat(uint32_t(j >> 32));
  return {std::min((sx + dx) / side_, kOneMinusEpsilon), std::min((sy + dy) / side_, kOneMinusEpsilon)};
}

}  // namespace objektiv
