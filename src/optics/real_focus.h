// Focusing a lens as a camera does: moving it as a whole (unit focusing) until an axial
// object point at a given distance from the film is sharpest for real rays through the
// current stop, with paraxial optics as the start and the fallback.
#pragma once
#include <string>

#include "optics/lens_tracer.h"

namespace objektiv {

struct LensFocus {
  double back_focus = 0;       // last vertex to film, mm
  double plane_of_focus_to_film = 0;  // mm (infinite for infinity)
  bool clamped = false;        // the object was closer than the lens can focus: closest focus
  bool real_rays = false;      // refined with real rays (false: the paraxial solution)
  int rays_used = 0;           // real rays in the final best-focus fit
};

// `distance_from_film` in mm; infinity (or anything beyond 1e12) focuses at infinity.
// Never fails: too close gives the closest focus, too few real rays the paraxial focus.
LensFocus FocusLens(const LensSystem& lens, double distance_from_film, double lambda_nm = 587.5618);

// The paraxial part of the above: the back focus that images the object sharp by first-order
// optics (the closest focus if it is too close).
LensFocus ParaxialFocus(const LensPrescription& lens, double distance_from_film, double lambda_nm = 587.5618);

// The film-to-object distance of the closest focus by unit focusing (paraxial, mm).
double ClosestFocusDistance(const LensPrescription& lens, double lambda_nm = 587.5618);

// One line for the log: where the lens went and how it was found.
std::string DescribeFocus(const LensFocus& focus, double infinity_back_focus);

}  // namespace objektiv
