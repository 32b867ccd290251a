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
#include "optics/dispersion.h"
#include "optics/lens_prescription.h"
#include "optics/lens_system.h"
#include "optics/paraxial.h"

namespace objektiv {

// The lens as its x-z section sees it paraxially: each toroid replaced by a sphere of its x-z
// curvature (no conic or aspheric terms: a toroid's x-z section is a circle).
LensPrescription XSection(const LensPrescription& lens);

// The lens as set up, in its x-z section: a ray in the x-z plane meets a toroid where its
// section is the circle of curvature curvature_x and is turned within that plane, as by a
// sphere of that curvature; so the x-z plane's real rays (and the horizontal analyses) are
// this system's y-z ones. Same stop and film.
LensSystem XSectionSystem(const LensSystem& lens);

struct Anamorphosis {
  ParaxialData x;          // first-order data of the x-z section
  double squeeze = 1;      // EFL_y / EFL_x
  double focus_split = 0;  // BFL_x - BFL_y (mm): the sections' paraxial foci apart (astigmatism on the axis)
};
// The x-z section's data at lambda, with the stop's semi-diameter as ComputeParaxial takes it.
Anamorphosis ComputeAnamorphosis(const LensPrescription& lens, const ParaxialData& y, double lambda_nm = kLambdad,
                                 double stop_semi_diameter = -1);

}  // namespace objektiv
