// Owen-scrambled Sobol' points (first two dimensions), as used by the padded Sobol sampler:
// each pair of dimensions takes the 2D Sobol' net with its own scramble and index shuffle
// (Burley 2020, "Practical Hash-based Owen Scrambling").
#pragma once
#include <cstdint>

#include "base/rng.h"
#include "base/vec.h"

namespace objektiv {

inline uint32_t ReverseBits32(uint32_t n) {
  n = (n << 16) | (n >> 16);
  n = ((n & 0x00ff00ffu) << 8) | ((n & 0xff00ff00u) >> 8);
  n = ((n & 0x0f0f0f0fu) << 4) | ((n & 0xf0f0f0f0u) >> 4);
  n = ((n & 0x33333333u) << 2) | ((n & 0xccccccccu) >> 2);
  n = ((n & 0x55555555u) << 1) | ((n & 0xaaaaaaaau) >> 1);
  return n;
}

// Laine-Karras style permutation in which each output bit depends only on the same and
// lower input bits; applied to bit-reversed values it is a nested uniform (Owen) scramble.
inline uint32_t LaineKarrasPermutation(uint32_t x, uint32_t seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

inline uint32_t NestedUniformScramble(uint32_t x, uint32_t seed) {
  return ReverseBits32(LaineKarrasPermutation(ReverseBits32(x), seed));
}

// Dimension 0 of Sobol' is the van der Corput sequence; dimension 1 uses the generator
// matrix of the primitive polynomial x + 1 (the Pascal matrix mod 2).
inline uint32_t Sobol0(uint32_t index) { return ReverseBits32(index); }
inline uint32_t Sobol1(uint32_t index) {
  uint32_t v = 1u << 31, result = 0;
  for (; index; index >>= 1, v ^= v >> 1)
    if (index & 1) result ^= v;
  return result;
}

// Point `index` of the shuffled, Owen-scrambled 2D Sobol' net with the given seed.
inline Vec2f ScrambledSobol2D(uint32_t index, uint64_t seed) {
  uint32_t shuffled = NestedUniformScramble(index, uint32_t(MixBits(seed ^ 0x1234)));
  uint32_t x = NestedUniformScramble(Sobol0(shuffled), uint32_t(MixBits(seed ^ 0xa511e9b3)));
  uint32_t y = NestedUniformScramble(Sobol1(shuffled), uint32_t(MixBits(seed ^ 0x63d83595)));
  return {UIntToUnitFloat(x), UIntToUnitFloat(y)};
}

inline float ScrambledSobol1D(uint32_t index, uint64_t seed) {
  uint32_t shuffled = NestedUniformScramble(index, uint32_t(MixBits(seed ^ 0x1234)));
  return UIntToUnitFloat(NestedUniformScramble(Sobol0(shuffled), uint32_t(MixBits(seed ^ 0xa511e9b3))));
}

}  // namespace objektiv
