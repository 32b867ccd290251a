// An anamorphic lens: toroidal (cylindrical) surfaces give it a different power in each of its
// two principal sections. The y-z section (vertical on the film) is the one the rest of the
// library's paraxial data describe (LensSurface::ParaxialCurvature is a toroid's y-z
// curvature); the x-z section (horizontal) traces the toroids' x-z curvatures instead.
//
// The squeeze factor is EFL_y / EFL_x: at the same film width, the horizontal field takes that
// many times the angle a spherical lens of EFL_y would give, so a scene is squeezed that many
// times horizontally on the film (2 for a classic 2x anamorphic) and the picture is stretched
// back by it (desqueezed). 1 for a rotationally symmetric lens.
#pragma once
#include <optional>

#include "optics/dispersion.h"
#include "optics/lens_prescription.h"
#include "optics/lens_system.h"
#include "optics/paraxial.h"

namespace objektiv {

// The lens turned a quarter about its axis (TurnedAboutAxis): its x-z section becomes the y-z
// section that paraxial optics and the real-ray analyses trace (what lay along +x lies along +y).
LensPrescription XSection(const LensPrescription& lens);

// The lens as set up, turned a quarter about its axis (XSection): the same lens in every ray,
// its horizontal analyses those of this system's y-z plane. Same stop and film.
LensSystem XSectionSystem(const LensSystem& lens);

struct Anamorphosis {
  ParaxialData x;          // first-order data of the x-z section
  double squeeze = 1;      // EFL_y / EFL_x
  double focus_split = 0;  // BFL_x - BFL_y (mm): the sections' paraxial foci apart (astigmatism on the axis)
};
// The x-z section's data at lambda, with the stop's semi-diameter as ComputeParaxial takes it.
Anamorphosis ComputeAnamorphosis(const LensPrescription& lens, const ParaxialData& y, double lambda_nm = kLambdad,
                                 double stop_semi_diameter = -1);

// A front anamorphic's own focusing (LensPrescription::focus_gap): the gap that makes its x-z
// section image an object `distance_from_film` mm in front of the film sharp on the film
// `back_focus` mm behind the last vertex, paraxially (the film and the object stay put, the
// elements in front of the gap move); the secant method from the gap as designed. Nothing
// where the lens has no focus gap, the object is at infinity (the design's own gap), or no
// gap between 0 and 4 times the design's does it.
std::optional<double> AnamorphicFocusGap(const LensPrescription& lens, double distance_from_film, double back_focus,
                                         double lambda_nm = kLambdad);

}  // namespace objektiv
