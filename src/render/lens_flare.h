// What the lens does with the scene's bright points besides forming the image the camera rays
// trace: their ghosts (every two-reflection path through the lens as set up, each found by
// its ray bundle: optics/ghosts.h) and, since camera rays never hit a point light, their own
// images (the direct bundle: the lens's aberrations, transmittance and vignetting included).
// Spectral: each bundle traced at `wavelengths` wavelengths evenly spread over 380..780 nm,
// each weighted by the light's emission and the CIE matching functions; deterministic (no
// noise: what is left is the grid's faceting and the wavelength steps).
//
// Culling: each ghost is first traced coarsely (grid 8) at 450, 550 and 650 nm for the flux
// that lands on the film (the whole film, whatever the crop), times its light's brightness
// there; the dimmest ghosts of all the lights (by their largest share at any of the three), as
// many as leave out together at most `cull` of the ghosts' light on the film at each of the
// three, are left out. (Culling by a ghost's mean irradiance against the brightest ghost's, as before, dropped
// the wide faint ghosts that make the veil: 35-43% of the ghost light at 1e-3 in a night
// street, since the brightest ghost is small and focused; the flux over the whole film plane,
// or at 580 nm only, left out more than the share on the film, or of a coated lens's blue.)
//
// The aperture mask's grey levels weight every bundle where it crosses the stop; with the
// camera's transmission off, the lights' own images leave out the lens's losses as the camera
// rays do.
#pragma once
#include <atomic>
#include <vector>

#include "render/film.h"
#include "render/flare_sources.h"

namespace objektiv {

struct FlareSettings {
  bool ghosts = false;        // the two-reflection ghosts
  bool light_images = false;  // the lights' own images
  int grid = 32;              // rays per side of each bundle (edges subdivided further)
  int edge_levels = 3;        // BundleOptions::edge_levels
  int region_grid = 32;       // the region search's grid (GhostRegion)
  bool pixel_centres = false;  // SplatColour's
  // Ghosts whose light spans at least this many pixels of the crop window both ways, and
  // whose irradiance rises nowhere far above its mean (no focused core: IrradianceContrast of
  // optics/film_splat.h at most 4), are splatted at half the resolution, then added upsampled:
  // a quarter of the pixel writes, their edges a ramp of about two pixels. 0: none.
  int half_resolution_from = 0;
  // Each bundle traced once, at 550 nm, with its losses at each of the `wavelengths` bands
  // (at most 32) on a lattice of its rays (BundleOptions::spectrum): a preview's colours (the
  // coatings' and the glasses', and how they change over each ghost), without the ghosts'
  // chromatic spread.
  bool one_geometry = false;
  int wavelengths = 16;
  double cull = 1e-3;
  // Turned true: no further chunk of bundles is traced (the interactive viewer's change);
  // FlareImages::stopped says so, the images then partial.
  const std::atomic<bool>* stop = nullptr;
  // Preview quality, for the live viewer while the camera moves: what a frame of 33 ms
  // affords (bench/bench_flare.cpp, BM_GhostPreview).
  static FlareSettings Preview();
};

struct FlareImages {
  int width = 0, height = 0;  // the crop window's
  // CIE XYZ per pixel (interleaved), in the film's units (camera/lens_camera.h).
  std::vector<float> ghosts, lights;
  // Ghosts per source, summed over sources: traced, culled as too dim, and those whose light
  // does not reach the film at all.
  int sources = 0, ghosts_traced = 0, ghosts_culled = 0, ghosts_dark = 0;
  bool stopped = false;  // by FlareSettings::stop, before every bundle was traced
  double seconds = 0;
};

FlareImages RenderFlare(const Scene& scene, const RealisticCamera& camera, const CropWindow& crop,
                        const FlareSettings& settings);

}  // namespace objektiv
