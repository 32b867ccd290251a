// Samplers: every number is a pure function of (pixel, sample index, dimension, seed), so
// images do not depend on thread count or tile order, and sample ranges can be merged.
#pragma once
#include <memory>

#include "base/lowdiscrepancy.h"
#include "base/rng.h"

namespace objektiv {

class Sampler {
 public:
  Sampler(int spp, uint64_t seed) : spp_(spp), seed_(seed) {}
  virtual ~Sampler() = default;
  virtual std::unique_ptr<Sampler> Clone() const = 0;

  virtual void StartPixelSample(Vec2i pixel, int index) {
    pixel_ = pixel;
    index_ = index;
    dim_ = 0;
    pixel_hash_ = Hash(pixel.x, pixel.y, seed_);
  }
  virtual float Get1D() = 0;
  virtual Vec2f Get2D() = 0;
  // The film position within the pixel (the first dimensions, best stratified).
  virtual Vec2f GetPixel2D() { return Get2D(); }
  int spp() const { return spp_; }

 protected:
  int spp_;
  uint64_t seed_;
  // Per-dimension seed: a function of (pixel, seed) hashed once per sample, and the dimension.
  uint64_t DimensionHash(int dim) const { return MixBits(pixel_hash_ ^ (uint64_t(dim) * 0x9e3779b97f4a7c15ull)); }

  Vec2i pixel_;
  int index_ = 0, dim_ = 0;
  uint64_t pixel_hash_ = 0;
};

// Uniform random numbers from PCG32, jumped to (pixel, index, dimension).
class IndependentSampler final : public Sampler {
 public:
  using Sampler::Sampler;
  std::unique_ptr<Sampler> Clone() const override { return std::make_unique<IndependentSampler>(*this); }
  void StartPixelSample(Vec2i pixel, int index) override;
  float Get1D() override { return rng_.UniformFloat(); }
  Vec2f Get2D() override {
    float a = rng_.UniformFloat();
    return {a, rng_.UniformFloat()};
  }

 private:
  PCG32 rng_;
};

// Jittered strata: per dimension (or pair), the sample index is mapped through a random
// permutation to a stratum. The sample count is rounded up to a square for the 2D strata.
class StratifiedSampler final : public Sampler {
 public:
  StratifiedSampler(int spp, uint64_t seed);
  std::unique_ptr<Sampler> Clone() const override { return std::make_unique<StratifiedSampler>(*this); }
  float Get1D() override;
  Vec2f Get2D() override;

 private:
  int side_;
};

// Owen-scrambled Sobol' (as pbrt-v4's default): each dimension pair is its own shuffled,
// scrambled 2D Sobol' net; the first spp points of any pair are a (0,m,2)-net for spp = 2^m.
class SobolSampler final : public Sampler {
 public:
  using Sampler::Sampler;
  std::unique_ptr<Sampler> Clone() const override { return std::make_unique<SobolSampler>(*this); }
  float Get1D() override;
  Vec2f Get2D() override;
};

}  // namespace objektiv
