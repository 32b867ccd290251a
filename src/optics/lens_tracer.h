// Exact sequential ray tracing through a lens as set up, in double precision (for analysis and
// the reference of the renderer's batch tracer). Lens space: millimetres, z along the optical
// axis toward the film, the first vertex at z = 0.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "base/vec.h"
#include "optics/lens_system.h"
#include "optics/uniaxial_crystal.h"

namespace objektiv {

struct LensRay {
  Vec3d o, d;  // d unit length: where the light goes (in a crystal the ray's, not its wave normal)
  // Birefringent crystals (optics/uniaxial_crystal.h): whether the ray is the extraordinary wave
  // of the crystal it is in, and which wave it takes in each crystal still ahead, one bit a
  // crystal entered (refracted into or reflected inside), lowest first, 1 extraordinary.
  bool extraordinary = false;
  uint32_t wave_choices = 0;
};

enum class TraceFailure { kNone, kMissedSurface, kClipped, kTotalInternalReflection };

struct TraceResult {
  std::optional<LensRay> ray;  // the ray after the last surface traced, if it got through
  TraceFailure failure = TraceFailure::kNone;
  int surface = -1;            // where it failed (-1: at the lens hood's mouth)
  // Fraction of the light that gets through: the product of the surfaces' transmittances
  // (1 - R, unpolarised: Fresnel's where bare, the coating's where coated) at every refracting
  // surface, of the glasses' internal transmittances along the path (Beer-Lambert, from the
  // catalogs' IT data) and of what dust and scratches let through where the ray met them (0 or
  // 1; optics/surface_dirt.h), kept apart for those who average it (the ghosts' grids).
  double surface_transmittance = 1, internal_transmittance = 1, dirt = 1;
  double Transmittance() const { return surface_transmittance * internal_transmittance * dirt; }
};

// What happened at each refracting surface a ray crossed (for ghosts and diagnostics).
struct SurfaceEvent {
  int surface;
  double reflectance;  // unpolarised reflectance there (LensSystem::SurfaceReflectance)
  double cos_incidence;
};

// Unpolarised Fresnel reflectance for light going from index n1 into n2 at cos(theta_i)
// (1 beyond the critical angle).
double FresnelReflectance(double n1, double n2, double cos_i);

// From the object side through every surface toward the film. `path`, if given, receives
// the point where the ray meets each surface it reaches; `events` the reflectance at each
// refracting surface crossed; `curve` the whole path to draw: the same points and, through a
// gradient-index medium, the point after every step of the integration between them.
TraceResult TraceFromObject(const LensSystem& lens, const LensRay& ray, double lambda_nm,
                            std::vector<Vec3d>* path = nullptr, std::vector<SurfaceEvent>* events = nullptr,
                            std::vector<Vec3d>* curve = nullptr);
// From the film through every surface toward the object.
TraceResult TraceFromFilm(const LensSystem& lens, const LensRay& ray, double lambda_nm,
                          std::vector<Vec3d>* path = nullptr, std::vector<SurfaceEvent>* events = nullptr);
// One step of a path through the lens: the ray, travelling toward the film or toward the
// object, meets `surface` and is refracted through it or reflected back from it (a ghost's
// path reflects twice). The transmittance gathers 1 - R at each refraction and R at each
// reflection (LensSystem::SurfaceReflectance).
struct SurfaceVisit {
  int surface;
  bool reflect;
  bool toward_film;
};
// The ray through `visits` in order; consecutive visits must be neighbouring surfaces (the
// segment between them lies in one medium). A reflection where the media on both sides are
// the same fails (kMissedSurface: there is no interface).
TraceResult TraceSequence(const LensSystem& lens, const LensRay& ray, double lambda_nm,
                          std::span<const SurfaceVisit> visits, std::vector<Vec3d>* path = nullptr,
                          std::vector<SurfaceEvent>* events = nullptr);
// The unit normal of surface s at p (relative to its vertex or not: it depends on x, y only),
// pointing toward +z (the film).
Vec3d SurfaceNormal(const LensSurface& s, const Vec3d& p);
// The unit normal of surface s at p in its own frame (as SurfaceNormal), from the implicit form
// of its conic where it is one (no square root of the sag's slope): the tracers' way.
Vec3d InterfaceNormal(const LensSurface& s, const Vec3d& p);
// Direction d (unit) reflected, or refracted with index ratio eta (incoming over outgoing;
// nothing beyond the critical angle), at a surface of unit normal n facing it, cos_i = -n.d.
Vec3d ReflectedDirection(const Vec3d& d, const Vec3d& n, double cos_i);
std::optional<Vec3d> RefractedDirection(const Vec3d& d, const Vec3d& n, double eta, double cos_i);
// Where the ray o + t d (o relative to the vertex, in the surface's frame) first meets surface
// s, t >= about 0: nothing if it misses; `blocked` set where it meets a Fresnel surface's riser.
// Every kind of surface, its form error included (the batch tracer's way for the surfaces its
// kernels do not trace).
std::optional<double> IntersectSurface(const LensSurface& s, const Vec3d& o, const Vec3d& d, bool& blocked);

// The two pieces of IntersectSurface and InterfaceNormal for a plain conic of curvature c
// (1/mm, not 0) and conic constant k (k1 = 1 + k), inline for the compiled ghost paths
// (optics/compiled_sequence.h), which call them with c and k1 looked up once.
// The conic through the vertex, c (x^2 + y^2) + k1 c z^2 - 2 z = 0: its two sheets are told
// apart by k1 c z <= 1 (the vertex's) or >= 1; the surface is the vertex's sheet, and the ray
// meets it first at the smaller root t > -1e-9.
inline std::optional<double> IntersectConic(double c, double k1, const Vec3d& o, const Vec3d& d) {
  const double A = c * (d.x * d.x + d.y * d.y) + k1 * c * d.z * d.z;
  const double B = 2 * (c * (o.x * d.x + o.y * d.y) + k1 * c * o.z * d.z - d.z);
  const double C = c * (o.x * o.x + o.y * o.y) + k1 * c * o.z * o.z - 2 * o.z;
  const double disc = B * B - 4 * A * C;
  if (disc < 0) return std::nullopt;
  const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
  const double roots[2] = {q != 0 ? C / q : std::numeric_limits<double>::infinity(),
                           A != 0 ? q / A : std::numeric_limits<double>::infinity()};
  double best = std::numeric_limits<double>::infinity();
  for (double tr : roots) {
    if (!std::isfinite(tr) || tr <= -1e-9) continue;
    if (k1 * c * (o.z + tr * d.z) > 1) continue;  // the other sheet
    best = std::min(best, tr);
  }
  if (!std::isfinite(best)) return std::nullopt;
  return best;
}
// The unit normal of that conic at p (toward +z at the vertex): the gradient of its implicit form.
inline Vec3d ConicNormal(double c, double k1, const Vec3d& p) {
  const Vec3d g(-c * p.x, -c * p.y, 1 - k1 * c * p.z);
  return g / Length(g);
}

// One step of any path: where `ray` meets surface i travelling toward the film (or the
// object; along a curve through a gradient-index medium, optics/gradient_propagation.h), whether it gets through the opening there, and what the interface does; the
// caller chooses to reflect or refract (Reflected, Refracted). The exact tracer's own step.
struct SurfaceCrossing {
  TraceFailure failure = TraceFailure::kNone;  // kMissedSurface, or kClipped (p is set)
  Vec3d p;                 // the point on the surface
  Vec3d d;                 // the direction the ray arrives in (its own, but through a gradient-index medium)
  double t = 0;            // the distance travelled to it (the curved path's length through a gradient)
  bool interface = false;  // whether the index changes there (else the ray goes straight on)
  // A mirror: the ray is reflected (Reflected), with `reflectance` the mirror's, and goes on
  // to the next surface in order (not an interface: no refraction, no ghost reflection).
  bool mirror = false;
  Vec3d normal;            // unit, facing the incoming ray (where an interface or a mirror)
  double cos_i = 1, eta = 1;  // eta: incoming index over outgoing
  double reflectance = 0;     // unpolarised (LensSystem::SurfaceReflectance), the mirror's, 0 where neither
  double clean = 1;           // what the surface's dust and scratches let through at p (optics/surface_dirt.h)
  // The ray's crystal state (LensRay), which Reflected and Refracted carry on. Where a crystal
  // lies on either side (`anisotropic`): the arriving wave vector and the media as the waves
  // see them (the outgoing one for the reflected and the refracted wave), from which they
  // solve for the wave that leaves; `eta` and `cos_i` are then the refracted wave's index
  // ratio and its wave normal's incidence.
  bool extraordinary = false;
  uint32_t wave_choices = 0;
  bool anisotropic = false;
  Vec3d k_in;
  WaveMedium reflected_medium, refracted_medium;
};
// Local error allowed per step of the integration through a gradient-index medium, mm (and in
// n dr/ds, index units): the exact tracer's, and the renderer's (its single-precision tracer
// agrees with the exact one to 1e-4 mm at the film).
inline constexpr double kGradientTolerance = 1e-10, kGradientRenderTolerance = 1e-6;
// `curve`, if given, receives the points along the way through a gradient-index medium (the
// crossing's point last), or the crossing's point alone. Without `with_reflectance` an
// interface's reflectance is left 0 (a coating's thin-film stack is most of a step's cost, and
// tracing for geometry alone, or with tabulated coatings, does not need it); a mirror's and total
// reflection's are set all the same.
SurfaceCrossing CrossSurface(const LensSystem& lens, int i, const LensRay& ray, double lambda_nm, bool toward_film,
                             double gradient_tolerance = kGradientTolerance, std::vector<Vec3d>* curve = nullptr,
                             bool with_reflectance = true);
// The ray leaving an interface crossing in direction d (SurfaceCrossing::d) reflected, or
// refracted (nothing beyond the critical angle), with the ray's crystal state: entering a
// crystal (refracted into it, reflected inside it) takes the next of its wave choices.
LensRay Reflected(const SurfaceCrossing& c, const Vec3d& d);
std::optional<LensRay> Refracted(const SurfaceCrossing& c, const Vec3d& d);
// The ray going on through a crossing that is no interface (the same medium on both sides).
inline LensRay Onward(const SurfaceCrossing& c) { return {c.p, c.d, c.extraordinary, c.wave_choices}; }
// The glass's internal transmittance over `length` mm between neighbouring surfaces `from`
// and `to` (1 in air).
double SegmentTransmittance(const LensSystem& lens, int from, int to, double lambda_nm, double length);

// Where a ray from the film meets the stop's plane, whether or not the stop lets it through, in
// the stop's own frame (LensSystem::InSurfaceFrame: relative to its vertex, the same as lens
// space where it is centred); nothing if it does not get that far (or the lens has no stop).
std::optional<Vec3d> StopCrossingFromFilm(const LensSystem& lens, const LensRay& ray, double lambda_nm);

}  // namespace objektiv
