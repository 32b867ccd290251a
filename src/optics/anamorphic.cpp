#include "optics/anamorphic.h"

namespace objektiv {

LensPrescription XSection(const LensPrescription& lens) {
  LensPrescription out = lens;
  if (!lens.RotationallySymmetric()) out.name += " (x-z section)";
  for (LensSurface& s : out.surfaces) {
    if (!s.toroidal) continue;
    s.toroidal = false;
    s.SetCurvature(s.curvature_x);
    s.curvature_x = 0;
    s.conic = 0;
    s.a2 = 0;
    s.aspheric = {};
  }
  return out;
}

LensSystem XSectionSystem(const LensSystem& lens) {
  LensSystem x(XSection(lens.prescription()));
  x.SetStopSemiDiameter(lens.StopSemiDiameter());
  x.SetStopShape(lens.stop_shape());
  x.SetBackFocus(lens.BackFocus());
  return x;
}

Anamorphosis ComputeAnamorphosis(const LensPrescription& lens, const ParaxialData& y, double lambda_nm,
                                 double stop_semi_diameter) {
  Anamorphosis a;
  a.x = ComputeParaxial(XSection(lens), lambda_nm, stop_semi_diameter);
  a.squeeze = a.x.efl != 0 ? y.efl / a.x.efl : 0;
  a.focus_split = a.x.bfl - y.bfl;
  return a;
}

}  // namespace objektiv
