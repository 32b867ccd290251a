// Real-ray analysis of a lens focused at infinity (the film at the paraxial focus, unless
// the tracer's back focus was set otherwise): chief rays, distortion, spots, aberrations.
#pragma once
#include <optional>
#include <vector>

#include "optics/lens_tracer.h"

namespace objektiv {

// The chief ray for a field angle (degrees, in the y-z plane) from an object at infinity:
// the ray that crosses the stop at its centre, found by iteration on its entrance height.
std::optional<LensRay> ChiefRay(const LensSystem& lens, double field_deg, double lambda_nm);

// Height of the chief ray on the film (mm). Rays travel toward +y for positive fields.
std::optional<double> RealImageHeight(const LensSystem& lens, double field_deg, double lambda_nm);

// Distortion at a field angle: (real - ideal) / ideal image height, with the ideal height
// EFL tan(theta) (rectilinear). Negative: barrel, positive: pincushion.
// (`efl`: the object side's focal length, object index x EFL where the object space is not air.)
std::optional<double> Distortion(const LensSystem& lens, double efl, double field_deg, double lambda_nm);

struct Spot {
  std::vector<Vec2d> points;  // on the film, mm
  Vec2d centroid;
  double rms_radius = 0, geometric_radius = 0;  // about the centroid, mm
  double transmitted = 0;  // fraction of the rays launched over the entrance pupil that arrive
};

// Rays from a field angle over the entrance pupil (a square grid of `n` x `n` rays cut to
// a circle 1.2 entrance-pupil radii wide, so that vignetting shows), traced to the film.
Spot SpotDiagram(const LensSystem& lens, double field_deg, double lambda_nm, int n = 31);

// Relative illumination at a field angle (1 on axis): the image irradiance from a uniform
// distant scene, E ~ A(theta) sin(theta) / (h dh/dtheta), with A the cross-section of the
// beam from that direction that reaches the film (vignetting) and h the real image height
// (distortion). For a thin lens with the stop at the lens this is the cos^4 law.
std::optional<double> RelativeIllumination(const LensSystem& lens, double field_deg, double lambda_nm);

// How much of the light entering along the axis reaches the film: the surfaces' share (their
// reflection losses, bare or coated, and mirrors' reflectances) and the glasses' (absorption),
// at one wavelength. Where a central obstruction blocks the axis (a mirror lens), the ray
// parallel to it through the middle of the first clear zone.
struct AxialTransmittance {
  double surfaces = 0, glass = 0;
  double Total() const { return surfaces * glass; }
};
AxialTransmittance AxialTransmittanceOf(const LensSystem& lens, double lambda_nm);

struct FieldCurvature {
  double tangential = 0, sagittal = 0;  // focus positions relative to the film, along the axis (mm)
};
// Tangential and sagittal foci of the thin pencils around the chief ray at a field angle.
std::optional<FieldCurvature> FieldCurvatureAt(const LensSystem& lens, double field_deg, double lambda_nm);

// Full field of view (degrees) of a sensor `width` x `height` mm: the field angles whose real
// chief rays reach the edges and the corner (distortion included); where the sensor extends
// beyond the image circle (fisheyes), the image circle's field. An anamorphic lens: the
// horizontal in its x-z section (optics/anamorphic.h), no diagonal (NaN). A decentred or
// tilted lens: the field of the lens centred on its axis.
struct FieldOfView {
  double horizontal = 0, vertical = 0, diagonal = 0;
};
FieldOfView SensorFieldOfView(const LensSystem& lens, double width, double height, double lambda_nm);

// The real back focus: the film distance behind the last vertex that minimises the RMS
// radius of the on-axis spot (in mm).
double RealBackFocus(const LensSystem& lens, double lambda_nm);

// Longitudinal spherical aberration: where a ray parallel to the axis at `height` mm crosses
// the axis, minus the paraxial focus (mm; negative = in front of it).
std::optional<double> LongitudinalAberration(const LensSystem& lens, double height, double lambda_nm);

}  // namespace objektiv
