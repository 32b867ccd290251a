// A path of surface visits (optics/lens_tracer.h, TraceSequence) made ready for many rays at
// one wavelength: the indices on both sides of every surface, each glass's absorption
// coefficient and every interface's bare or coated reflectance law are looked up once, so
// that a ray costs only its intersections, refractions and reflectances. The ghosts' ray
// bundles (optics/ghosts.h) trace thousands of rays along one path at one wavelength; each
// visit of TraceSequence evaluated two dispersion formulas and an absorption table again.
//
// Same rays, same results: the same intersection, normal, reflection, refraction and
// reflectance functions in the same order, but for the bands' absorption, whose exponents
// are summed along the path and taken once (tests/test_compiled_sequence.cpp compares every
// ghost path of several lenses with TraceSequence). Paths through what it does not trace
// (a lens hood, tilted or decentred surfaces, toroids, Fresnel zones, form errors,
// gradient-index media, crystals, mirrors) are not compiled: Compile says so and the caller
// goes on with TraceSequence. Dust and scratches are not traced (the bundles take each
// surface's mean clear share instead).
#pragma once
#include <array>
#include <optional>
#include <span>
#include <vector>

#include "optics/coating_tables.h"
#include "optics/lens_tracer.h"

namespace objektiv {

class CompiledSequence {
 public:
  // Nothing where the path visits what this does not trace (above). `bands`: up to
  // kMaxBands further wavelengths at which each ray's transmittance is also found along the
  // same path, the one traced at lambda_nm (a preview's colours: the losses at each
  // wavelength, with the geometry of one); the transmittance at lambda_nm is then not found.
  static constexpr int kMaxBands = 32;
  // `tables`, if given (at the bands' wavelengths), give the coated surfaces' reflectance at
  // the bands (optics/coating_tables.h: within 1e-4 of the stacks).
  // Without `losses` only where the rays go is traced (their transmittances are left 1).
  static std::optional<CompiledSequence> Compile(const LensSystem& lens, std::span<const SurfaceVisit> visits,
                                                 double lambda_nm, std::span<const double> bands = {},
                                                 const CoatingTables* tables = nullptr, bool losses = true);

  struct Result {
    bool alive = false;
    bool followed = false;  // blocked, and followed past the openings to the last visit
    LensRay ray;  // after the last visit
    double surface_transmittance = 1, internal_transmittance = 1;  // at lambda_nm; 1 with bands
  };
  // The ray along the path, as TraceSequence traces it (its failures all give alive false).
  // `stop_points`, if given, receives where the ray crossed the stop each time (lens space).
  // With `follow_blocked`, a ray the openings (the stop, the rims, obscurations) block goes on
  // as if they did not: alive stays false, and `followed` and `ray` say where it would go (a
  // bundle's edge cells are placed on the film by their blocked corners).
  // `band_transmittance`, if given (band_count() values), receives the whole transmittance
  // (surfaces and glass) at each of the bands; the bands' losses are traced only then (a
  // result of a few words: most rays are traced for where they go).
  Result Trace(const LensRay& ray, std::vector<Vec3d>* stop_points = nullptr, bool follow_blocked = false,
               std::span<double> band_transmittance = {}) const;
  int band_count() const { return band_count_; }

 private:
  struct Step {
    const LensSurface* surface;
    int index;
    double vertex_z;
    bool reflect, toward_film, interface, is_stop;
    double eta;              // incoming index over outgoing
    double n_object, n_film;  // the indices on the surface's two sides
    // The absorption coefficient (1/mm) of the medium crossed to reach this step (0: none, or
    // the first step).
    double alpha;
    bool tabulated;  // its reflectance at the bands from tables_
    double semi_diameter2, obscuration2;  // squared
    // A plain conic (no aspheric terms): its curvature (0: a plane) and 1 + its conic
    // constant, for IntersectConic and ConicNormal.
    bool conic;
    double c, k1;
    bool bare;
  };
  // A step's data at one band, kept apart from the steps (band_count_ per step, step by step):
  // the indices on its two sides, the absorption coefficient as Step::alpha, and a bare
  // interface's Fresnel relative index (outgoing over incoming).
  struct BandStep {
    double n_object, n_film, alpha, fresnel_eta;
  };
  const LensSystem* lens_ = nullptr;
  double lambda_ = 0;
  int band_count_ = 0;
  std::array<double, kMaxBands> bands_{};
  const CoatingTables* tables_ = nullptr;
  bool losses_ = true;
  std::vector<Step> steps_;
  std::vector<BandStep> band_steps_;
};

}  // namespace objektiv
