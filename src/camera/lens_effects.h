// What a real lens adds to the image the camera rays trace, asked for with the realistic
// camera (the passes: render/lens_flare.h, render/diffraction_glare.h, render/lens_layers.h):
// - ghosts: every two-reflection path through the lens, for each bright point of the scene
//   (point, spot and directional lights in front of the lens), by ray bundles; and by light
//   tracing, the ghosts of area and environment lights and every light's veiling glare (four
//   and more reflections);
// - diffraction: the stop's Fraunhofer pattern spread over the light that reaches the film
//   straight from emitters (the default once on), or over the whole image.
// With either on, the bright points themselves are drawn as the lens images them (a point
// light is otherwise invisible to camera rays).
#pragma once

namespace objektiv {

enum class DiffractionScope { kOff, kEmitters, kImage };

struct LensEffects {
  bool ghosts = false;
  int ghost_grid = 32;         // rays per side of each ghost's bundle
  double ghost_cull = 1e-3;    // the dimmest ghosts, together at most this share of the ghosts' light, are left out
  int glare_samples = 4;       // light paths per film pixel for the light-traced part (0: none)
  int wavelengths = 16;        // for the ghosts, the lights' images and the diffraction kernel
  DiffractionScope diffraction = DiffractionScope::kOff;
  bool Any() const { return ghosts || diffraction != DiffractionScope::kOff; }
};

}  // namespace objektiv
