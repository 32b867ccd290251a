// The radiometric f-number of a real lens: N = 1 / (2 sin u'), with u' the half-angle of the
// on-axis image cone for an object at infinity. The image irradiance on the axis is
// proportional to sin^2 u', so closing the stop by one stop of this N halves the exposure
// exactly; for an aplanatic lens it equals the paraxial EFL / EPD.
#pragma once
#include <optional>

#include "optics/dispersion.h"
#include "optics/lens_tracer.h"

namespace objektiv {

// With the tracer's stop as it is (film at the paraxial infinity focus). Where a central
// obstruction hides the middle of the cone (a mirror lens), the cone's outer edge: the
// f-number the lens is marked with (its exposure is less, by the hidden share).
double RealFNumber(const LensSystem& lens, double lambda_nm = kLambdad);

// Where a central obstruction hides the middle of the on-axis cone: the f-number of the hidden
// cone's edge. Stopping down to it leaves no light on the axis (a mirror lens's aperture is
// fixed). Nothing where the axis is clear, or where no light gets through at all.
std::optional<double> ObstructionFNumber(const LensSystem& lens, double lambda_nm = kLambdad);

// The central obstruction's shadow in the pupil, as a fraction of the stop's radius as set:
// the ratio of the hidden cone's sine to the whole cone's, RealFNumber / ObstructionFNumber (an
// aplanatic lens maps pupil radii to sines of the image cone); 0 where the axis is clear. The
// diffraction patterns' pupil is the stop's opening less this disc.
double ObstructionRatio(const LensSystem& lens, double lambda_nm = kLambdad);

// The stop semi-diameter that gives f-number `fnumber`; nothing if the cone cannot reach the
// stop (a rim behind it cuts it first) or needs a stop larger than the lens's.
std::optional<double> StopSemiDiameterForFNumber(const LensSystem& lens, double fnumber,
                                                 double lambda_nm = kLambdad);

}  // namespace objektiv
