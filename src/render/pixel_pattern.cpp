#include "render/pixel_pattern.h"

#include <algorithm>
#include <cmath>

#include "base/rng.h"

namespace objektiv {

const char* PixelPatternName(PixelPattern p) {
  switch (p) {
    case PixelPattern::kSampler: return "sampler";
    case PixelPattern::kGrid: return "grid";
    case PixelPattern::kRgss: return "rgss";
    case PixelPattern::kQuincunx: return "quincunx";
  }
  return "?";
}

namespace {
int GridSide(int spp) { return std::max(1, int(std::floor(std::sqrt(double(std::max(spp, 1)))))); }

// In [0,1), 1 itself kept just below (the filters sample [0,1)).
float Unit(float v) { return std::min(v, kOneMinusEpsilon); }

// The round's toroidal shift: 0 for round 0, else uniform per (pixel, round).
Vec2f RoundShift(int round, uint64_t pixel_hash) {
  if (round == 0) return {0.f, 0.f};
  const uint64_t h = Hash(pixel_hash, uint64_t(round), 0x5d1f7a3cull);
  return {UIntToUnitFloat(uint32_t(h)), UIntToUnitFloat(uint32_t(h >> 32))};
}

Vec2f Wrap(Vec2f p, Vec2f shift) {
  float x = p.x + shift.x, y = p.y + shift.y;
  if (shift.x != 0) x -= std::floor(x);
  if (shift.y != 0) y -= std::floor(y);
  return {Unit(x), Unit(y)};
}
}  // namespace

int PatternRoundSize(PixelPattern p, int spp) {
  switch (p) {
    case PixelPattern::kGrid: return GridSide(spp) * GridSide(spp);
    case PixelPattern::kRgss: return 4;
    case PixelPattern::kQuincunx: return 5;
    default: return 1;
  }
}

PatternSample PatternPosition(PixelPattern p, int spp, int index, uint64_t pixel_hash) {
  switch (p) {
    case PixelPattern::kGrid: {
      const int side = GridSide(spp), n = side * side;
      const int round = index / n, j = index % n;
      const Vec2f cell((j % side + 0.5f) / side, (j / side + 0.5f) / side);
      return {Wrap(cell, RoundShift(round, pixel_hash)), 1.f};
    }
    case PixelPattern::kRgss: {
      static const Vec2f kRgss[4] = {{0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};
      return {Wrap(kRgss[index % 4], RoundShift(index / 4, pixel_hash)), 1.f};
    }
    case PixelPattern::kQuincunx: {
      if (index < 5) {  // the classic pattern: centre 1/2, corners 1/8 (x 5: a mean weight of 1)
        static const Vec2f kQuincunx[5] = {{0.5f, 0.5f}, {0.f, 0.f}, {1.f, 0.f}, {0.f, 1.f}, {1.f, 1.f}};
        const Vec2f q = kQuincunx[index];
        return {Vec2f(Unit(q.x), Unit(q.y)), index == 0 ? 2.5f : 0.625f};
      }
      // The quincunx lattice shifted: its centre point and its (one, wrapped) corner point.
      const int round = 1 + (index - 5) / 2, j = (index - 5) % 2;
      return {Wrap(j == 0 ? Vec2f(0.5f, 0.5f) : Vec2f(0.f, 0.f), RoundShift(round, pixel_hash)), 1.f};
    }
    default:
      return {{0.5f, 0.5f}, 1.f};
  }
}

}  // namespace objektiv
