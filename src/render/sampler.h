// Samplers: every number is a pure function of (pixel, sample index, dimension, seed), so
// images do not depend on thread count or tile order, and sample ranges can be merged.
// One concrete class (the kind is a switch, well predicted) so that the integrators' many
// calls per path vertex inline instead of going through virtual dispatch.
#pragma once
#include <memory>

#include "base/lowdiscrepancy.h"
#include "base/rng.h"

namespace objektiv {

enum class SamplerKind {
  kIndependent,  // uniform random numbers from PCG32, jumped to (pixel, index, dimension)
  kStratified,   // jittered strata; per dimension (or pair) the index is permuted to a stratum;
                 // the count is rounded up to a square for the 2D strata
  kSobol,        // Owen-scrambled Sobol' (as pbrt-v4's default): each dimension pair is its own
                 // shuffled, scrambled 2D net; the first 2^m points of a pair are a (0,m,2)-net
};

class Sampler {
 public:
  Sampler(SamplerKind kind, int spp, uint64_t seed);
  std::unique_ptr<Sampler> Clone() const { return std::make_unique<Sampler>(*this); }

  void StartPixelSample(Vec2i pixel, int index) {
    pixel_hash_ = Hash(pixel.x, pixel.y, seed_);
    index_ = index;
    dim_ = 0;
    if (kind_ == SamplerKind::kIndependent) {
      rng_.SetSequence(pixel_hash_);
      rng_.Advance(uint64_t(index) << 16);  // 2^16 numbers per sample: more than any path uses
    } else if (kind_ == SamplerKind::kSobol) {
      index_reversed_ = ReverseBits32(uint32_t(index));
    }
  }

  float Get1D() {
    switch (kind_) {
      case SamplerKind::kIndependent:
        return rng_.UniformFloat();
      case SamplerKind::kSobol:
        return ScrambledSobol1DReversed(index_reversed_, DimensionHash(dim_++));
      default:
        return Stratified1D();
    }
  }

  Vec2f Get2D() {
    switch (kind_) {
      case SamplerKind::kIndependent: {
        float a = rng_.UniformFloat();
        return {a, rng_.UniformFloat()};
      }
      case SamplerKind::kSobol: {
        uint64_t h = DimensionHash(dim_);
        dim_ += 2;
        return ScrambledSobol2DReversed(index_reversed_, h);
      }
      default:
        return Stratified2D();
    }
  }

  // The film position within the pixel (the first dimensions, best stratified).
  Vec2f GetPixel2D() { return Get2D(); }
  int spp() const { return spp_; }
  SamplerKind kind() const { return kind_; }

 private:
  // Per-dimension seed: a function of (pixel, seed), hashed once per sample, and the dimension.
  uint64_t DimensionHash(int dim) const { return MixBits(pixel_hash_ ^ (uint64_t(dim) * 0x9e3779b97f4a7c15ull)); }
  float Stratified1D();
  Vec2f Stratified2D();

  SamplerKind kind_;
  int spp_;
  uint64_t seed_;
  int side_ = 1;  // stratified: strata per axis
  int index_ = 0, dim_ = 0;
  uint32_t index_reversed_ = 0;
  uint64_t pixel_hash_ = 0;
  PCG32 rng_;
};

}  // namespace objektiv
