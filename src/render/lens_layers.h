// The layers of a render through a real lens with its effects (camera/lens_effects.h), in the
// film's XYZ (crop-window sized, interleaved):
// - primary: what the camera rays traced (the integrator's image), plus the bright points'
//   own images through the lens;
// - ghosts: the two-reflection ghosts of the bright points (ray bundles), and by light
//   tracing the other lights' ghosts and every light's veiling glare;
// - diffraction: what the stop's diffraction changes: the diffracted light minus the same
//   light undiffracted (negative where the pattern takes light away from a point's core);
// - their sum: the picture.
// Without effects, primary is the film's image and the others are empty.
#pragma once
#include <atomic>
#include <cstdint>
#include <vector>

#include "camera/camera.h"
#include "render/film.h"
#include "scene/scene.h"

namespace objektiv {

struct LensLayers {
  int width = 0, height = 0;
  std::vector<float> primary, ghosts, diffraction;  // ghosts, diffraction: empty when not asked for
  std::vector<float> Sum() const;
  // What the passes did, for the log and the header.
  int flare_sources = 0, ghosts_traced = 0, ghosts_culled = 0, ghosts_dark = 0, diffraction_radius = 0;
  double fnumber = 0;  // working, of the diffraction pattern
  int other_lights = 0;  // area and environment lights: ghosts by light tracing only, no own images
  // The light-traced part of the ghosts layer (render/glare_light_tracer.h).
  int64_t glare_paths = 0, glare_landed = 0, glare_paths_asked = 0;
  double glare_median_landings = 0;
  double ghost_seconds = 0, glare_seconds = 0, diffraction_seconds = 0;
  bool stopped = false;  // by ComposeLensLayers' stop: partial
};

// The memory the effects take beyond the film (the layers, the passes' images per thread, the
// diffraction's FFTs), for the render's memory budget; 0 without effects.
uint64_t LensEffectsBytes(const Camera& camera, const CropWindow& crop, int threads);

// Films that the effects need prepared before rendering (the emitted light kept apart).
void PrepareFilmForLensEffects(const Camera& camera, Film& film);

// `seed`: the sampler's, so that renders with different seeds have independent glare noise.
// `stop` (the interactive viewer's): once true, the passes end early and `stopped` says the
// layers are not whole.
LensLayers ComposeLensLayers(const Scene& scene, const Camera& camera, const Film& film, uint64_t seed = 0,
                             const std::atomic<bool>* stop = nullptr);

}  // namespace objektiv
