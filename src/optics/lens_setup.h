// Setting a lens up as a camera or `objektiv lens` asks for it, the one way every user builds
// its LensSystem: the stop by radiometric f-number or by diameter, with the opening's shape
// (round, an iris of blades, cut by a mask's support); the film by unit focusing on a plane at
// a distance from the film or from the entrance pupil, with real rays (best RMS focus; the
// cameras) or paraxially (the analyses, which take the lens at its paraxial focus); and the
// line the log prints about it.
#pragma once
#include <cmath>
#include <string>

#include "optics/dispersion.h"
#include "optics/lens_system.h"
#include "optics/real_focus.h"

namespace objektiv {

struct StopRequest {
  double fnumber = 0;      // radiometric (optics/real_fnumber.h); within 2% of the widest means wide open
  double diameter_mm = 0;  // the stop's diameter instead; both 0: wide open
  StopShape opening;       // round by default
};

struct FocusRequest {
  enum class From { kFilm, kEntrancePupil };
  double distance_mm = INFINITY;  // to the plane in focus, from `from`; infinity: focus at infinity
  From from = From::kFilm;
  bool real_rays = true;  // false: the paraxial focus
  double lambda_nm = kLambdad;
  bool quiet = false;     // no warnings (the lens commands report the figures themselves)
};

struct LensSetup {
  LensSystem lens;
  double fnumber = 0;  // radiometric f-number of the stop as set (before the opening's shape)
  LensFocus focus;
  std::string report;  // "lens NAME: EFL ..., f/...; focused at ..."
};

// Throws InputError (without a location: the caller knows where the request was written) when
// the stop cannot be set as asked. `tilt`: a tilt-shift lens's tilt, the whole lens turned
// about its entrance pupil (MovedAsAWhole) once its stop is set (the f-number is the lens's
// own), before it focuses.
LensSetup SetUpLens(LensPrescription prescription, const StopRequest& stop, const FocusRequest& focus,
                    const std::optional<SurfacePlacement>& tilt = {});

// The lens fully open, at its paraxial focus for an object at infinity at `lambda_nm`: how
// `objektiv lens info`, `plot` and `analyze` take a lens.
LensSystem AtParaxialInfinityFocus(LensPrescription prescription, double lambda_nm = kLambdad);

// The real f-number of the lens fully open (d line, object at infinity).
double WideOpenFNumber(const LensPrescription& prescription);

}  // namespace objektiv
