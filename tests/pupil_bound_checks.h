// Checks of a lens's pupil bounds shared by the tests of each surface kind: how many of the
// camera's rays get through, and whether the bound holds all the light (the passing area on the
// sampling plane estimated through the bound against a brute-force estimate over a square).
#pragma once
#include <cmath>
#include <functional>

#include "base/rng.h"
#include "optics/lens_tracer.h"
#include "optics/pupil_bounds.h"

namespace objektiv::test {

struct PassRate {
  int launched = 0, passed = 0;  // samples with light (pdf > 0), and those that got through
  double Rate() const { return launched ? double(passed) / launched : 0; }
};

// `count` camera rays from film points `film(rng)` aimed where the bound samples; `waves`: the
// waves they take in birefringent crystals (LensRay::wave_choices).
inline PassRate CameraPassRate(const LensSystem& lens, const PupilBounds& bounds, int count, PCG32& rng,
                               const std::function<Vec2d(PCG32&)>& film, double lambda_nm, uint32_t waves = 0) {
  PassRate p;
  for (int i = 0; i < count; ++i) {
    const Vec2d f = film(rng);
    const PupilBounds::Sample s = bounds.SampleRear(f, {rng.UniformFloat(), rng.UniformFloat()});
    if (s.pdf == 0) continue;
    ++p.launched;
    const Vec3d o(f.x, f.y, lens.FilmZ());
    p.passed += bool(TraceFromFilm(lens, {o, Normalize(s.point - o), false, waves}, lambda_nm).ray);
  }
  return p;
}

struct AreaEstimates {
  double brute = 0, bound = 0, se = 0;  // mm^2 on the sampling plane, and their joint standard error
  bool has_bound = false;               // the film point has a bound (light)
  double passed_share = 0;              // of the rays sampled in the bound, those that got through
};

// The passing area for one film point: uniformly over the square +-half (which must hold all
// the light on the sampling plane), and through the bound; `count` rays each, taking `waves`
// in birefringent crystals.
inline AreaEstimates PassingArea(const LensSystem& lens, const PupilBounds& bounds, Vec2d film, double half, int count,
                                 PCG32& rng, double lambda_nm, uint32_t waves = 0) {
  const Vec3d o(film.x, film.y, lens.FilmZ());
  int brute = 0, via_bound = 0;
  for (int i = 0; i < count; ++i) {
    const Vec3d target(half * (2 * rng.UniformFloat() - 1), half * (2 * rng.UniformFloat() - 1), bounds.rear_z());
    brute += bool(TraceFromFilm(lens, {o, Normalize(target - o), false, waves}, lambda_nm).ray);
    const PupilBounds::Sample s = bounds.SampleRear(film, {rng.UniformFloat(), rng.UniformFloat()});
    if (s.pdf > 0) via_bound += bool(TraceFromFilm(lens, {o, Normalize(s.point - o), false, waves}, lambda_nm).ray);
  }
  const ConvexPolygon* poly = bounds.BoundAt(film);
  const double square = 4 * half * half, area = poly ? poly->area : 0;
  AreaEstimates a;
  a.brute = square * brute / count;
  a.bound = area * via_bound / count;
  a.se = std::sqrt(square * a.brute / count + area * a.bound / count);
  a.has_bound = poly != nullptr;
  a.passed_share = double(via_bound) / count;
  return a;
}

}  // namespace objektiv::test
