// Samplers: every number is a pure function of (pixel, sample index, dimension, seed), so
// images do not depend on thread count or tile order, and sample ranges can be merged.
// One concrete class (the kind is a switch, well predicted) so that the integrators' many
// calls per path vertex inline instead of going through virtual dispatch.
#pragma once
#include <memory>

#include "base/lowdiscrepancy.h"
#include "base/rng.h"
#include "render/pixel_pattern.h"

namespace objektiv {

enum class SamplerKind {
  kIndependent,  // uniform random numbers from PCG32, jumped to (pixel, index, dimension)
  kStratified,   // jittered strata; per dimension (or pair) the index is permuted to a stratum;
                 // the count is rounded up to a square for the 2D strata
  kSobol,        // Owen-scrambled Sobol' (as pbrt-v4's default): each dimension pair is its own
                 // shuffled, scrambled 2D net; the first 2^m points of a pair are a (0,m,2)-net
};

// How many samples each pixel takes (render/adaptive_sampling.h says what the modes do).
enum class AdaptiveMode {
  kNone,         // every pixel takes the render's samples
  kStatistical,  // samples until the pixel's estimated relative standard error is below threshold
  kWhitted,      // classic adaptive supersampling: corners and centre, quadrants subdivided
};
const char* AdaptiveModeName(AdaptiveMode m);

struct AdaptiveSettings {
  AdaptiveMode mode = AdaptiveMode::kNone;
  // statistical: the relative standard error of the pixel's mean luminance to reach;
  // whitted: the luminance contrast (max - min) / (max + min + floor) that subdivides.
  double threshold = 0.05;  // DefaultThreshold(mode) unless given
  static double DefaultThreshold(AdaptiveMode m) { return m == AdaptiveMode::kWhitted ? 0.1 : 0.05; }
  int min_samples = 16;  // statistical: the pilot every pixel takes (the cap is the sample count)
  // Luminance (the film's linear Y, before exposure) under which a pixel counts as dark: the
  // relative error is taken against max(|mean|, floor), the contrast's denominator adds it.
  double floor = 0.01;
  int max_depth = 2;  // whitted: subdivision levels below the pixel (0: corners and centre only)
};

class Sampler {
 public:
  Sampler(SamplerKind kind, int spp, uint64_t seed, PixelPattern pattern = PixelPattern::kSampler,
          AdaptiveSettings adaptive = {});
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

  // The film position within the pixel (the first dimensions, best stratified), in the
  // filter's sample space, and the sample's weight: the sampler's own numbers (weight 1), or the
  // pattern's position (render/pixel_pattern.h; the dimensions are taken all the same, so that
  // the path's numbers are those of the sampler either way).
  PatternSample GetPixelSample() {
    const Vec2f u = Get2D();
    if (pattern_ == PixelPattern::kSampler) return {u, 1.f};
    return PatternPosition(pattern_, spp_, index_, pixel_hash_);
  }
  Vec2f GetPixel2D() { return GetPixelSample().u; }
  int spp() const { return spp_; }
  int index() const { return index_; }  // of the sample started
  SamplerKind kind() const { return kind_; }
  PixelPattern pattern() const { return pattern_; }
  const AdaptiveSettings& adaptive() const { return adaptive_; }

 private:
  // Per-dimension seed: a function of (pixel, seed), hashed once per sample, and the dimension.
  uint64_t DimensionHash(int dim) const { return MixBits(pixel_hash_ ^ (uint64_t(dim) * 0x9e3779b97f4a7c15ull)); }
  float Stratified1D();
  Vec2f Stratified2D();

  SamplerKind kind_;
  PixelPattern pattern_;
  AdaptiveSettings adaptive_;
  int spp_;
  uint64_t seed_;
  int side_ = 1;  // stratified: strata per axis
  int index_ = 0, dim_ = 0;
  uint32_t index_reversed_ = 0;
  uint64_t pixel_hash_ = 0;
  PCG32 rng_;
};

}  // namespace objektiv
