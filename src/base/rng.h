// Random numbers and hashing. Every random number in a render is a function of
// (pixel, sample index, dimension, seed): the samplers build on Hash() and PCG32 below.
#pragma once
#include <cstdint>
#include <cstring>

namespace objektiv {

// 64-bit finaliser of SplitMix64: a bijective avalanche mix.
inline uint64_t MixBits(uint64_t v) {
  v ^= v >> 31;
  v *= 0x7fb5d329728ea185ull;
  v ^= v >> 27;
  v *= 0x81dadef4bc2dd44dull;
  v ^= v >> 33;
  return v;
}

// Hash of any number of integral arguments (order matters).
template <typename... Args>
uint64_t Hash(Args... args) {
  uint64_t h = 0x9e3779b97f4a7c15ull;
  ((h = MixBits(h ^ (uint64_t(args) + 0x632be59bd9b4e019ull))), ...);
  return h;
}

// 1 / 2^32 below 1: the largest float strictly less than one.
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

inline float UIntToUnitFloat(uint32_t v) {
  float f = float(v >> 8) * 0x1p-24f;
  return f < kOneMinusEpsilon ? f : kOneMinusEpsilon;
}

// PCG32 (O'Neill 2014): small state, good quality, supports jumping ahead.
class PCG32 {
 public:
  PCG32() { SetSequence(0x853c49e6748fea9bull, 0xda3e39cb94b95bdbull); }
  PCG32(uint64_t seq_index, uint64_t seed) { SetSequence(seq_index, seed); }

  void SetSequence(uint64_t seq_index, uint64_t seed) {
    state_ = 0u;
    inc_ = (seq_index << 1u) | 1u;
    Uniform32();
    state_ += seed;
    Uniform32();
  }
  void SetSequence(uint64_t seq_index) { SetSequence(seq_index, MixBits(seq_index)); }

  uint32_t Uniform32() {
    uint64_t old = state_;
    state_ = old * kMult + inc_;
    uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31));
  }
  float UniformFloat() { return UIntToUnitFloat(Uniform32()); }

  // Jump ahead by delta steps in O(log delta) (Brown, "Random number generation with arbitrary strides").
  void Advance(uint64_t delta) {
    uint64_t cur_mult = kMult, cur_plus = inc_, acc_mult = 1u, acc_plus = 0u;
    while (delta > 0) {
      if (delta & 1) {
        acc_mult *= cur_mult;
        acc_plus = acc_plus * cur_mult + cur_plus;
      }
      cur_plus = (cur_mult + 1) * cur_plus;
      cur_mult *= cur_mult;
      delta /= 2;
    }
    state_ = acc_mult * state_ + acc_plus;
  }

 private:
  static constexpr uint64_t kMult = 0x5851f42d4c957f2dull;
  uint64_t state_, inc_;
};

}  // namespace objektiv
