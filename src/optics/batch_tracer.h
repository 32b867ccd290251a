// The renderer's lens tracer: single precision, many rays at once in structure-of-arrays form
// (surfaces in the outer loop, rays in the inner loop, branch-free, so that the compiler
// vectorises it),
// each ray with its own wavelength (each glass's index is tabulated at 1 nm). It follows the
// double-precision tracer (optics/lens_tracer.h) to well below 1e-4 mm at the film. Coated
// surfaces' reflectances are tabulated over wavelength and angle from the lens's own
// (LensSystem::SurfaceReflectance).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "optics/lens_system.h"

namespace objektiv {

// One ray in single precision, lens space (mm), with its wavelength and the transmittance
// gathered so far.
struct FloatRay {
  float ox, oy, oz, dx, dy, dz, lambda;
  float transmittance = 1;
  uint32_t wave_choices = 0;  // the waves it takes in birefringent crystals (LensRay::wave_choices)
  bool extraordinary = false;
};

struct RayBatch {
  std::vector<float> ox, oy, oz, dx, dy, dz, lambda;
  std::vector<float> transmittance;  // Fresnel and internal transmittance, multiplied along
  std::vector<uint8_t> alive;
  // Birefringent crystals (LensRay): the waves each ray takes in those ahead, and whether it is
  // the extraordinary wave of the one it is in.
  std::vector<uint32_t> wave_choices;
  std::vector<uint8_t> extraordinary;
  // Where each ray crossed the stop's plane (lens x, y in mm), set by the tracer when
  // `record_stop` is on (an aperture mask needs it).
  bool record_stop = false;
  std::vector<float> stop_x, stop_y;
  // Scratch for the tracer: per medium and ray, the index and absorption coefficient at the
  // ray's wavelength; per ray, the optical depth crossed; for coated surfaces, per ray, the
  // row of the coatings' tables at its wavelength, the weight of the next row, and cos(incidence).
  std::vector<float> media_index, media_alpha, depth;
  std::vector<int32_t> coat_row;
  std::vector<float> coat_weight, coat_cos;
  void Resize(size_t n);
  size_t Size() const { return ox.size(); }
  void Push(const FloatRay& r) {  // appended alive
    ox.push_back(r.ox), oy.push_back(r.oy), oz.push_back(r.oz);
    dx.push_back(r.dx), dy.push_back(r.dy), dz.push_back(r.dz);
    lambda.push_back(r.lambda);
    transmittance.push_back(r.transmittance);
    alive.push_back(1);
    wave_choices.push_back(r.wave_choices);
    extraordinary.push_back(r.extraordinary);
  }
  FloatRay Get(size_t i) const {
    return {ox[i], oy[i], oz[i], dx[i], dy[i], dz[i], lambda[i], transmittance[i], wave_choices[i], bool(extraordinary[i])};
  }
};

class BatchLensTracer {
 public:
  // The lens compiled for tracing in single precision: its surfaces, the stop's size and
  // opening, the film's position, and each medium's tables (the lens itself is not kept).
  explicit BatchLensTracer(const LensSystem& lens);
  // In place, film toward object; rays that are blocked get alive = 0. With `transmission`
  // the Fresnel losses and glass absorption are multiplied into `transmittance`.
  void TraceFromFilm(RayBatch& rays, bool transmission = true) const;
  void TraceFromObject(RayBatch& rays, bool transmission = true) const;
  // Without the rims (and a lens hood): only the stop clips (to show a lens without optical
  // vignetting).
  void IgnoreRims();
  float FilmZ() const { return film_z_; }

 private:
  struct Surface {
    float z, c, k1, semi2;        // vertex z, curvature, 1 + conic, semi-diameter squared
    float obscuration2;           // the central obstruction's radius squared (0: none)
    float cx;                     // a toroid's x-z curvature (LensSurface::curvature_x)
    // A cylinder (a toroid flat in one section, its other a conic without aspheric terms) is
    // met in closed form: the conic's equation with x's (mx 0) or y's (my 0) terms left out.
    float mx = 1, my = 1;
    bool plane, aspheric, toroid, cylinder, is_stop, mirror;
    // Decentred or tilted: rays are taken into the surface's frame (origin: its vertex at
    // `origin`; axes[0..2] its x, y, z in lens space) for the step, and back.
    bool placed = false;
    float origin[3] = {0, 0, 0}, axes[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    float reflectance;            // a mirror's
    float a2, a[7];
    // A Q-type asphere (LensSurface::forbes): its sum's Chebyshev coefficients (q_count of
    // them; 0: none), 1 / r_n^2, and whether its base is the best-fit sphere (else a conic).
    float q[ForbesAsphere::kMaxTerms] = {};
    int q_count = 0;
    float inv_rn2 = 0;
    bool qbfs = false;
    // A surface no kernel traces (a Fresnel surface, a form error): traced one ray at a time
    // through this copy (IntersectSurface).
    std::shared_ptr<const LensSurface> scalar;
    // Next to a gradient-index medium or a birefringent crystal (on either side): each ray
    // traced by the exact tracer (ExactStep).
    bool exact_step = false;
    std::shared_ptr<const SurfaceDirt> dirt;  // dust and scratches (null: clean)
    int medium_after;            // glass index (-1: air); its tables are at medium_after + 1
    int coating;                 // -1: bare (Fresnel's equations inline) or a mirror of constant reflectance; else coating_tables_[2 coating + toward object] (a metal mirror's reflectance: both the same)
  };
  void Trace(RayBatch& rays, bool from_film, bool transmission) const;
  void ExactStep(int i, bool from_film, bool transmission, bool absorb, RayBatch& rays) const;
  static void ToSurfaceFrame(const Surface& s, RayBatch& rays);
  static void FromSurfaceFrame(const Surface& s, RayBatch& rays);

  std::vector<Surface> surfaces_;
  // Per medium (air first), 360..830 nm at 1 nm: index, absorption coefficient per mm.
  std::vector<std::vector<float>> index_tables_, absorption_tables_;
  std::vector<uint8_t> constant_index_;  // per medium: the same index at every wavelength
  // Per coated surface and direction (toward the film, toward the object): its reflectance
  // over wavelength (rows) and cos(incidence) (columns).
  std::vector<std::vector<float>> coating_tables_;
  bool absorbing_ = false;               // any glass absorbs somewhere in the range
  int object_medium_ = -1;               // the medium before the first surface (-1: air)
  float film_z_;
  // The opening, where not round (the circle is tested inline), and the stop's radius.
  StopShape stop_shape_;
  float stop_semi_;
  // The lens as set up, where a gradient-index medium or a crystal needs the exact tracer (null: none).
  std::shared_ptr<const LensSystem> exact_;
  std::optional<LensHood> hood_;  // in front of the first vertex (z 0 in lens space)
  float first_vertex_z_ = 0;
  void ClipAtHood(RayBatch& rays) const;
};

}  // namespace objektiv
