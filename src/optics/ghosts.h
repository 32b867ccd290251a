// Ghosts: the images a lens forms of a bright point with light reflected twice inside it.
// Light travelling toward the film is partly reflected at surface `first` (R = 4% for bare
// glass, far less coated), travels back, is partly reflected again at an earlier surface
// `second`, and goes on to the film, refracted everywhere else: a second, usually defocused
// image of the point shaped by the stop it crossed (three times, or once), tinted by the two
// coatings' reflectance. A lens of n reflecting surfaces has n (n - 1) / 2 of them; paths with
// four or more reflections carry R^2 less again (veiling glare) and are not traced here.
//
// Each ghost is found by a bundle of rays (Hullin et al. 2011, "Physically-based real-time lens
// flare rendering"): a square grid of rays from the source over the front element, each traced
// exactly along the ghost's path; each grid cell whose four corners all reach the film is a
// quadrilateral there carrying the cell's flux, and its irradiance is that flux over the
// quadrilateral's area (the bundle's change of cross-section: where a ghost is focused, it is
// bright). The grid first spans the front element coarsely, then, finer, only the part whose
// rays get through; cells that lie across the edge of what gets through are split in four,
// BundleOptions::edge_levels times over, so that the ghost's outline follows the stop's.
#pragma once
#include <array>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "base/vec.h"
#include "optics/coating_tables.h"
#include "optics/film_splat.h"
#include "optics/lens_tracer.h"

namespace objektiv {

struct Ghost {
  int first = 0, second = 0;  // the surfaces that reflect, first > second
};

// The surfaces where the index changes (the interfaces that reflect), in order.
std::vector<int> ReflectingSurfaces(const LensSystem& lens);
// Every two-reflection path: each pair of surfaces where the index changes.
std::vector<Ghost> TwoReflectionGhosts(const LensSystem& lens);
// A ghost's path: surfaces 0..first toward the film (reflected at first), first-1..second
// toward the object (reflected at second), second+1..n-1 toward the film.
std::vector<SurfaceVisit> GhostPath(const LensSystem& lens, const Ghost& ghost);

// A point light in lens space (mm): at a point in front of the lens, or at infinity in a
// direction (unit, d.z > 0, the way its light travels).
struct PointSource {
  Vec3d position{0, 0, -1e6};
  bool at_infinity = false;
  Vec3d direction{0, 0, 1};
  static PointSource At(Vec3d p) { return {p, false, {0, 0, 1}}; }
  static PointSource Distant(Vec3d d) { return {{0, 0, 0}, true, d}; }
};

// The part of the start square (a plane just in front of the lens) whose rays get through a
// path, found at one wavelength (a coarse grid of `search_grid` rays a side, then a finer one
// if the pupil is small; a grid below 32, a preview's, narrowed by a second of its size over
// what the first found) and widened to hold the other wavelengths' too: a bundle's grid spans
// it. Nothing where no light gets through.
struct BundleRegion {
  Vec2d lo, hi;
};
std::optional<BundleRegion> GhostRegion(const LensSystem& lens, const Ghost& ghost, const PointSource& source,
                                        double lambda_nm, int search_grid = 32);

// The ghost's bundle at one wavelength: `grid` x `grid` cells over the part of the front
// element its light gets through (each cell split in two triangles): `region` (from
// GhostRegion, at any wavelength: the search is the costlier part for a small grid), or found
// here at this wavelength.
std::vector<FilmTriangle> GhostBundle(const LensSystem& lens, const Ghost& ghost, const PointSource& source,
                                      double lambda_nm, int grid = 64, const BundleRegion* region = nullptr);

// A bundle's colour at many wavelengths along one geometry (a preview's): the bundle traced at
// its own wavelength alone, the losses along its path (the coatings', the glasses') at each of
// `wavelengths` found at the nodes of a lattice over its start square every `lattice_cells`
// cells of its grid (optics/colour_lattice.h), each weighted by its colour per unit
// transmittance (`weights`: the light's emission over the wavelength's band, through the
// matching functions) and summed: each triangle's tint is its colour per unit flux. Without
// the ghosts' chromatic spread (one geometry), with their colours and how they change over
// each ghost.
struct BundleSpectrum {
  std::vector<double> wavelengths;  // at most CompiledSequence::kMaxBands
  std::vector<Vec3d> weights;       // one per wavelength
  int lattice_cells = 4;
};

// Everything a bundle can be asked for: the grid, the levels of splitting cells across the
// edge of what gets through (3: an eighth of a cell; a preview's 1), the region (see GhostBundle), the stop's
// transmittance at (u, v) in stop radii where its opening lets light through (an aperture
// mask's grey levels; none: 1), applied at each crossing of the stop, and whether to leave
// out the surfaces' and glasses' losses (the camera's `transmission false`).
struct BundleOptions {
  int grid = 64;
  int edge_levels = 3;
  // A preview's colours along one geometry (above). The triangles' flux is then in units of
  // the transmittance weighted by the weights' sum of X, Y and Z, their tint their colour per
  // unit flux.
  const BundleSpectrum* spectrum = nullptr;
  // The coated surfaces' reflectance at the spectrum's wavelengths from tables
  // (optics/coating_tables.h, at those wavelengths), instead of their thin-film stacks.
  const CoatingTables* coating_tables = nullptr;
  const BundleRegion* region = nullptr;
  std::function<double(double u, double v)> stop_transmittance;
  bool lossless = false;
};
std::vector<FilmTriangle> GhostBundle(const LensSystem& lens, const Ghost& ghost, const PointSource& source,
                                      double lambda_nm, const BundleOptions& options);

// The same for the light that goes straight through (no reflection): the point's own image,
// for comparison (a ghost's share of the light is its flux over this one's).
std::vector<FilmTriangle> DirectBundle(const LensSystem& lens, const PointSource& source, double lambda_nm,
                                       const BundleOptions& options);
std::optional<BundleRegion> DirectRegion(const LensSystem& lens, const PointSource& source, double lambda_nm,
                                         int search_grid = 32);
std::vector<FilmTriangle> DirectBundle(const LensSystem& lens, const PointSource& source, double lambda_nm, int grid = 64,
                                       const BundleRegion* region = nullptr);

// The light the point sends onto the front element's clear aperture (per unit intensity, or
// irradiance, as the bundles' flux): what a ghost's share of the light is measured against.
double FrontElementFlux(const LensSystem& lens, const PointSource& source);

}  // namespace objektiv
