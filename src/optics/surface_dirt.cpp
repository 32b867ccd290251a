#include "optics/surface_dirt.h"

#include <algorithm>
#include <cmath>

#include "base/rng.h"

namespace objektiv {

namespace {
constexpr double kMinRadius = 0.005, kMaxRadius = 0.075;  // mm: particles of 10 to 150 um across
constexpr int kMaxCellsPerSide = 1024;

double Uniform(PCG32& rng) { return (double(rng.Uniform32()) + 0.5) / 4294967296.0; }
}  // namespace

double SurfaceDirt::ParticleCount(double coverage, double semi_diameter) {
  // E[r^2] for log-uniform radii: (r1^2 - r0^2) / (2 ln(r1 / r0)); the count covers `coverage`
  // of the aperture's area pi semi^2 on average.
  const double mean_r2 = (kMaxRadius * kMaxRadius - kMinRadius * kMinRadius) / (2 * std::log(kMaxRadius / kMinRadius));
  return coverage * semi_diameter * semi_diameter / mean_r2;
}

SurfaceDirt::SurfaceDirt(double coverage, int scratches, uint64_t seed, double semi_diameter)
    : coverage_(coverage), seed_(seed), semi_(semi_diameter) {
  PCG32 rng(0x5eed, seed);
  const size_t count = size_t(std::llround(std::min(ParticleCount(coverage, semi_diameter), kMaxParticles)));
  particles_.reserve(count);
  for (size_t k = 0; k < count; ++k) {
    const double rho = semi_diameter * std::sqrt(Uniform(rng)), phi = 2 * M_PI * Uniform(rng);
    particles_.push_back({rho * std::cos(phi), rho * std::sin(phi), kMinRadius * std::pow(kMaxRadius / kMinRadius, Uniform(rng))});
  }
  for (int k = 0; k < scratches; ++k) {
    const double rho = semi_diameter * std::sqrt(Uniform(rng)), phi = 2 * M_PI * Uniform(rng);
    const double dir = M_PI * Uniform(rng), half_length = 0.5 * semi_diameter * (0.1 + 0.5 * Uniform(rng));
    const double cx = rho * std::cos(phi), cy = rho * std::sin(phi), ux = std::cos(dir), uy = std::sin(dir);
    scratches_.push_back({cx - ux * half_length, cy - uy * half_length, cx + ux * half_length, cy + uy * half_length,
                          0.5e-3 * (2 + 10 * Uniform(rng))});
  }
  BuildGrid();
}

SurfaceDirt::SurfaceDirt(std::vector<Particle> particles, std::vector<Scratch> scratches, double semi_diameter)
    : semi_(semi_diameter), particles_(std::move(particles)), scratches_(std::move(scratches)) {
  BuildGrid();
}

SurfaceDirt SurfaceDirt::Scaled(double factor) const {
  std::vector<Particle> p = particles_;
  for (Particle& q : p) q = {q.x * factor, q.y * factor, q.r * factor};
  std::vector<Scratch> s = scratches_;
  for (Scratch& q : s) q = {q.x0 * factor, q.y0 * factor, q.x1 * factor, q.y1 * factor, q.half_width * factor};
  SurfaceDirt out(std::move(p), std::move(s), semi_ * factor);
  out.coverage_ = coverage_, out.seed_ = seed_;
  return out;
}

void SurfaceDirt::BuildGrid() {
  double largest = 0;
  // The grid spans [-extent, extent]^2: the aperture and every item whole.
  extent_ = semi_;
  for (const Particle& p : particles_) {
    largest = std::max(largest, p.r);
    extent_ = std::max({extent_, std::abs(p.x) + p.r, std::abs(p.y) + p.r});
  }
  for (const Scratch& s : scratches_)
    extent_ = std::max({extent_, std::abs(s.x0) + s.half_width, std::abs(s.y0) + s.half_width, std::abs(s.x1) + s.half_width,
                        std::abs(s.y1) + s.half_width});
  const double side = 2 * extent_;
  // (Clamped in double: without particles the wanted count overflows an int.)
  cells_ = int(std::clamp(std::ceil(side / std::max(2 * largest, 1e-9)), 1.0, double(kMaxCellsPerSide)));
  cell_size_ = side / cells_;
  // Each item's cells: those its bounding box overlaps (a stroke's, along its length).
  std::vector<std::pair<uint32_t, int32_t>> entries;
  auto cell_range = [&](double lo, double hi, int& a, int& b) {
    a = std::clamp(int(std::floor((lo + extent_) / cell_size_)), 0, cells_ - 1);
    b = std::clamp(int(std::floor((hi + extent_) / cell_size_)), 0, cells_ - 1);
  };
  auto add_box = [&](double x0, double y0, double x1, double y1, int32_t item) {
    int ax, bx, ay, by;
    cell_range(x0, x1, ax, bx);
    cell_range(y0, y1, ay, by);
    for (int j = ay; j <= by; ++j)
      for (int i = ax; i <= bx; ++i) entries.push_back({uint32_t(j * cells_ + i), item});
  };
  for (size_t k = 0; k < particles_.size(); ++k) {
    const Particle& p = particles_[k];
    add_box(p.x - p.r, p.y - p.r, p.x + p.r, p.y + p.r, int32_t(k));
  }
  for (size_t k = 0; k < scratches_.size(); ++k) {
    const Scratch& s = scratches_[k];
    const double length = std::hypot(s.x1 - s.x0, s.y1 - s.y0);
    const int pieces = std::max(1, int(std::ceil(length / (0.5 * cell_size_))));
    for (int m = 0; m < pieces; ++m) {
      const double t0 = double(m) / pieces, t1 = double(m + 1) / pieces;
      const double xa = s.x0 + (s.x1 - s.x0) * t0, ya = s.y0 + (s.y1 - s.y0) * t0;
      const double xb = s.x0 + (s.x1 - s.x0) * t1, yb = s.y0 + (s.y1 - s.y0) * t1;
      add_box(std::min(xa, xb) - s.half_width, std::min(ya, yb) - s.half_width, std::max(xa, xb) + s.half_width,
              std::max(ya, yb) + s.half_width, ~int32_t(k));
    }
  }
  std::sort(entries.begin(), entries.end());
  entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
  cell_start_.assign(size_t(cells_) * cells_ + 1, 0);
  for (const auto& e : entries) ++cell_start_[e.first + 1];
  for (size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  cell_items_.resize(entries.size());
  for (size_t k = 0; k < entries.size(); ++k) cell_items_[k] = entries[k].second;  // sorted by cell already
  // The clear share: items placed at random over the aperture and covering a total area a leave
  // exp(-a / A) of its area A clear in expectation (overlaps included).
  double covered = 0;
  for (const Particle& p : particles_) covered += M_PI * p.r * p.r;
  for (const Scratch& s : scratches_) covered += 2 * s.half_width * std::hypot(s.x1 - s.x0, s.y1 - s.y0);
  mean_ = semi_ > 0 ? std::exp(-covered / (M_PI * semi_ * semi_)) : 1;
}

double SurfaceDirt::Transmittance(double x, double y) const {
  const double fx = (x + extent_) / cell_size_, fy = (y + extent_) / cell_size_;
  if (!(fx >= 0 && fy >= 0 && fx < cells_ && fy < cells_)) return 1;
  const size_t cell = size_t(int(fy)) * size_t(cells_) + size_t(int(fx));
  for (uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
    const int32_t item = cell_items_[k];
    if (item >= 0) {
      const Particle& p = particles_[size_t(item)];
      if ((x - p.x) * (x - p.x) + (y - p.y) * (y - p.y) <= p.r * p.r) return 0;
    } else {
      const Scratch& s = scratches_[size_t(~item)];
      // The distance from the stroke: to the nearest point of the segment.
      const double ex = s.x1 - s.x0, ey = s.y1 - s.y0, len2 = ex * ex + ey * ey;
      const double t = len2 > 0 ? std::clamp(((x - s.x0) * ex + (y - s.y0) * ey) / len2, 0.0, 1.0) : 0.0;
      const double dx = x - (s.x0 + t * ex), dy = y - (s.y0 + t * ey);
      if (dx * dx + dy * dy <= s.half_width * s.half_width) return 0;
    }
  }
  return 1;
}

}  // namespace objektiv
