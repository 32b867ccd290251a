// Exact sequential ray tracing through a prescription, in double precision (for analysis).
// Lens space: millimetres, z along the optical axis toward the film, the first vertex at z = 0.
#pragma once
#include <optional>
#include <vector>

#include "base/vec.h"
#include "optics/lens_prescription.h"
#include "optics/stop_shape.h"

namespace objektiv {

struct LensRay {
  Vec3d o, d;  // d unit length
};

enum class TraceFailure { kNone, kMissedSurface, kClipped, kTotalInternalReflection };

struct TraceResult {
  std::optional<LensRay> ray;  // the ray after the last surface traced, if it got through
  TraceFailure failure = TraceFailure::kNone;
  int surface = -1;            // where it failed
  // Fraction of the light that gets through: the product of the Fresnel transmittances
  // (1 - R, unpolarised, uncoated) at every refracting surface and of the glasses' internal
  // transmittances along the path (Beer-Lambert, from the catalogs' IT data).
  double fresnel_transmittance = 1, internal_transmittance = 1;
};

// What happened at each refracting surface a ray crossed (for ghosts and diagnostics).
struct SurfaceEvent {
  int surface;
  double reflectance;  // unpolarised Fresnel reflectance there (uncoated)
  double cos_incidence;
};

// Unpolarised Fresnel reflectance for light going from index n1 into n2 at cos(theta_i)
// (1 beyond the critical angle).
double FresnelReflectance(double n1, double n2, double cos_i);

class LensTracer {
 public:
  explicit LensTracer(LensPrescription lens);

  // From the object side through every surface toward the film. `path`, if given, receives
  // the point where the ray meets each surface it reaches (for plots); `events` the Fresnel
  // reflectance at each refracting surface crossed.
  TraceResult TraceFromObject(const LensRay& ray, double lambda_nm, std::vector<Vec3d>* path = nullptr,
                              std::vector<SurfaceEvent>* events = nullptr) const;
  // From the film through every surface toward the object.
  TraceResult TraceFromFilm(const LensRay& ray, double lambda_nm, std::vector<Vec3d>* path = nullptr,
                            std::vector<SurfaceEvent>* events = nullptr) const;
  // Where a ray from the film meets the stop's plane, whether or not the stop lets it through;
  // nothing if it does not get that far (or the lens has no stop).
  std::optional<Vec3d> StopCrossingFromFilm(const LensRay& ray, double lambda_nm) const;

  // The stop's semi-diameter may be narrowed (never widened) to set an f-number.
  void SetStopSemiDiameter(double r);
  double StopSemiDiameter() const;
  // The opening's shape (round, an iris of blades, cut by a mask's support); see StopShape.
  void SetStopShape(const StopShape& shape) { stop_shape_ = shape; }
  const StopShape& stop_shape() const { return stop_shape_; }

  // Moves the film to `distance` mm behind the last vertex (the last thickness).
  void SetBackFocus(double distance) { film_z_ = vertex_z_.back() + distance; }
  const LensPrescription& lens() const { return lens_; }
  double VertexZ(int i) const { return vertex_z_[i]; }
  double FilmZ() const { return film_z_; }
  // Whether (x, y) in the stop plane lies inside the opening.
  bool InsideStop(double x, double y) const;
  // Sag z(r) of surface i relative to its vertex, and dz/dr.
  double Sag(int i, double r) const;
  double SagSlope(int i, double r) const;

 private:
  // Intersect with surface i (ray in lens space); returns the parameter t or nothing.
  std::optional<double> Intersect(int i, const LensRay& ray) const;
  Vec3d Normal(int i, const Vec3d& p) const;  // unit, pointing toward +z
  TraceResult Trace(const LensRay& ray, double lambda_nm, bool from_film, std::vector<Vec3d>* path,
                    std::vector<SurfaceEvent>* events) const;

  LensPrescription lens_;
  std::vector<double> vertex_z_;
  double film_z_ = 0;
  double stop_semi_ = 0;
  StopShape stop_shape_;
};

}  // namespace objektiv
