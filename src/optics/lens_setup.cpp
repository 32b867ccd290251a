#include "optics/lens_setup.h"

#include <cmath>

#include <fmt/format.h>

#include "base/error.h"
#include "base/log.h"
#include "optics/anamorphic.h"
#include "optics/focusing.h"
#include "optics/real_fnumber.h"

namespace objektiv {

double WideOpenFNumber(const LensPrescription& prescription) { return RealFNumber(LensSystem(prescription)); }

namespace {

void SetStop(LensSystem& lens, const StopRequest& stop) {
  const LensPrescription& rx = lens.prescription();
  const double full = lens.FullStopSemiDiameter();
  if (stop.diameter_mm > 0) {
    if (stop.diameter_mm / 2 > full * (1 + 1e-9))
      throw InputError(fmt::format("stop diameter {} mm is larger than {}'s stop ({:.4g} mm)", stop.diameter_mm,
                                   rx.name, 2 * full));
    lens.SetStopSemiDiameter(stop.diameter_mm / 2);
  } else if (stop.fnumber > 0) {
    std::optional<double> semi = StopSemiDiameterForFNumber(lens, stop.fnumber);
    if (!semi) {
      // A lens sold as f/2.8 may open to f/2.81 by the real rays: a request within 2% of the
      // widest aperture means wide open.
      const double wide_open = RealFNumber(lens);
      if (!(wide_open < INFINITY))
        throw InputError(fmt::format("no light gets through {} on the axis: its rims, mirrors or obstruction block every "
                                     "ray (check their radii, semi-diameters and aspheric terms)", rx.Described()));
      if (stop.fnumber < wide_open / 1.02)
        throw InputError(fmt::format("f/{} is faster than {} opens (f/{:.3g})", stop.fnumber, rx.name, wide_open));
      spdlog::info("lens {}: f/{} taken as wide open (f/{:.3g})", rx.name, stop.fnumber, wide_open);
      semi = full;
    }
    lens.SetStopSemiDiameter(*semi);
  }
}

// No light on the axis with the stop as set (`fnumber`: the lens's, infinite then): a central
// obstruction (a mirror lens's secondary) hides the whole cone once the stop is narrowed to
// its shadow, or rims and mirrors block every ray.
void CheckLightGetsThrough(const LensSystem& lens, const StopRequest& stop, double fnumber) {
  if (fnumber < INFINITY) return;
  const LensPrescription& rx = lens.prescription();
  const std::optional<double> limit = ObstructionFNumber(LensSystem(rx));
  const std::string asked = stop.diameter_mm > 0 ? fmt::format("a stop of {} mm", stop.diameter_mm)
                            : stop.fnumber > 0   ? fmt::format("f/{}", stop.fnumber)
                                                 : std::string("wide open");
  const std::string why = limit ? fmt::format(": its central obstruction hides the whole cone from f/{:.3g} on (a "
                                              "mirror lens's aperture is fixed; its filters or the exposure set the light)",
                                              *limit)
                                : ": its rims, mirrors or obstruction block every ray";
  throw InputError(fmt::format("{}: no light gets through {}{}", asked, rx.Described(), why));
}

// The plane in focus as a distance from the film. Given from the entrance pupil, it depends
// on where focusing puts the lens: a few rounds of first-order focusing settle it (the pupil
// moves by the focusing travel, a few mm on a distance of metres, and real rays move it by a
// fraction of that).
double DistanceFromFilm(const LensSystem& lens, const FocusRequest& focus) {
  if (focus.from == FocusRequest::From::kFilm || !(focus.distance_mm < INFINITY)) return focus.distance_mm;
  LensSystem t = lens;
  double distance = focus.distance_mm;
  for (int round = 0; round < 6; ++round) {
    t.SetBackFocus(ParaxialFocus(t.prescription(), distance).back_focus);
    distance = focus.distance_mm + (t.FilmZ() - t.EntrancePupilZ());
  }
  return distance;
}

// Sets the anamorphic focus gap of the lens for an object `distance` mm from the film (where
// its prescription has one; optics/anamorphic.h) and says how it moved ("" where it did not).
std::string FocusAnamorphicGap(LensSystem& lens, double distance, double lambda_nm) {
  const LensPrescription& rx = lens.prescription();
  if (rx.focus_gap < 0 || !(distance < 1e12)) return "";
  const double back = ParaxialFocus(rx, distance, lambda_nm).back_focus;
  const std::optional<double> gap = AnamorphicFocusGap(rx, distance, back, lambda_nm);
  const double design = rx.surfaces[size_t(rx.focus_gap)].thickness;
  if (!gap) {
    spdlog::warn("lens {}: its anamorphic focusing cannot bring the horizontal section into focus at {:.4g} m (the gap "
                 "after row {} stays {:.3f} mm)", rx.name, distance * 1e-3, rx.focus_gap + 1, design);
    return "";
  }
  LensPrescription t = rx;
  t.surfaces[size_t(rx.focus_gap)].thickness = *gap;
  LensSystem focused(std::move(t));
  focused.SetStopSemiDiameter(lens.StopSemiDiameter());
  focused.SetStopShape(lens.stop_shape());
  lens = std::move(focused);
  return fmt::format("; anamorphic focusing: the gap after row {} {:.3f} mm (designed {:.3f})", rx.focus_gap + 1, *gap,
                     design);
}

// For an anamorphic lens, how far apart its sections focus the object the lens is focused on
// (paraxially), and a warning where that blurs one of them beyond a full-frame circle of
// confusion (0.03 mm): a front adapter without focusing of its own is sharp near infinity only.
std::string AnamorphicFocusNote(const LensSystem& lens, const LensFocus& focus, double lambda_nm, bool quiet) {
  const LensPrescription& rx = lens.prescription();
  if (!rx.HasToroids()) return "";
  const double distance = focus.plane_of_focus_to_film;
  double split = 0;
  if (std::isinf(distance)) {
    split = ComputeAnamorphosis(rx, lens.paraxial(), lambda_nm).focus_split;
  } else {
    const double y = ParaxialFocus(rx, distance, lambda_nm).back_focus;
    const double object = distance - y - rx.TotalTrack();
    split = ImageObject(XSection(rx), object, lambda_nm).back_focus - y;
  }
  const double blur = std::abs(split) / lens.paraxial().fnumber;  // the blur disc's diameter
  if (blur > 0.03 && !quiet)
    spdlog::warn("lens {}: at this focus its horizontal and vertical sections focus {:.2f} mm apart, which blurs one of "
                 "them by about {:.3f} mm on the film{}", rx.name, std::abs(split), blur,
                 rx.focus_gap < 0 ? " (the lens has no anamorphic focusing of its own: see focus_gap in docs/lens-format.md)"
                                  : "");
  return fmt::format("; the sections' paraxial foci {:.3f} mm apart", std::abs(split));
}

}  // namespace

LensSetup SetUpLens(LensPrescription prescription, const StopRequest& stop, const FocusRequest& focus,
                    const std::optional<SurfacePlacement>& tilt) {
  LensSetup setup{LensSystem(std::move(prescription)), 0, {}, ""};
  LensSystem& lens = setup.lens;
  if (!(lens.paraxial().efl > 0))
    throw InputError(fmt::format("{}: EFL {:.4g} mm: the lens forms no real image of a distant point (a camera needs a "
                                 "positive one)", lens.prescription().name, lens.paraxial().efl));
  // The f-number is the lens's own: the stop is set on the lens centred on its axis (a
  // decentred or tilted element would vignette the axial cone and take it for a slower lens).
  LensSystem reference = lens.prescription().Centred() ? lens : LensSystem(CentredOnAxis(lens.prescription()));
  SetStop(reference, stop);
  setup.fnumber = RealFNumber(reference);
  CheckLightGetsThrough(reference, stop, setup.fnumber);
  lens.SetStopSemiDiameter(reference.StopSemiDiameter());
  lens.SetStopShape(stop.opening);
  if (!stop.opening.IsRound() && lens.StopIndex() >= 0 && lens.surface(lens.StopIndex()).mirror)
    spdlog::warn("lens {}: its stop is a mirror's rim (a mirror lens has no iris); the blades or mask shape it as an "
                 "iris there would", lens.prescription().name);
  if (tilt) {
    LensSystem tilted(MovedAsAWhole(lens.prescription(), *tilt, lens.paraxial().entrance_pupil_position));
    tilted.SetStopSemiDiameter(lens.StopSemiDiameter());
    tilted.SetStopShape(lens.stop_shape());
    lens = std::move(tilted);
  }
  const double distance = DistanceFromFilm(lens, focus);
  // A front anamorphic with focusing of its own: its gap set for this distance first (where
  // the y-z section puts the film), then the whole lens focused as usual.
  std::string anamorphic_focus = FocusAnamorphicGap(lens, distance, focus.lambda_nm);
  setup.focus = focus.real_rays ? FocusLens(lens, distance, focus.lambda_nm)
                                : ParaxialFocus(lens.prescription(), distance, focus.lambda_nm);
  lens.SetBackFocus(setup.focus.back_focus);
  const ParaxialData& p = lens.paraxial();
  const int blades = stop.opening.blades();
  setup.report = fmt::format("lens {}: EFL {:.2f} mm, f/{:.3g} (paraxial f/{:.3g}){}; {}", lens.prescription().name,
                             p.efl, setup.fnumber, p.fnumber, blades >= 3 ? fmt::format(", {} blades", blades) : "",
                             DescribeFocus(setup.focus, p.bfl));
  setup.report += anamorphic_focus + AnamorphicFocusNote(lens, setup.focus, focus.lambda_nm, focus.quiet);
  return setup;
}

LensSystem AtParaxialInfinityFocus(LensPrescription prescription, double lambda_nm) {
  FocusRequest focus;
  focus.real_rays = false;
  focus.lambda_nm = lambda_nm;
  focus.quiet = true;
  return SetUpLens(std::move(prescription), {}, focus).lens;
}

}  // namespace objektiv
