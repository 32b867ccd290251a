// A lens prescription: surfaces from the object side to the film, lengths in millimetres.
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "optics/coating.h"
#include "optics/forbes_asphere.h"
#include "optics/form_error.h"
#include "optics/fresnel_zones.h"
#include "optics/glass.h"
#include "optics/gradient_index.h"
#include "optics/mirror_metal.h"
#include "optics/surface_dirt.h"
#include "optics/surface_placement.h"
#include "optics/uniaxial_crystal.h"

namespace objektiv {

struct LensSurface {
  double radius = 0;          // mm; positive: centre of curvature on the film side; 0 with flat = true
  bool flat = false;          // a plane surface (radius infinite)
  double thickness = 0;       // mm to the next surface (the last: to the film)
  double semi_diameter = 0;   // clear semi-diameter, mm
  // The aperture stop: a plane iris (and a flat interface if the media differ), or a mirror's
  // own rim (a mirror lens has no iris: its stop is the primary mirror).
  bool is_stop = false;
  // A mirror: light is reflected here and goes back into the medium it came from (`medium` is
  // that one): by a metal layer, seen from that medium (optics/mirror_metal.h), or where
  // `mirror_metal` is null, with `mirror_reflectance` (0..1] at every wavelength and angle. Thicknesses follow the direction of
  // travel, as lens designers write them: after an odd number of mirrors light travels toward
  // the object and the thicknesses are negative (z steps, vertex to vertex).
  bool mirror = false;
  double mirror_reflectance = 1;
  std::shared_ptr<const MirrorMetal> mirror_metal;
  // A central obstruction: the surface blocks light that meets it within this radius (mm) of
  // the axis (a mirror lens's secondary mirror and its holder); 0: none.
  double obscuration = 0;
  double conic = 0;           // k: 0 sphere, -1 paraboloid
  std::array<double, 7> aspheric{};  // even aspheric coefficients a4, a6, ..., a16
  double a2 = 0;              // r^2 aspheric term (Zemax EVENASPH PARM 1); adds 2 a2 to the paraxial curvature
  // A Q-type asphere (optics/forbes_asphere.h): Forbes's polynomials added to the conic (Qcon)
  // or to the sphere of this radius, conic 0 (Qbfs); null: none. Not with a4..a16 or a toroid.
  std::shared_ptr<const ForbesAsphere> forbes;
  // A Fresnel surface (optics/fresnel_zones.h): the profile above cut into zones of one pitch,
  // each facet lowered to the vertex plane, risers between them; null: the profile itself.
  std::shared_ptr<const FresnelZones> fresnel;
  // The figure's departure from all the above (optics/form_error.h): a smooth random shape of
  // a given peak-to-valley; null: a perfect surface.
  std::shared_ptr<const FormError> form_error;
  // A toroidal surface (a cylinder where one section is flat): the y-z profile that the radius,
  // conic and aspheric terms give, turned about an axis parallel to y that crosses the axis
  // 1 / curvature_x behind the vertex (Zemax TOROIDAL, its radius of rotation). Its x-z
  // section is a circle of curvature curvature_x; 0: flat in x (a cylinder curved in y only).
  bool toroidal = false;
  double curvature_x = 0;
  // Dust and scratches (optics/surface_dirt.h): what absorbs the light meeting the surface; null: clean.
  std::shared_ptr<const SurfaceDirt> dirt;
  // Decentred or tilted (optics/surface_placement.h); none: centred on the axis.
  std::optional<SurfacePlacement> placement;
  // Anti-reflection coating (optics/coating.h); null: bare. It lies on the surface's glass: on
  // the side of the glass where the other side is air, on the film side between two glasses.
  std::shared_ptr<const Coating> coating;
  // Medium after this surface (towards the film); null means air.
  std::shared_ptr<const Glass> medium;
  // A gradient-index medium after this surface (optics/gradient_index.h), laid out in this
  // surface's frame; `medium` is its glass (its index on the axis at the vertex, its dispersion
  // and absorption); null: homogeneous.
  std::shared_ptr<const GradientIndex> gradient;
  // A birefringent crystal after this surface (optics/uniaxial_crystal.h): `medium` gives its
  // ordinary index, the crystal its extraordinary one and its optic axis (in this surface's
  // frame); null: isotropic.
  std::shared_ptr<const UniaxialCrystal> crystal;

  double Curvature() const { return (flat || radius == 0) ? 0.0 : 1.0 / radius; }
  // Sets the radius from a curvature c (1/mm): a plane where c is 0 or so small (a subnormal
  // number) that 1/c overflows.
  void SetCurvature(double c);
  // Curvature at the vertex, including the r^2 aspheric term (a Qbfs surface's too): what
  // paraxial optics sees.
  double ParaxialCurvature() const { return Curvature() + 2 * (a2 + (forbes ? forbes->VertexR2Term() : 0.0)); }
  bool HasAsphericTerms() const {
    if (a2 != 0 || forbes) return true;
    for (double a : aspheric)
      if (a != 0) return true;
    return false;
  }
  double IndexAfter(double lambda_nm) const { return medium ? medium->Index(lambda_nm) : 1.0; }
  // Sag z(r) relative to the vertex (conic plus even aspheric or Q-type terms), and dz/dr: the surface's
  // own where it is rotationally symmetric, a toroid's y-z profile.
  double Sag(double r) const;
  double SagSlope(double r) const;
  void SagWithSlope(double r, double& z, double& slope) const;  // both in one pass
  // Sag z(x, y) of any surface and, where asked, its gradient (dz/dx, dz/dy); false outside
  // the surface (beyond where a conic turns over, or a toroid's profile reaches its axis). A
  // Fresnel surface's is its facet's (the profile's slope, lowered to the vertex plane); a
  // form error is added.
  bool SagAt(double x, double y, double& z, double* gx = nullptr, double* gy = nullptr) const;
  // The same without the form error: the surface as prescribed.
  bool NominalSagAt(double x, double y, double& z, double* gx = nullptr, double* gy = nullptr) const;
  // Paraxial curvature of the x-z section (a toroid's curvature_x, else ParaxialCurvature()).
  double ParaxialCurvatureX() const { return toroidal ? curvature_x : ParaxialCurvature(); }
  // The vertex curvature of the surface's section by the lens's y-z plane, what paraxial
  // optics traces: ParaxialCurvature(), or for a toroid turned about its axis by its placement,
  // Euler's c_x u_x^2 + c_y u_y^2, u the lens's y in the surface's frame (a tilt is ignored:
  // paraxial data are those of the lens centred).
  double ParaxialCurvatureInY() const;
};

struct LensPrescription {
  std::string name, source;
  std::string file;  // the file it was read from (empty: made in code), for messages
  double design_focal_length = 0, design_fnumber = 0, image_circle = 0;  // metadata (0: not given)
  std::vector<LensSurface> surfaces;
  // The medium in front of the first surface, where the scene is: null is air; water for an
  // underwater housing's port, oil for an immersion objective. The film side is always air.
  std::shared_ptr<const Glass> object_medium;
  // An anamorphic's own focusing (a front adapter's focus ring): the gap after this surface
  // (0-based) changes so that the x-z section focuses where the y-z section does
  // (optics/anamorphic.h: AnamorphicFocusGap); -1: none (only the whole lens moves).
  int focus_gap = -1;
  // The coatings the lens file defines (used by its surfaces or not: a scene may choose one).
  std::vector<std::shared_ptr<const Coating>> defined_coatings;

  int StopIndex() const;  // -1 if none
  // Its name, and the file it came from where that says more: "NAME (PATH)".
  std::string Described() const { return file.empty() || file == name ? name : name + " (" + file + ")"; }
  // The medium light crosses before surface i (from the object side): the object medium
  // before the first.
  const std::shared_ptr<const Glass>& MediumBefore(size_t i) const {
    return i > 0 ? surfaces[i - 1].medium : object_medium;
  }
  double IndexBefore(size_t i, double lambda_nm) const {
    const std::shared_ptr<const Glass>& m = MediumBefore(i);
    return m ? m->Index(lambda_nm) : 1.0;
  }
  // First vertex to the last along z (without the distance to the film): the sum of the
  // thicknesses, negative ones (after a mirror) included.
  double TotalTrack() const;
  // Each surface's vertex z along the axis from the first (the sums of the thicknesses before it).
  std::vector<double> VertexZs() const;
  int MirrorCount() const;
  // Whether every surface is a figure of revolution about the axis (no toroid, none decentred
  // or tilted, no form error, every crystal's optic axis along it): the radial pupil bounds, the
  // thin- and thick-lens models and the radial analyses rely on it.
  bool RotationallySymmetric() const { return Centred() && !HasToroids() && !HasFormErrors() && !HasTurnedCrystals(); }
  bool HasToroids() const;
  bool HasFormErrors() const;
  bool HasGradients() const;  // a gradient-index medium anywhere
  int CrystalCount() const;   // birefringent media
  bool HasTurnedCrystals() const;  // a crystal whose optic axis is not the lens's axis
  // Whether the lens is its own mirror image under x -> -x (axis 0) or y -> -y (axis 1): every
  // surface's placement (its decentre has no such component, its frame turns only about that
  // axis or in the plane it is normal to), every crystal's optic axis as a line in lens space,
  // and no form error. The pupil grid tabulates half the film (or a quadrant) where it holds.
  bool MirrorSymmetric(int axis) const;
  bool Centred() const;  // no surface decentred or tilted
  // +1 where light leaves surface i toward the film (+z), -1 toward the object (after an odd
  // number of mirrors up to and including i).
  int DirectionAfter(size_t i) const;
  // The same lens `factor` times larger: radii, thicknesses, apertures, the metadata lengths
  // and the aspheric terms (a sag a r^2k scales to factor a r^2k at factor r, so a' = a /
  // factor^(2k - 1)).
  LensPrescription Scaled(double factor) const;
};

// Throws InputError "PATH:LINE: ..." if the surface's semi-diameter lies beyond the largest a
// conic surface reaches before its sag turns over: r^2 (1+k) c^2 < 1 (for every reader).
// Every surface between air and glass gets `coating` (null: bare); with `only_bare`, only
// those without one yet (a lens-wide default). Cemented surfaces keep theirs.
void CoatAirGlassSurfaces(LensPrescription& lens, const std::shared_ptr<const Coating>& coating, bool only_bare);

void CheckReachable(const LensSurface& s, const std::string& path, int line);
// The lens turned by `angle` (radians, right-handed) about its axis, as a whole: its toroids,
// decentred or tilted surfaces and its stop (with the opening the stop's frame carries) get the
// turned placement; surfaces of revolution on the axis are the same turned.
LensPrescription TurnedAboutAxis(const LensPrescription& lens, double angle);
// The same lens with every surface back on the axis, untilted (what its f-number, paraxial
// data and field of view are reported for).
LensPrescription CentredOnAxis(const LensPrescription& lens);
// Why a toroid cannot lie as it is placed: turned about the axis so that its sections no longer
// lie along the film's x and y (paraxial optics would need the coupled, skew treatment of
// crossed cylinders, not modelled); empty where it can.
std::string ToroidTurnMismatch(const LensSurface& s);
// The lens moved as a whole by the rigid motion `motion` (its turn, then its offset) about the
// point (0, 0, pivot_z) of lens space: every surface placed where that puts it (a tilt-shift
// lens's tilt); the film stays.
LensPrescription MovedAsAWhole(const LensPrescription& lens, const SurfacePlacement& motion, double pivot_z);
// The first surface whose thickness goes against the direction light travels after it (a
// positive thickness after an odd number of mirrors, a negative one otherwise), or an odd
// number of mirrors in all (the image would lie on the object's side, where the film cannot
// be); the index of the surface to blame (the last one for the count) and why. Nothing where
// the lens folds consistently (for the readers, which name the line).
std::optional<std::pair<size_t, std::string>> FirstDirectionMismatch(const LensPrescription& lens);
// The first surface that crosses an earlier one within both their clear apertures (it lies
// before it somewhere, along the direction light travels: a thickness too small for the sags,
// a decentre or tilt too large), checking each surface against the next six up to the next
// mirror (a small stop between two menisci does not hide them); decentred and tilted surfaces
// where they are placed. The index of the later surface and why; nothing where none crosses
// (for the readers, which name the line).
std::optional<std::pair<size_t, std::string>> FirstCrossedGap(const LensPrescription& lens);
// The first surface whose coating cannot lie there (optics/coating.h: CoatingMismatch), and
// why; nothing where every coating fits (for the readers, which name its line, and Recoat).
std::optional<std::pair<size_t, std::string>> FirstCoatingMismatch(const LensPrescription& lens);
// Throws InputError "PATH:LINE: ..." if the surface's thickness or semi-diameter is beyond
// kMaxLensLength (in mm, after unit conversion): a thickness of 1e300 gave an EFL of 0 and a
// lens that renders nothing, in silence (for every reader).
inline constexpr double kMaxLensLength = 1e5;  // 100 m
void CheckSize(const LensSurface& s, const std::string& path, int line);

}  // namespace objektiv
