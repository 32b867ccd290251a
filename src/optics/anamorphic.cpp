#include "optics/anamorphic.h"

#include <cmath>

#include "optics/focusing.h"

namespace objektiv {

LensPrescription XSection(const LensPrescription& lens) {
  LensPrescription out = TurnedAboutAxis(lens, M_PI / 2);
  if (lens.HasToroids()) out.name += " (x-z section)";
  return out;
}

LensSystem XSectionSystem(const LensSystem& lens) {
  LensSystem x(XSection(lens.prescription()));
  x.SetStopSemiDiameter(lens.StopSemiDiameter());
  x.SetStopShape(lens.stop_shape());  // in the stop's frame, which turned with it
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

std::optional<double> AnamorphicFocusGap(const LensPrescription& lens, double distance_from_film, double back_focus,
                                         double lambda_nm) {
  const int k = lens.focus_gap;
  if (k < 0 || !(distance_from_film < 1e12)) return std::nullopt;
  const double design = lens.surfaces[size_t(k)].thickness;
  // Where the x-z section focuses the object with gap g, less where the film is.
  auto miss = [&](double g) -> std::optional<double> {
    if (!(g > 0 && g < 4 * design)) return std::nullopt;
    LensPrescription t = lens;
    t.surfaces[size_t(k)].thickness = g;
    const double object = distance_from_film - back_focus - t.TotalTrack();
    if (!(object > 0)) return std::nullopt;
    const double b = ImageObject(XSection(t), object, lambda_nm).back_focus;
    return std::isfinite(b) ? std::optional<double>(b - back_focus) : std::nullopt;
  };
  double g0 = design, g1 = design * (1 + 1e-3);
  std::optional<double> f0 = miss(g0), f1 = miss(g1);
  for (int it = 0; it < 60 && f0 && f1; ++it) {
    if (std::abs(*f1) < 1e-10 * (1 + back_focus)) return g1;
    if (*f1 == *f0) break;
    const double g2 = g1 - *f1 * (g1 - g0) / (*f1 - *f0);
    g0 = g1, f0 = f1, g1 = g2, f1 = miss(g1);
  }
  return f1 && std::abs(*f1) < 1e-6 * (1 + back_focus) ? std::optional<double>(g1) : std::nullopt;
}

}  // namespace objektiv
