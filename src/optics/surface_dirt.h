// Dust and scratches on a lens surface: a fixed pattern over its clear aperture that absorbs
// the light meeting it, drawn from a seed (the same seed, the same pattern).
//
// Dust: opaque round particles, their radii log-uniform from 5 to 75 um, centres uniform over
// the clear aperture, as many as cover `coverage` of its area on average (particles may
// overlap: the share of the aperture blocked is 1 - exp(-coverage) in expectation).
// Scratches: `count` opaque straight strokes, each of random direction through a uniform point
// of the aperture, 0.1 to 0.6 semi-diameters long and 2 to 12 um wide.
//
// Light meeting either is lost (what it scatters is not traced): near the film, and with the
// lens stopped down, dust casts the dark blurred spots photographers know from the sky; on a
// front element, far from focus, it only dims the image a little. Points are looked up in a
// uniform grid (cells at least the largest particle's diameter wide), a few particles a cell.
#pragma once
#include <cstdint>
#include <vector>

#include "base/vec.h"

namespace objektiv {

class SurfaceDirt {
 public:
  struct Particle {
    double x, y, r;  // mm, in the surface's frame
  };
  struct Scratch {
    double x0, y0, x1, y1, half_width;  // a stroke from (x0, y0) to (x1, y1), mm
  };
  // Drawn from the seed over a clear aperture of `semi_diameter` mm.
  SurfaceDirt(double coverage, int scratches, uint64_t seed, double semi_diameter);
  // Given particles and strokes (tests).
  SurfaceDirt(std::vector<Particle> particles, std::vector<Scratch> scratches, double semi_diameter);

  // 1 where light gets through at (x, y) of the surface's frame, 0 where dust or a scratch is.
  double Transmittance(double x, double y) const;
  // The share of the clear aperture left clear, exp(-(the items' total area) / (its area)) (the
  // expectation for items placed at random): what the dirt lets through on average, for images
  // traced on grids coarser than the particles.
  double MeanTransmittance() const { return mean_; }

  double coverage() const { return coverage_; }
  int scratch_count() const { return int(scratches_.size()); }
  uint64_t seed() const { return seed_; }
  size_t particle_count() const { return particles_.size(); }
  // The same pattern on a lens `factor` times larger (the particles too: a scaled drawing).
  SurfaceDirt Scaled(double factor) const;

  static constexpr double kMaxCoverage = 0.5;
  static constexpr int kMaxScratches = 1000;
  static constexpr double kMaxParticles = 2e6;
  // How many particles cover `coverage` of a clear aperture of `semi_diameter` mm.
  static double ParticleCount(double coverage, double semi_diameter);

 private:
  void BuildGrid();
  double coverage_ = 0;
  uint64_t seed_ = 0;
  double semi_ = 0;
  std::vector<Particle> particles_;
  std::vector<Scratch> scratches_;
  // Grid over [-extent, extent]^2 (the aperture and every item whole): per cell, indices into
  // particles_ (>= 0) and scratches_ (~index).
  double extent_ = 0;
  double mean_ = 1;
  int cells_ = 1;
  double cell_size_ = 1;
  std::vector<uint32_t> cell_start_;
  std::vector<int32_t> cell_items_;
};

}  // namespace objektiv
