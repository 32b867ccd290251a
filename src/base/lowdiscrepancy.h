// Owen-scrambled Sobol' points (first two dimensions), as used by the padded Sobol sampler:
// each pair of dimensions takes the 2D Sobol' net with its own scramble and index shuffle
// (Burley 2020, "Practical Hash-based Owen Scrambling").
#pragma once
#include <cstdint>

#include "base/rng.h"
#include "base/vec.h"

namespace objektiv {

inline uint32_t ReverseBits32(uint32_t n) {
  n = __builtin_bswap32(n);
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

// Sobol1 by bytes: the XOR of the generator columns selected by each byte of the index is
// tabulated (4 x 256 entries), so a point costs four lookups instead of a 32-step loop.
struct ByteTables {
  uint32_t t[4][256];
  // Tables for the linear map (over GF(2)) whose column for input bit i is columns[i].
  constexpr explicit ByteTables(const uint32_t (&columns)[32]) : t{} {
    for (int b = 0; b < 4; ++b)
      for (int x = 0; x < 256; ++x) {
        uint32_t r = 0;
        for (int bit = 0; bit < 8; ++bit)
          if (x & (1 << bit)) r ^= columns[8 * b + bit];
        t[b][x] = r;
      }
  }
  constexpr uint32_t operator()(uint32_t v) const {
    return t[0][v & 0xff] ^ t[1][(v >> 8) & 0xff] ^ t[2][(v >> 16) & 0xff] ^ t[3][v >> 24];
  }
};

// The generator columns of dimension 1 (polynomial x + 1): v_1 = 2^31, v_k = v_(k-1) ^ v_(k-1) / 2.
// `reversed`: the same map seen through bit reversal on both sides, Sobol1Reversed(Reverse(i)) =
// Reverse(Sobol1(i)), which lets the scrambled sampler below skip two reversals per point.
constexpr ByteTables Sobol1Map(bool reversed) {
  uint32_t columns[32] = {};
  uint32_t v = 1u << 31;
  for (int i = 0; i < 32; ++i, v ^= v >> 1) {
    if (!reversed) {
      columns[i] = v;
      continue;
    }
    uint32_t r = 0;
    for (int b = 0; b < 32; ++b)
      if (v & (1u << b)) r |= 1u << (31 - b);
    columns[31 - i] = r;  // input bit i of the index is bit 31 - i of the reversed index
  }
  return ByteTables(columns);
}
inline constexpr ByteTables kSobol1 = Sobol1Map(false), kSobol1Reversed = Sobol1Map(true);

inline uint32_t Sobol1(uint32_t index) { return kSobol1(index); }
inline uint32_t Sobol1Reversed(uint32_t index_reversed) { return kSobol1Reversed(index_reversed); }

// Point `index` of the shuffled, Owen-scrambled 2D Sobol' net for a 64-bit seed. The
// index shuffle is itself a nested uniform scramble (Burley 2020), which keeps every
// aligned power-of-two block of indices a (0,m,2)-net. Nested scrambles are applied as
// Reverse(LK(Reverse(v))); adjacent reversals cancel and are left out.
inline Vec2f ScrambledSobol2D(uint32_t index, uint64_t seed) {
  uint32_t s_index = uint32_t(seed), s_x = uint32_t(seed >> 32), s_y = uint32_t(MixBits(seed));
  uint32_t shuffled = ReverseBits32(LaineKarrasPermutation(ReverseBits32(index), s_index));
  uint32_t x = ReverseBits32(LaineKarrasPermutation(shuffled, s_x));  // Sobol0 = Reverse(shuffled)
  uint32_t y = ReverseBits32(LaineKarrasPermutation(ReverseBits32(Sobol1(shuffled)), s_y));
  return {UIntToUnitFloat(x), UIntToUnitFloat(y)};
}

// The same points from the bit-reversed index (reversed once per sample by the sampler).
// With r = LK(Reverse(index)) = Reverse(shuffled): x = Reverse(LK(Reverse(r))) and
// y = Reverse(LK(Reverse(Sobol1(shuffled)))) = Reverse(LK(Sobol1Reversed(r))).
inline Vec2f ScrambledSobol2DReversed(uint32_t index_reversed, uint64_t seed) {
  uint32_t s_index = uint32_t(seed), s_x = uint32_t(seed >> 32), s_y = uint32_t(MixBits(seed));
  uint32_t r = LaineKarrasPermutation(index_reversed, s_index);
  uint32_t x = ReverseBits32(LaineKarrasPermutation(ReverseBits32(r), s_x));
  uint32_t y = ReverseBits32(LaineKarrasPermutation(Sobol1Reversed(r), s_y));
  return {UIntToUnitFloat(x), UIntToUnitFloat(y)};
}

inline float ScrambledSobol1DReversed(uint32_t index_reversed, uint64_t seed) {
  uint32_t r = LaineKarrasPermutation(index_reversed, uint32_t(seed));
  return UIntToUnitFloat(ReverseBits32(LaineKarrasPermutation(ReverseBits32(r), uint32_t(seed >> 32))));
}

inline float ScrambledSobol1D(uint32_t index, uint64_t seed) {
  uint32_t s_index = uint32_t(seed), s_x = uint32_t(seed >> 32);
  uint32_t shuffled = ReverseBits32(LaineKarrasPermutation(ReverseBits32(index), s_index));
  return UIntToUnitFloat(ReverseBits32(LaineKarrasPermutation(shuffled, s_x)));
}

}  // namespace objektiv
