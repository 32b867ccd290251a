// The bright points of a scene as the lens sees them: what its ghosts and its diffraction
// pattern are made of. The scene's delta lights (point, spot and directional: lamps and the
// sun) that lie in front of the lens, each in lens space (optics/ghosts.h: PointSource), with
// its spectrum toward the lens and the share of the front element that sees it unoccluded.
//
// Units: the ray bundles carry flux per unit intensity (sr, a point at a finite distance) or
// per unit irradiance (mm^2 across the beam, a distant one), landing on film areas in mm^2.
// The camera records E, the film irradiance per scene unit squared (camera/lens_camera.h:
// pixel = exposure_scale (4 / pi) E), so a point light of intensity I gives E = I flux / (area
// mm_to_units^2) and a directional light of irradiance E0 gives E = E0 flux / area:
// `irradiance_scale` is 1 / mm_to_units^2 or 1.
#pragma once
#include <vector>

#include "camera/realistic_camera.h"
#include "optics/ghosts.h"
#include "scene/scene.h"

namespace objektiv {

struct FlareSource {
  PointSource source;            // lens space
  const Spectrum* emission;      // intensity (W/sr) or irradiance (per scene unit^2)
  double factor = 1;             // the spot's falloff toward the lens
  double irradiance_scale = 1;   // see above
  double visibility = 1;         // share of the front element's sample points that see it
  float Emission(double lambda_nm) const { return float(factor) * (*emission)(float(lambda_nm)); }
};

// The delta lights in front of the lens that some of the front element sees (spots: whose
// cone includes the lens). Visibility: shadow rays from `visibility_samples` points spread over
// the front element's clear aperture.
std::vector<FlareSource> FindFlareSources(const Scene& scene, const RealisticCamera& camera, int visibility_samples = 64);

}  // namespace objektiv
